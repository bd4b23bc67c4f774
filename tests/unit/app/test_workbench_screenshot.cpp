// The effect workbench's window as tests/workbench/workbench_window.sh captured it (F12 under
// xvfb-run): a picture of the effect with the panel over it, not a blank or single-colour
// frame. Runs only when ARCFIRE_WORKBENCH_SHOT names the screenshot (the script sets it).
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <string>

#include "assets/image.h"

namespace {

struct Rgb {
  int r, g, b;
};

Rgb pixel(const arc::Image& im, int x, int y) {
  const size_t i = (size_t(y) * size_t(im.width) + size_t(x)) * 4;
  return {im.rgba[i], im.rgba[i + 1], im.rgba[i + 2]};
}

}  // namespace

TEST(WorkbenchScreenshot, IsNotBlankAndShowsThePanel) {
  const char* path = std::getenv("ARCFIRE_WORKBENCH_SHOT");
  if (!path) GTEST_SKIP() << "set by tests/workbench/workbench_window.sh (ctest workbench_window_smoke)";
  const arc::Image im = arc::load_image(path);
  ASSERT_EQ(im.width, 1280);
  ASSERT_EQ(im.height, 720);
  // Not blank: a frame of stars, particles and panel text has hundreds of colours.
  std::set<int> colours;
  for (int y = 0; y < im.height; y += 2)
    for (int x = 0; x < im.width; x += 2) {
      const Rgb p = pixel(im, x, y);
      colours.insert(p.r << 16 | p.g << 8 | p.b);
    }
  EXPECT_GT(colours.size(), 200u);
  // The panel: its active title bar (Dear ImGui's dark style, blue) across the top left, and
  // its near-black body below it, while the view on the right is the scene.
  const Rgb title = pixel(im, 200, 8);
  EXPECT_GT(title.b, title.r + 40) << "title bar " << title.r << "," << title.g << "," << title.b;
  EXPECT_GT(title.b, 90);
  int body_dark = 0;
  for (int y = 500; y < 700; y += 10) {
    const Rgb p = pixel(im, 405, y);
    body_dark += p.r < 40 && p.g < 40 && p.b < 40;
  }
  EXPECT_GE(body_dark, 15);
}
