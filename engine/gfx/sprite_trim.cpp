// gfx/sprite_trim.cpp — per sprite and mip level, the box where sampling can be non-zero.
#include "gfx/sprite_trim.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace arc {

int mip_levels(int width, int height) {
  int n = 1;
  for (int s = std::max(width, height); s > 1; s /= 2) ++n;
  return n;
}

Image stretch_nearest(const Image& image, int width, int height) {
  if (image.width == width && image.height == height) return image;
  Image out;
  out.width = width;
  out.height = height;
  out.premultiplied = image.premultiplied;
  out.rgba.resize(size_t(width) * size_t(height) * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t from = (size_t(y * image.height / height) * size_t(image.width) + size_t(x * image.width / width)) * 4;
      std::memcpy(&out.rgba[(size_t(y) * size_t(width) + size_t(x)) * 4], &image.rgba[from], 4);
    }
  return out;
}

namespace {

// One axis: level-0 texels [lo, hi] (inclusive) hold the non-zero ones, of n0; at a level of
// n texels the footprint of texel i is [i·n0/n, (i+1)·n0/n) (rounded outward when n does not
// divide n0), and bilinear filtering reads texel i for coordinates within one texel of its
// centre: (i − 0.5)/n < t < (i + 1.5)/n.
void level_range(int lo, int hi, int n0, int n, float& t0, float& t1) {
  const bool exact = n0 % n == 0;
  int i0 = int((long long)lo * n / n0), i1 = int((long long)hi * n / n0);
  if (!exact) i0 -= 1, i1 += 1;
  t0 = std::clamp((float(i0) - 0.5f) / float(n), 0.0f, 1.0f);
  t1 = std::clamp((float(i1) + 1.5f) / float(n), 0.0f, 1.0f);
}

}  // namespace

std::vector<TrimBox> trim_boxes(const std::vector<Image>& layers) {
  std::vector<TrimBox> boxes;
  if (layers.empty()) return boxes;
  const int w = layers[0].width, h = layers[0].height;
  const int levels = mip_levels(w, h);
  boxes.reserve(layers.size() * size_t(levels));
  for (const Image& img : layers) {
    if (img.width != w || img.height != h || img.rgba.size() != size_t(w) * size_t(h) * 4)
      throw std::invalid_argument("trim_boxes: every layer must have the first one's size");
    int x0 = w, y0 = h, x1 = -1, y1 = -1;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const uint8_t* t = &img.rgba[(size_t(y) * size_t(w) + size_t(x)) * 4];
        if ((t[0] | t[1] | t[2] | t[3]) == 0) continue;
        x0 = std::min(x0, x), x1 = std::max(x1, x);
        y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
    for (int m = 0; m < levels; ++m) {
      TrimBox b{0.5f, 0.5f, 0.5f, 0.5f};
      if (x1 >= 0) {
        level_range(x0, x1, w, std::max(1, w >> m), b.u0, b.u1);
        level_range(y0, y1, h, std::max(1, h >> m), b.v0, b.v1);
      }
      boxes.push_back(b);
    }
  }
  return boxes;
}

float SpriteTrim::facing_depth(float view_depth, float near) { return std::max(view_depth, near); }

float SpriteTrim::segment_depth(float distance, float size, float half_long, float near) {
  const float r = std::max(distance, near);
  return r + (size * size + half_long * half_long) / r;
}

int SpriteTrim::level(TrimMode mode, float lod_scale, float size, float depth, int levels) {
  if (mode == TrimMode::Off || mode == TrimMode::BaseLevel) return 0;
  const float lod = std::log2(std::max(lod_scale * depth / std::max(size, 1e-6f), 1e-30f));
  const int l = int(std::floor(lod + (mode == TrimMode::NearestLevel ? 0.55f : 1.05f)));
  return std::clamp(l, 0, std::max(levels - 1, 0));
}

TrimBox SpriteTrim::box(TrimMode mode, int sprite, float lod_scale, float size, float depth) const {
  const size_t at = size_t(sprite) * size_t(levels);
  if (mode == TrimMode::Off || at + size_t(levels) > boxes.size()) return TrimBox{};
  return boxes[at + size_t(level(mode, lod_scale, size, depth, levels))];
}

TrimMode trim_mode(const RenderSettings& s) {
  using F = RenderSettings::Filter;
  if (!s.sprite_trim) return TrimMode::Off;
  if (s.filter == F::Nearest || s.filter == F::Linear) return TrimMode::BaseLevel;
  return s.filter == F::MipmapNearest ? TrimMode::NearestLevel : TrimMode::Trilinear;
}

}  // namespace arc
