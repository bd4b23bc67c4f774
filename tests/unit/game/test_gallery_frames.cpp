// tests/unit/game/test_gallery_frames.cpp — the effect gallery rendered headless at 1280x720:
// in every filled cell of its 5 × 3 grid the effect covers a readable share of the
// cell at its fullest, and stays mostly within it. The share is measured as the pixels the
// particles change (the frame against the same frame without particles), over ticks that catch
// each effect's phases. ARCFIRE_GFX_DUMP=DIR saves the frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "assets/image.h"
#include "game/app/all_settings.h"
#include "game/app/scene_resources.h"
#include "game/render/render_view_builder.h"
#include "game/render/screen_projection.h"
#include "gfx/renderer.h"
#include "gfx_test_util.h"
#include "test_helpers.h"
#include "core/data_root.h"

namespace arc {
namespace {

constexpr int kWidth = 1280, kHeight = 720;
constexpr int kColumns = 5, kRows = 3;
constexpr double kCellWidth = 96, kCellHeight = 66;  // metres, in the plane z = 0 (levels/gallery.json)

// The fifth column holds only the flare, in the middle row.
bool filled(int col, int row) { return col < 4 || row == 1; }

struct Rect {
  int x0, y0, x1, y1;
};

// A cell's rectangle on screen: its corners in the plane z = 0, projected.
Rect cell_rect(const Projector& pr, int col, int row) {
  const double cx = -144 + kCellWidth * col, cy = 66 - kCellHeight * row;
  glm::dvec2 a(0.0), b(0.0);
  pr.project({cx - 0.5 * kCellWidth, cy + 0.5 * kCellHeight, 0}, a);
  pr.project({cx + 0.5 * kCellWidth, cy - 0.5 * kCellHeight, 0}, b);
  return {std::max(0, int(a.x)), std::max(0, int(a.y)), std::min(kWidth, int(b.x)), std::min(kHeight, int(b.y))};
}

bool changed(const Image& a, const Image& b, int x, int y) {
  const size_t i = (size_t(y) * kWidth + x) * 4;
  int d = 0;
  for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])));
  return d > 8;
}

TEST(GalleryFrames, EveryEffectFillsAReadablePartOfItsCell) {
  std::string why;
  if (!test::headless(why)) GTEST_SKIP() << "no EGL context: " << why;
  Game game = Game::load_level(test::repo("levels/gallery.json"), test::options());
  Renderer renderer(RendererDesc{.offscreen = true});
  renderer.apply_settings(all_settings());
  const std::vector<ModelId> models = load_scene_resources(renderer, game.world(), arc::data_root());
  HudState no_hud;
  no_hud.show_hud = false;
  std::array<double, kColumns * kRows> fullest{};
  double spill = 0.0;
  for (int tick = 1; tick <= 240; ++tick) {
    game.step(InputFrame{});
    if (tick != 6 && tick % 30 != 0) continue;
    RenderView view;
    build_render_view(game.world(), models, 1.0, CameraSettings{}, no_hud, kWidth, kHeight, view);
    renderer.render(view, kWidth, kHeight);
    const Image with = renderer.read_pixels();
    view.particles.clear();
    renderer.render(view, kWidth, kHeight);
    const Image without = renderer.read_pixels();
    if (const char* dir = std::getenv("ARCFIRE_GFX_DUMP"); dir && *dir)
      save_image(std::string(dir) + "/gallery_" + std::to_string(tick) + ".png", with);
    const Projector pr = Projector::of(view.camera, kWidth, kHeight);
    double in_cells = 0.0, all = 0.0;
    for (int row = 0; row < kRows; ++row)
      for (int col = 0; col < kColumns; ++col) {
        const Rect r = cell_rect(pr, col, row);
        int n = 0;
        for (int y = r.y0; y < r.y1; ++y)
          for (int x = r.x0; x < r.x1; ++x) n += changed(with, without, x, y) ? 1 : 0;
        const size_t c = size_t(row * kColumns + col);
        fullest[c] = std::max(fullest[c], double(n) / double((r.x1 - r.x0) * (r.y1 - r.y0)));
        in_cells += n;
      }
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) all += changed(with, without, x, y) ? 1 : 0;
    spill = std::max(spill, all > 0 ? 1.0 - in_cells / all : 0.0);
  }
  for (size_t c = 0; c < fullest.size(); ++c) {
    if (!filled(int(c % kColumns), int(c / kColumns))) continue;
    std::printf("cell %zu (row %zu, column %zu): effect covers %.1f%% of it at its fullest\n", c, c / kColumns + 1,
                c % kColumns + 1, 100.0 * fullest[c]);
    EXPECT_GT(fullest[c], 0.03) << "cell " << c;
  }
  // The grid leaves margins (above the top row, beside the columns): little may spill there.
  std::printf("at most %.1f%% of the changed pixels fall outside every cell\n", 100.0 * spill);
  EXPECT_LT(spill, 0.1);
}

}  // namespace
}  // namespace arc
