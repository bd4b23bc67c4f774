#version 330 core
// Quads and lines sample the atlas's white pixel, text samples glyphs: one program, one draw.
in vec2 v_uv;
in vec4 v_color;
uniform sampler2D u_font;
out vec4 o_color;
void main() {
  vec4 c = v_color * texture(u_font, v_uv);
  o_color = vec4(c.rgb * c.a, c.a);
}
