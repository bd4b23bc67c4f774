// gfx/particle_coverage.h — which tiles of the screen the frame's particles can touch (no GL).
//
// The half-resolution particle target (particle_target.h) is put over the scene by a pass whose
// cost on a software rasteriser is that of a full-screen textured, blended draw, as much as the
// particles themselves in a busy frame. Where no particle landed, the target still holds its
// clear value (no light, transmittance 1) and the composite changes nothing, so it is drawn only
// over the tiles a particle's screen box reaches: the same image, exactly. Boxes come from the
// overdraw budget's footprint estimate (overdraw_budget.h: each quad as particle.vert builds it,
// size clamp and rotation included), widened by the bilinear filter's reach; a particle that
// reaches past the near plane marks the whole screen, since its projection is unbounded.
//
// Example, compiled as GfxCpuExamples.CoveredTiles in tests/unit/gfx/test_gfx_cpu_examples.cpp:
//   ParticleCoverage c;
//   c.reset(1280, 720);
//   c.add_box(640.0f, 360.0f, 50.0f, 20.0f);  // centre (y up) and half-extents, pixels
//   std::vector<PixelRect> rects;
//   c.rects(rects);   // row runs of marked 32-pixel tiles, merged down while equal
#pragma once
#include <vector>

namespace arc {

struct PixelRect {
  int x0, y0, x1, y1;  // [x0, x1) × [y0, y1), GL window pixels (y up)
};

// Where a particle's quad can be on screen, conservatively: x and y from −1 to 1 across the
// view (y up), beyond that where it reaches off screen. A box that is not finite (a quad
// reaching past the near plane) is taken as the whole screen.
struct ScreenBox {
  float x0, y0, x1, y1;
};

class ParticleCoverage {
 public:
  static constexpr int kTile = 32;       // pixels along a tile's side
  static constexpr float kMargin = 4.0f; // pixels: a half-resolution texel and its bilinear neighbour

  void reset(int width, int height);
  void add_box(float cx, float cy, float hx, float hy);  // a non-finite box marks everything
  void add_whole_screen() { whole_ = true; }
  bool whole_screen() const { return whole_; }
  // The marked tiles as rectangles clipped to the screen: runs within a tile row, and a run
  // merged with the one below it when both span the same tiles. Empty when nothing is marked.
  void rects(std::vector<PixelRect>& out) const;
  // Share of the screen's pixels inside rects() (1 for the whole screen).
  double share() const;

 private:
  void resolve() const;
  int width_ = 0, height_ = 0, tiles_x_ = 0, tiles_y_ = 0;
  bool whole_ = false;
  std::vector<int> diff_;            // 2-D difference array of box counts, (tiles_x + 1) × (tiles_y + 1)
  mutable std::vector<char> marked_; // tiles_x × tiles_y, resolved from diff_
  mutable bool resolved_ = false;
};

}  // namespace arc
