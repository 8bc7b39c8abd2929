#version 330 core
// Flat discs (1D/2D, antialiased rim) or, with SPH_SHADED defined, lit spheres that write their
// true depth so that overlapping particles intersect correctly (3D).
// cpu_splat.cpp reproduces this stage on the CPU for software GL: keep the two in step.

in vec2 v_offset;
flat in vec3 v_color;
flat in float v_radius;
flat in vec3 v_eye;
flat in float v_eye_radius;

uniform mat4 u_proj;  // eye -> clip (sphere depth)

out vec4 frag_color;

void main() {
#ifdef SPH_SHADED
  vec2 p = v_offset / v_radius;
  float q = dot(p, p);
  if (q > 1.0) discard;
  vec3 n = vec3(p, sqrt(1.0 - q));
  const vec3 light = vec3(-0.3841, 0.5762, 0.7215);  // unit vector, eye space: upper left, towards the viewer
  float diffuse = max(dot(n, light), 0.0);
  float specular = pow(max(2.0 * diffuse * n.z - light.z, 0.0), 24.0);  // (reflect(-light, n)).z
  frag_color = vec4(min(v_color * (0.35 + 0.75 * diffuse) + vec3(0.25 * specular), vec3(1.0)), 1.0);
  vec4 surface = u_proj * vec4(v_eye + n * v_eye_radius, 1.0);
  gl_FragDepth = 0.5 * surface.z / surface.w + 0.5;
#else
  // Coverage falls from 1 to 0 across the last pixel of the radius; zero-alpha fragments leave the
  // framebuffer unchanged under blending, so there is no discard.
  frag_color = vec4(v_color, clamp(v_radius + 0.5 - length(v_offset), 0.0, 1.0));
#endif
}
