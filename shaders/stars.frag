#version 330 core
in vec3 v_color;
out vec4 o_color;
void main() {
  vec2 q = gl_PointCoord * 2.0 - 1.0;
  float f = max(1.0 - dot(q, q), 0.0);
  o_color = vec4(v_color * f * f, 0.0);
}
