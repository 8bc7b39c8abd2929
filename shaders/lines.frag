#version 330 core
// Thick lines fade out over the last pixel of their half width (antialiasing); fills pass a huge
// half width and stay opaque.

in vec4 v_color;
in vec2 v_edge;

out vec4 frag_color;

void main() {
  float coverage = clamp(v_edge.y + 0.5 - abs(v_edge.x), 0.0, 1.0);
  frag_color = vec4(v_color.rgb, v_color.a * coverage);
}
