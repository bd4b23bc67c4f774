#version 330 core
// One step down the bloom chain: Jimenez's 13-tap downsample ("Next Generation Post Processing
// in Call of Duty: Advanced Warfare", SIGGRAPH 2014). Thirteen bilinear taps make five
// overlapping 2×2-texel boxes: the inner box weighs 0.5, the four corner boxes 0.125 each.
// With PREFILTER (the first step, from the full-resolution scene) each box is also weighted by
// 1 / (1 + luma) (Karis' average, from the same talk) so a single bright pixel cannot flicker as
// a big blob, and a soft-knee threshold keeps only light above u_threshold, with a quadratic
// knee of half-width u_knee instead of a hard cut.
in vec2 v_uv;
uniform sampler2D u_source;
uniform vec2 u_texel;       // 1 / source size
uniform float u_threshold;  // linear scene value where bloom starts
uniform float u_knee;
out vec4 o_color;

vec3 tap(vec2 offset) { return texture(u_source, v_uv + offset * u_texel).rgb; }

#if PREFILTER
float karis_weight(vec3 c) { return 1.0 / (1.0 + dot(c, vec3(0.2126, 0.7152, 0.0722))); }

vec3 soft_threshold(vec3 c) {
  float brightness = max(c.r, max(c.g, c.b));
  float rq = clamp(brightness - u_threshold + u_knee, 0.0, 2.0 * u_knee);
  rq = rq * rq / (4.0 * u_knee + 1e-5);
  return c * (max(rq, brightness - u_threshold) / max(brightness, 1e-5));
}
#endif

void main() {
  vec3 a = tap(vec2(-2.0, 2.0)), b = tap(vec2(0.0, 2.0)), c = tap(vec2(2.0, 2.0));
  vec3 d = tap(vec2(-1.0, 1.0)), e = tap(vec2(1.0, 1.0));
  vec3 f = tap(vec2(-2.0, 0.0)), g = tap(vec2(0.0, 0.0)), h = tap(vec2(2.0, 0.0));
  vec3 i = tap(vec2(-1.0, -1.0)), j = tap(vec2(1.0, -1.0));
  vec3 k = tap(vec2(-2.0, -2.0)), l = tap(vec2(0.0, -2.0)), m = tap(vec2(2.0, -2.0));
  vec3 inner = (d + e + i + j) * 0.25;
  vec3 tl = (a + b + f + g) * 0.25, tr = (b + c + g + h) * 0.25;
  vec3 bl = (f + g + k + l) * 0.25, br = (g + h + l + m) * 0.25;
#if PREFILTER
  float wi = 0.5 * karis_weight(inner), w1 = 0.125 * karis_weight(tl), w2 = 0.125 * karis_weight(tr);
  float w3 = 0.125 * karis_weight(bl), w4 = 0.125 * karis_weight(br);
  vec3 sum = (inner * wi + tl * w1 + tr * w2 + bl * w3 + br * w4) / (wi + w1 + w2 + w3 + w4);
  o_color = vec4(soft_threshold(sum), 1.0);
#else
  o_color = vec4(inner * 0.5 + (tl + tr + bl + br) * 0.125, 1.0);
#endif
}
