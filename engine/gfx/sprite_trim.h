// gfx/sprite_trim.h — each sprite's quad cut down to where it can show anything (no GL).
//
// A particle's quad blends every pixel it covers, but a sprite is mostly empty: the spark is a
// thin streak down the middle of its square (13 % of it holds a non-zero texel), the flare's
// rays end well inside theirs (66 %), a smoke puff's ragged edge a few texels from its sides
// (76 %). Where every texel a sample reads is zero the particle adds nothing (premultiplied
// colour and alpha both 0: the blend leaves the pixel as it was), so drawing the quad cut to
// the box of those texels gives the same picture with fewer blended pixels — the particle
// trimming of Persson's "Graphics Gems for Games" (2009), with a box rather than a polygon, so
// a particle stays two triangles.
//
// The box depends on the mip level the sampler reads: a texel of level m averages a block of
// 2^m × 2^m level-0 texels, so the non-zero region grows by up to a block a side, and a
// bilinear sample reads the texels within one texel of it. shaders/particle.vert picks, per
// particle, the coarsest level any of its pixels can read (from its size on screen and the
// filter) and takes that level's box; a coarser level's box holds every finer one's.
//
// Example, compiled as GfxCpuExamples.TrimBoxes in tests/unit/gfx/test_gfx_cpu_examples.cpp:
//   std::vector<TrimBox> boxes = trim_boxes(layers);   // layers: premultiplied, one size
//   TrimBox b = boxes[size_t(layer) * mip_levels(w, h) + level];  // u, v in [0, 1]
#pragma once
#include <vector>

#include "assets/image.h"
#include "gfx/render_settings.h"

namespace arc {

// A rectangle of texture coordinates: u across the image's columns, v down its rows (row 0 at
// v = 0, as the sprite array is uploaded). Empty (u0 = u1 = v0 = v1 = 0.5) for a sprite with
// no non-zero texel.
struct TrimBox {
  float u0 = 0, v0 = 0, u1 = 1, v1 = 1;
};

// The number of mip levels of a w × h texture down to 1 × 1 (as glGenerateMipmap makes).
int mip_levels(int width, int height);

// `image` stretched to width × height by nearest sampling (how the sprite array holds a
// smaller sprite), or a copy when it already has that size.
Image stretch_nearest(const Image& image, int width, int height);

// For every layer (all the same size, premultiplied RGBA8) and every mip level, the box
// outside which bilinear sampling of that level returns exactly zero: boxes[layer · levels +
// level]. Holds for box-filtered mipmaps of any size (a level's texel is taken to average the
// level-0 texels its footprint touches).
std::vector<TrimBox> trim_boxes(const std::vector<Image>& layers);

// Which levels the sprite sampler can read (render.texture_filter): only the base level (no
// mipmaps), the nearest level to the level of detail, or the two around it (trilinear). Off:
// whole quads.
enum class TrimMode : int { Off = -1, BaseLevel = 0, NearestLevel = 1, Trilinear = 2 };

// The boxes of a sprite array and the rule particle.vert picks a particle's box by, for the
// CPU's blended-area estimate (overdraw_budget.h). The sampler's level of detail across a
// quad's narrower side (its half-width `size`; the long side of a segment is longer) is at
// most that of a fronto-parallel quad at some depth D:
//   lod = log2(texels · tan(fov_y/2) / height_px · D / size).
// A camera-facing quad is fronto-parallel (particle.vert turns it in the view plane), D its
// centre's view depth. An axis-locked segment's quad lies square to the view ray through its
// centre, at distance R from the eye. Projecting that plane to the screen scales its area by
// P²·R/Z³ at a point of view depth Z (P: pixels per unit at depth 1) and no direction by more
// than P·|q|/Z², so no direction by less than P·R/(Z·|q|) ≥ P·R/(R² + radius²): every part of
// it shows at least as large as a fronto-parallel quad at D = R + radius²/R (radius² = size² +
// half_long², the farthest corner). The coarsest level the sampler can read is then
// floor(lod + 0.55) (nearest: the level is lod rounded, with 0.05 for rounding) or
// floor(lod + 1.05) (trilinear: the next one up too).
struct SpriteTrim {
  std::vector<TrimBox> boxes;  // trim_boxes() of the array
  int levels = 1;              // mip levels of each layer
  int texels = 1;              // the larger side of a layer

  // D (see above) of a camera-facing quad at view depth `view_depth`, and of a segment's quad
  // at `distance` from the eye; both at least the near plane's distance.
  static float facing_depth(float view_depth, float near);
  static float segment_depth(float distance, float size, float half_long, float near);
  // The level a quad of half-width `size` at D = `depth` takes: `lod_scale` = texels ·
  // tan(fov_y/2) / height_px.
  static int level(TrimMode mode, float lod_scale, float size, float depth, int levels);
  // Its box: the whole quad when off or the sprite has no boxes.
  TrimBox box(TrimMode mode, int sprite, float lod_scale, float size, float depth) const;
  // texels · tan(fov_y/2) / height_px, the shader's u_lod_scale.
  float lod_scale(float tan_half_y, int height_px) const { return float(texels) * tan_half_y / float(height_px > 0 ? height_px : 1); }
};

// The mode render.texture_filter (and RenderSettings::sprite_trim) gives.
TrimMode trim_mode(const RenderSettings& settings);

}  // namespace arc
