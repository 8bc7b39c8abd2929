#version 330 core
// An image the size of the viewport, premultiplied alpha, rows bottom-up (the CPU particle splat).

in vec2 v_uv;

uniform sampler2D u_image;

out vec4 frag_color;

void main() {
  frag_color = texelFetch(u_image, ivec2(v_uv * vec2(textureSize(u_image, 0))), 0);
}
