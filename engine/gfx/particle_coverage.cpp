// gfx/particle_coverage.cpp — tile marks by a 2-D difference array, and their rectangles (no GL).
#include "gfx/particle_coverage.h"

#include <algorithm>
#include <cmath>

namespace arc {

void ParticleCoverage::reset(int width, int height) {
  width_ = std::max(width, 1);
  height_ = std::max(height, 1);
  tiles_x_ = (width_ + kTile - 1) / kTile;
  tiles_y_ = (height_ + kTile - 1) / kTile;
  whole_ = false;
  diff_.assign(size_t(tiles_x_ + 1) * size_t(tiles_y_ + 1), 0);
  resolved_ = false;
}

// One box costs four additions whatever its size; resolve() sums them once per frame.
void ParticleCoverage::add_box(float cx, float cy, float hx, float hy) {
  const float x0 = cx - hx - kMargin, x1 = cx + hx + kMargin, y0 = cy - hy - kMargin, y1 = cy + hy + kMargin;
  if (!std::isfinite(x0) || !std::isfinite(x1) || !std::isfinite(y0) || !std::isfinite(y1)) {
    whole_ = true;
    return;
  }
  if (x1 <= 0.0f || y1 <= 0.0f || x0 >= float(width_) || y0 >= float(height_)) return;
  const int tx0 = std::max(0, int(std::floor(x0 / float(kTile))));
  const int ty0 = std::max(0, int(std::floor(y0 / float(kTile))));
  const int tx1 = std::min(tiles_x_, int(std::floor(x1 / float(kTile))) + 1);
  const int ty1 = std::min(tiles_y_, int(std::floor(y1 / float(kTile))) + 1);
  const size_t stride = size_t(tiles_x_ + 1);
  diff_[size_t(ty0) * stride + size_t(tx0)] += 1;
  diff_[size_t(ty0) * stride + size_t(tx1)] -= 1;
  diff_[size_t(ty1) * stride + size_t(tx0)] -= 1;
  diff_[size_t(ty1) * stride + size_t(tx1)] += 1;
  resolved_ = false;
}

void ParticleCoverage::resolve() const {
  if (resolved_) return;
  marked_.assign(size_t(tiles_x_) * size_t(tiles_y_), 0);
  const size_t stride = size_t(tiles_x_ + 1);
  std::vector<int> row(size_t(tiles_x_ + 1), 0);  // column sums of diff_ down to this row
  for (int y = 0; y < tiles_y_; ++y) {
    int run = 0;
    for (int x = 0; x < tiles_x_; ++x) {
      row[size_t(x)] += diff_[size_t(y) * stride + size_t(x)];
      run += row[size_t(x)];
      marked_[size_t(y) * size_t(tiles_x_) + size_t(x)] = whole_ || run > 0;
    }
  }
  resolved_ = true;
}

void ParticleCoverage::rects(std::vector<PixelRect>& out) const {
  out.clear();
  if (tiles_x_ == 0) return;
  if (whole_) {
    out.push_back({0, 0, width_, height_});
    return;
  }
  resolve();
  std::vector<size_t> below, here;  // rects ending at this row's bottom edge, and at its top
  for (int y = 0; y < tiles_y_; ++y) {
    here.clear();
    const char* m = &marked_[size_t(y) * size_t(tiles_x_)];
    for (int x = 0; x < tiles_x_;) {
      if (!m[x]) {
        ++x;
        continue;
      }
      int end = x;
      while (end < tiles_x_ && m[end]) ++end;
      const PixelRect r{x * kTile, y * kTile, std::min(end * kTile, width_), std::min((y + 1) * kTile, height_)};
      // Grow the rectangle below when it spans exactly these columns.
      auto same = std::find_if(below.begin(), below.end(), [&](size_t i) { return out[i].x0 == r.x0 && out[i].x1 == r.x1; });
      if (same != below.end()) {
        out[*same].y1 = r.y1;
        here.push_back(*same);
      } else {
        here.push_back(out.size());
        out.push_back(r);
      }
      x = end;
    }
    below.swap(here);
  }
}

// The marked tiles' pixels (the last row and column cut at the screen's edge), as rects() covers them.
double ParticleCoverage::share() const {
  if (whole_) return 1.0;
  resolve();
  double px = 0;
  for (int y = 0; y < tiles_y_; ++y)
    for (int x = 0; x < tiles_x_; ++x)
      if (marked_[size_t(y) * size_t(tiles_x_) + size_t(x)])
        px += double(std::min(kTile, width_ - x * kTile)) * double(std::min(kTile, height_ - y * kTile));
  return px / (double(width_) * double(height_));
}

}  // namespace arc
