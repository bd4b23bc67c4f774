#version 330 core
// The bloom chain's steps down (bloom_pass.h). With PREFILTER (scene → half size): one bilinear
// tap, the exact mean of the 2×2 scene pixels under this one, through a soft-knee threshold
// that keeps only light above u_threshold, with a quadratic knee of half-width u_knee instead
// of a hard cut. Otherwise Jimenez's 13-tap downsample ("Next Generation Post Processing in
// Call of Duty: Advanced Warfare", SIGGRAPH 2014): thirteen bilinear taps make five overlapping
// 2×2-texel boxes, the inner box weighing 0.5 and the four corner boxes 0.125 each. With KARIS
// (the first 13-tap step) each box is also weighted by 1 / (1 + luma) (Karis' average, from the
// same talk), so a single bright pixel cannot flicker as a big blob.
in vec2 v_uv;
uniform sampler2D u_source;
uniform vec2 u_texel;       // 1 / source size
uniform float u_threshold;  // linear scene value where bloom starts
uniform float u_knee;
out vec4 o_color;

vec3 tap(vec2 offset) { return textureLod(u_source, v_uv + offset * u_texel, 0.0).rgb; }

#if PREFILTER
void main() {
  vec3 c = tap(vec2(0.0));
  float brightness = max(c.r, max(c.g, c.b));
  float rq = clamp(brightness - u_threshold + u_knee, 0.0, 2.0 * u_knee);
  rq = rq * rq / (4.0 * u_knee + 1e-5);
  o_color = vec4(c * (max(rq, brightness - u_threshold) / max(brightness, 1e-5)), 1.0);
}
#else
float box_weight(vec3 c) {
#if KARIS
  return 1.0 / (1.0 + dot(c, vec3(0.2126, 0.7152, 0.0722)));
#else
  return 1.0;
#endif
}

void main() {
  vec3 a = tap(vec2(-2.0, 2.0)), b = tap(vec2(0.0, 2.0)), c = tap(vec2(2.0, 2.0));
  vec3 d = tap(vec2(-1.0, 1.0)), e = tap(vec2(1.0, 1.0));
  vec3 f = tap(vec2(-2.0, 0.0)), g = tap(vec2(0.0, 0.0)), h = tap(vec2(2.0, 0.0));
  vec3 i = tap(vec2(-1.0, -1.0)), j = tap(vec2(1.0, -1.0));
  vec3 k = tap(vec2(-2.0, -2.0)), l = tap(vec2(0.0, -2.0)), m = tap(vec2(2.0, -2.0));
  vec3 inner = (d + e + i + j) * 0.25;
  vec3 tl = (a + b + f + g) * 0.25, tr = (b + c + g + h) * 0.25;
  vec3 bl = (f + g + k + l) * 0.25, br = (g + h + l + m) * 0.25;
  float wi = 0.5 * box_weight(inner), w1 = 0.125 * box_weight(tl), w2 = 0.125 * box_weight(tr);
  float w3 = 0.125 * box_weight(bl), w4 = 0.125 * box_weight(br);
  o_color = vec4((inner * wi + tl * w1 + tr * w2 + bl * w3 + br * w4) / (wi + w1 + w2 + w3 + w4), 1.0);
}
#endif
