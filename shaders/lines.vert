#version 330 core
// Overlay geometry (axes, ticks, curves, colour bar, panels) as triangles in frame pixels,
// origin at the top-left corner, y down.

layout(location = 0) in vec2 a_pos;    // [px]
layout(location = 1) in vec4 a_color;  // straight (not premultiplied) alpha
layout(location = 2) in vec2 a_edge;   // (signed distance from the line's centre, half width) [px]

uniform vec2 u_viewport;  // frame size [px]

out vec4 v_color;
out vec2 v_edge;

void main() {
  v_color = a_color;
  v_edge = a_edge;
  gl_Position = vec4(2.0 * a_pos.x / u_viewport.x - 1.0, 1.0 - 2.0 * a_pos.y / u_viewport.y, 0.0, 1.0);
}
