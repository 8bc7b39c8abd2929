#version 330 core
// Particles as instanced screen-aligned quads: one instance per particle, the 4 corners of a
// triangle strip come from gl_VertexID. Quads are sized in pixels so that discs stay round
// (aspect-correct) and never shrink below u_min_radius pixels. The colour is looked up here, once
// per particle, so the fragment stage only computes coverage (and shading in 3D).
// cpu_splat.cpp reproduces this stage and particles.frag on the CPU for software GL: keep in step.

layout(location = 0) in vec3 a_center;  // particle position [world units]
layout(location = 1) in float a_radius; // disc/sphere radius [world units]
layout(location = 2) in float a_value;  // scalar field shown by colour [field units]
layout(location = 3) in float a_wall;   // 1: wall particle, drawn in u_wall_color whatever its value; 0: fluid

uniform mat4 u_view;           // world -> eye
uniform mat4 u_proj;           // eye -> clip (orthographic in 1D/2D, perspective in 3D)
uniform vec2 u_viewport;       // viewport size [px]
uniform float u_pixel_radius;  // > 0: every particle gets this radius [px]; else a_radius is used
uniform float u_min_radius;    // smallest radius drawn [px]
uniform vec2 u_range;          // field values mapped to the two ends of the colour map (min < max)
uniform sampler1D u_cmap;      // 256-entry colour map, linear filtering
uniform vec4 u_invalid_color;  // colour of NaN/inf values
uniform vec4 u_wall_color;     // colour of wall particles (palette::kWall)

out vec2 v_offset;            // this corner's offset from the centre [px], y up
flat out vec3 v_color;        // colour-mapped value
flat out float v_radius;      // disc radius [px]
flat out vec3 v_eye;          // centre in eye space (sphere depth)
flat out float v_eye_radius;  // radius in eye units

void main() {
  vec4 eye = u_view * vec4(a_center, 1.0);
  vec4 clip = u_proj * eye;
  // Pixels per eye-space unit at this depth (clip.w is 1 for orthographic projections).
  float px_per_unit = 0.5 * u_viewport.y * u_proj[1][1] / clip.w;
  float r = u_pixel_radius > 0.0 ? u_pixel_radius : a_radius * px_per_unit;
  r = max(r, u_min_radius);
  v_radius = r;
  float half_size = r + 1.0;  // one spare pixel for the antialiased rim
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)) * 2.0 - 1.0;
  v_offset = corner * half_size;
  v_eye = eye.xyz;
  v_eye_radius = r / px_per_unit;

  bool finite = !(isnan(a_value) || isinf(a_value));
  float t = clamp((a_value - u_range.x) / (u_range.y - u_range.x), 0.0, 1.0);
  // Texel centres of the 256 entries sit at (i + 0.5)/256.
  v_color = finite ? textureLod(u_cmap, (t * 255.0 + 0.5) / 256.0, 0.0).rgb : u_invalid_color.rgb;
  if (a_wall > 0.5) v_color = u_wall_color.rgb;
  clip.xy += v_offset * 2.0 / u_viewport * clip.w;
  gl_Position = clip;
}
