#version 330 core
// Controlled-additive blending (Ilmonen 2006 §4): with premultiplied sprite tcola and colour
// fgc = rgb·alpha the output is (fgc·tcola, alpha·talpha·(1 − burn)) under
// glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA). Soft edges scale both (§3, Lorach, Krazanowski).
// The renderer compiles variants (SOFT, CONTRAST, CONTRAST_SQUARE, DENSITY_EXTENT, FB_DEPTH defined
// 0 or 1) and uses the soft one (depth read, linearisation) only for runs of particles an opaque
// surface can reach, the contrast one only when one of the run uses the contrast curve, the
// squaring one when the contrast power is 2 (the default), and the density-extent one only when
// one of the run uses that method: a software rasteriser runs every instruction of a shader on
// every pixel, branches and mixes with a weight of 0 included, and pow() is a log2 and an exp2
// polynomial per pixel.
#if SOFT && FB_DEPTH
// The opaque depth under this fragment, read from the framebuffer drawn into (the scene's
// depth, or the half-resolution target's): no copy, and on llvmpipe a load of the depth tile
// the depth test has in hand instead of a texture fetch.
#extension GL_ARM_shader_framebuffer_fetch_depth_stencil : require
#endif
in vec2 v_uv;
in float v_depth;
flat in vec4 v_color;  // (rgb·alpha, alpha·(1 − burn))
flat in vec4 v_soft;   // linearize.x·inv_extent, inv_extent, offset·inv_extent − bias, use texture alpha
flat in vec2 v_aux;    // contrast (0/1), sprite layer
uniform sampler2DArray u_sprites;
uniform sampler2D u_scene_depth;  // this frame's opaque depth, copied (nearest filtering)
uniform vec2 u_inv_depth_size;    // 1 / its size in texels
uniform vec3 u_linearize;         // view depth = x / (y·depth + z); the denominator is ≥ 0
uniform float u_contrast_power;
uniform float u_near;
uniform float u_inv_near_fade;    // 1 / fade distance; huge when the fade is off
out vec4 o_color;

const float kEps = 1e-6;

void main() {
  // The mip level from the uv derivatives of each 2×2 pixel quad. Not an explicit level per
  // particle (a flat input): llvmpipe then samples every pixel on its own (a per-element level),
  // which makes the particle pass several times slower.
  vec4 tex = texture(u_sprites, vec3(v_uv, v_aux.y));
  float k = clamp((v_depth - u_near) * u_inv_near_fade, 0.0, 1.0);
#if SOFT
  // Only particles an opaque surface can reach read the depth copy: the renderer gives the
  // others (and method off) inv_extent 0, and the arithmetic below then gives exactly 1. The
  // condition is flat, so a GPU skips the read wherever all fragments shaded together are clear
  // (it is uniform over a particle). llvmpipe pays for the read on every pixel of the draw
  // whatever the branch, so there the saving is the frames where no particle needs soft
  // edges at all (the renderer then picks the hard program and skips the depth copy).
  float d = 0.0;
#if FB_DEPTH
  d = gl_LastFragDepthARM;  // the value the copy would hold at this pixel
#else
  // A nearest-filtered read at the texel centre (gl_FragCoord is one): the same texel as
  // texelFetch, cheaper per pixel on llvmpipe, which bounds-checks texelFetch.
  if (v_soft.y != 0.0) d = textureLod(u_scene_depth, gl_FragCoord.xy * u_inv_depth_size, 0.0).r;
#endif
  // (zb − z − offset)/extent + bias, zb the opaque view depth (huge where there is none).
  // Linear ramp (Ilmonen), average density (quad already at z − E/2), density extent (quad at
  // z − E, range scaled by 1/texture alpha and mapped from [−1, 1]).
  float x = v_soft.x / max(d * u_linearize.y + u_linearize.z, 1e-30) - (v_depth * v_soft.y + v_soft.z);
#if DENSITY_EXTENT
  // Only density extent's range scales with the texture alpha (v_soft.w 1; 0 for the others,
  // whose runs take the variant without it, since the scaling costs every pixel).
  x = mix(x, x * 0.5 / max(tex.a, kEps) + 0.5, v_soft.w);
#endif
  x = clamp(x, 0.0, 1.0);
#if CONTRAST
  // Lorach's contrast curve: 0.5·(2x)^p below 0.5, mirrored above.
  float y = max(2.0 * min(x, 1.0 - x), 1e-8);
#if CONTRAST_SQUARE
  float c = 0.5 * (y * y);
#else
  float c = 0.5 * pow(y, u_contrast_power);
#endif
  x = mix(x, x < 0.5 ? c : 1.0 - c, v_aux.x);
#endif
  k *= x;
#endif
  o_color = v_color * tex * k;
}
