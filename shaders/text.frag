#version 330 core
// The atlas stores glyph coverage in its red channel (single-channel texture).

in vec2 v_uv;
in vec4 v_color;

uniform sampler2D u_font;

out vec4 frag_color;

void main() {
  frag_color = vec4(v_color.rgb, v_color.a * texture(u_font, v_uv).r);
}
