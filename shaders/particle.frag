#version 330 core
// Controlled-additive blending (Ilmonen 2006 §4): with premultiplied sprite tcola and colour
// fgc = rgb·alpha the output is (fgc·tcola, alpha·talpha·(1 − burn)) under
// glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA). Soft edges scale both (§3, Lorach, Krazanowski).
// The renderer compiles three variants (SOFT, CONTRAST defined 0 or 1) and uses the soft one
// (depth texture read, linearisation) only in frames where a visible particle has soft edges,
// and the contrast one only when one uses the contrast curve: a software rasteriser runs every
// instruction of a shader on every pixel, branches included.
in vec3 v_uv;
in vec4 v_color;  // (rgb·alpha, alpha·(1 − burn))
in float v_depth;
flat in vec4 v_soft;
flat in float v_contrast;
uniform sampler2DArray u_sprites;
uniform sampler2D u_scene_depth;  // this frame's opaque depth, copied
uniform vec2 u_linearize;         // view depth = x / (depth + y) for the depth mode in use
uniform float u_contrast_power;
uniform float u_near;
uniform float u_inv_near_fade;    // 1 / fade distance; huge when the fade is off
out vec4 o_color;

const float kEps = 1e-6;

void main() {
  vec4 tex = texture(u_sprites, v_uv);
  float k = clamp((v_depth - u_near) * u_inv_near_fade, 0.0, 1.0);
#if SOFT
  float d = texelFetch(u_scene_depth, ivec2(gl_FragCoord.xy), 0).r;
  float denom = d + u_linearize.y;
  float zb = abs(denom) > 1e-30 ? u_linearize.x / denom : 1e30;
  // Linear ramp (Ilmonen), average density (quad already at z − E/2), density extent (quad at
  // z − E, range scaled by 1/texture alpha and mapped from [−1, 1]).
  float x = (zb - v_depth - v_soft.y) * v_soft.x + v_soft.z;
  x = mix(x, x * 0.5 / max(tex.a, kEps) + 0.5, v_soft.w);
  x = clamp(x, 0.0, 1.0);
#if CONTRAST
  // Lorach's contrast curve: 0.5·(2x)^p below 0.5, mirrored above.
  float c = 0.5 * pow(max(2.0 * min(x, 1.0 - x), 1e-8), u_contrast_power);
  x = mix(x, x < 0.5 ? c : 1.0 - c, v_contrast);
#endif
  k *= x;
#endif
  o_color = v_color * tex * k;
}
