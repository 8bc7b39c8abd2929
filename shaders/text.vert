#version 330 core
// Glyph quads in frame pixels (origin top-left, y down) with atlas texture coordinates.

layout(location = 0) in vec2 a_pos;    // [px]
layout(location = 1) in vec2 a_uv;     // font atlas coordinates
layout(location = 2) in vec4 a_color;

uniform vec2 u_viewport;  // frame size [px]

out vec2 v_uv;
out vec4 v_color;

void main() {
  v_uv = a_uv;
  v_color = a_color;
  gl_Position = vec4(2.0 * a_pos.x / u_viewport.x - 1.0, 1.0 - 2.0 * a_pos.y / u_viewport.y, 0.0, 1.0);
}
