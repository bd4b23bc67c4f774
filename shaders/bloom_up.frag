#version 330 core
// One step up the bloom chain (Jimenez, SIGGRAPH 2014): a 3×3 tent filter (1 2 1 / 2 4 2 /
// 1 2 1, over 16) of the smaller level, added by the blend onto the next larger one.
in vec2 v_uv;
uniform sampler2D u_source;
uniform vec2 u_texel;  // 1 / source size
out vec4 o_color;

vec3 tap(float x, float y) { return textureLod(u_source, v_uv + vec2(x, y) * u_texel, 0.0).rgb; }

void main() {
  vec3 s = tap(0.0, 0.0) * 4.0;
  s += (tap(-1.0, 0.0) + tap(1.0, 0.0) + tap(0.0, -1.0) + tap(0.0, 1.0)) * 2.0;
  s += tap(-1.0, -1.0) + tap(1.0, -1.0) + tap(-1.0, 1.0) + tap(1.0, 1.0);
  o_color = vec4(s * (1.0 / 16.0), 1.0);
}
