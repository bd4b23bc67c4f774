#version 330 core
// Edge anti-aliasing of the display-ready image, after the console variant of Lottes' FXAA 3.11
// (NVIDIA, 2011): lumas at the four diagonal half-pixel corners find the local contrast and the
// edge direction; where the contrast exceeds a threshold, two pairs of taps along the edge
// (half a pixel and up to two pixels out) are averaged, falling back to the inner pair when
// the outer one crosses another edge. Nine taps, no search loop: a software rasteriser runs
// every instruction on every pixel, so the quality variant's edge walk would cost too much.
// Luma is computed from the (sRGB-encoded) colour, so it works on any input.
in vec2 v_uv;
uniform sampler2D u_image;
uniform vec2 u_texel;  // 1 / image size
out vec4 o_color;

const float kEdgeThreshold = 0.125;     // contrast relative to the local maximum
const float kEdgeThresholdMin = 0.05;   // ignore edges darker than this
const float kEdgeSharpness = 8.0;

float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }

void main() {
  vec4 m = textureLod(u_image, v_uv, 0.0);
  float l_m = luma(m.rgb);
  float l_nw = luma(textureLod(u_image, v_uv + vec2(-0.5, 0.5) * u_texel, 0.0).rgb);
  float l_ne = luma(textureLod(u_image, v_uv + vec2(0.5, 0.5) * u_texel, 0.0).rgb) + 1.0 / 384.0;
  float l_sw = luma(textureLod(u_image, v_uv + vec2(-0.5, -0.5) * u_texel, 0.0).rgb);
  float l_se = luma(textureLod(u_image, v_uv + vec2(0.5, -0.5) * u_texel, 0.0).rgb);
  float l_max = max(max(l_nw, l_ne), max(l_sw, l_se));
  float l_min = min(min(l_nw, l_ne), min(l_sw, l_se));
  float contrast = max(l_max, l_m) - min(l_min, l_m);
  // Gradient across the corners; the edge runs perpendicular to it.
  float gx = (l_ne + l_se) - (l_nw + l_sw);
  float gy = (l_nw + l_ne) - (l_sw + l_se);
  vec2 dir1 = vec2(gy, -gx);
  dir1 *= inversesqrt(max(dot(dir1, dir1), 1e-12));
  vec3 n1 = textureLod(u_image, v_uv - dir1 * 0.5 * u_texel, 0.0).rgb;
  vec3 p1 = textureLod(u_image, v_uv + dir1 * 0.5 * u_texel, 0.0).rgb;
  float dir_min = max(min(abs(dir1.x), abs(dir1.y)) * kEdgeSharpness, 1e-6);
  vec2 dir2 = clamp(dir1 / dir_min, -2.0, 2.0);
  vec3 n2 = textureLod(u_image, v_uv - dir2 * 2.0 * u_texel, 0.0).rgb;
  vec3 p2 = textureLod(u_image, v_uv + dir2 * 2.0 * u_texel, 0.0).rgb;
  vec3 two = (n1 + p1) * 0.5;
  vec3 four = (n2 + p2) * 0.25 + (n1 + p1) * 0.25;
  float l_four = luma(four);
  vec3 blended = (l_four < l_min || l_four > l_max) ? two : four;
  bool edge = contrast >= max(kEdgeThresholdMin, l_max * kEdgeThreshold);
  o_color = vec4(edge ? blended : m.rgb, 1.0);
}
