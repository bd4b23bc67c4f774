// Golden-image tests of whole game scenes, rendered headless through EGL (Mesa llvmpipe):
// the duel (issue 2), the effect gallery per soft-edge method and per quality preset, and the
// gallery moved 1e9 units from the origin (issue 4). Goldens live in tests/golden/ and are
// rewritten only with ARCFIRE_UPDATE_GOLDEN=1 (tools/update-goldens.sh).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <functional>

#include "core/json.h"
#include "core/settings.h"
#include "game/app/frame_renderer.h"
#include "game/sim/game.h"
#include "gfx/image_compare.h"
#include "platform/platform.h"

namespace {

const std::string kRoot = ARCFIRE_SOURCE_DIR;

bool updating() {
  const char* u = std::getenv("ARCFIRE_UPDATE_GOLDEN");
  return u && std::string(u) == "1";
}

arc::GameOptions game_options() {
  arc::GameOptions o;
  o.root_dir = kRoot;
  return o;
}

// Renders `ticks` ticks of a level with the given settings; skips when no EGL context exists.
arc::Image render_level(const std::string& level, int ticks, const arc::Settings& settings, int w = 480, int h = 270) {
  arc::Game game = arc::Game::load_level(level, game_options());
  for (int i = 0; i < ticks; ++i) game.step(arc::InputFrame{});
  arc::FrameRendererDesc d;
  d.width = w;
  d.height = h;
  d.root_dir = kRoot;
  arc::FrameRenderer fr(d, settings, game);
  return fr.render(game);
}

void check_golden(const std::string& name, const arc::Image& actual) {
  std::string golden = kRoot + "/tests/golden/" + name + ".png";
  if (updating()) {
    arc::save_image(golden, actual);
    GTEST_SKIP() << "updated " << golden;
  }
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " is missing; run tools/update-goldens.sh";
  arc::Image expected = arc::load_image(golden);
  arc::ImageDiff diff = arc::compare_images(expected, actual);
  if (!diff.passed) {
    std::string prefix = std::filesystem::current_path().string() + "/build/test-output/" + name;
    std::filesystem::create_directories(std::filesystem::path(prefix).parent_path());
    arc::write_failure_images(prefix, actual, expected);
    FAIL() << name << ": " << diff.summary() << "; wrote " << prefix << "_actual.png and _diff.png";
  }
}

// Not blank: enough distinct, non-black pixels to be a scene.
void expect_not_blank(const arc::Image& img) {
  size_t lit = 0;
  for (size_t i = 0; i < img.rgba.size(); i += 4)
    if (img.rgba[i] + img.rgba[i + 1] + img.rgba[i + 2] > 60) ++lit;
  EXPECT_GT(lit, img.rgba.size() / 4 / 200) << "the frame is (nearly) black";
}

#define SKIP_WITHOUT_EGL(expr)                                      \
  try {                                                             \
    expr;                                                           \
  } catch (const arc::PlatformError& e) {                           \
    GTEST_SKIP() << "no EGL/OpenGL context here: " << e.what();     \
  }

}  // namespace

TEST(SceneGolden, DuelAtTick60) {
  arc::Image img;
  SKIP_WITHOUT_EGL(img = render_level(kRoot + "/levels/duel.json", 60, arc::Settings::defaults(), 640, 360));
  expect_not_blank(img);
  check_golden("duel_tick060", img);
}

class GallerySoftEdgeGolden : public testing::TestWithParam<const char*> {};
TEST_P(GallerySoftEdgeGolden, MatchesGolden) {
  arc::Settings s = arc::Settings::defaults();
  s.set("render.soft_edges", GetParam(), "test");
  arc::Image img;
  SKIP_WITHOUT_EGL(img = render_level(kRoot + "/levels/gallery.json", 150, s));
  expect_not_blank(img);
  check_golden(std::string("gallery_soft_") + GetParam(), img);
}
INSTANTIATE_TEST_SUITE_P(Methods, GallerySoftEdgeGolden,
                         testing::Values("off", "linear", "contrast", "average_density", "density_extent"));

class GalleryPresetGolden : public testing::TestWithParam<const char*> {};
TEST_P(GalleryPresetGolden, MatchesGolden) {
  arc::Settings s = arc::Settings::defaults();
  s.apply_preset_file(kRoot + "/assets/settings/quality.json", GetParam());
  arc::Image img;
  SKIP_WITHOUT_EGL(img = render_level(kRoot + "/levels/gallery.json", 150, s));
  expect_not_blank(img);
  check_golden(std::string("gallery_preset_") + GetParam(), img);
}
INSTANTIATE_TEST_SUITE_P(Presets, GalleryPresetGolden, testing::Values("low", "medium", "high", "reference"));

// Every position in the gallery (ships, props, effects, camera) moved by 1e9 on each axis.
TEST(SceneLargeCoordinates, GalleryFarFromOriginLooksTheSame) {
  auto doc = arc::JsonDoc::load_file(kRoot + "/levels/gallery.json");
  nlohmann::json j = doc->root();
  std::function<void(nlohmann::json&)> shift = [&](nlohmann::json& v) {
    if (v.is_object()) {
      for (auto it = v.begin(); it != v.end(); ++it) {
        if ((it.key() == "position" || it.key() == "look_at") && it->is_array() && it->size() == 3)
          for (auto& c : *it) c = c.get<double>() + 1.0e9;
        else
          shift(*it);
      }
    } else if (v.is_array()) {
      for (auto& e : v) shift(e);
    }
  };
  shift(j);
  std::string far_level = testing::TempDir() + "/gallery_far.json";
  arc::write_file_atomic(far_level, j.dump(2));
  arc::Image near_img, far_img;
  SKIP_WITHOUT_EGL(near_img = render_level(kRoot + "/levels/gallery.json", 150, arc::Settings::defaults()));
  far_img = render_level(far_level, 150, arc::Settings::defaults());
  arc::ImageDiff diff = arc::compare_images(near_img, far_img);
  if (!diff.passed) {
    std::string prefix = std::filesystem::current_path().string() + "/build/test-output/gallery_far";
    std::filesystem::create_directories(std::filesystem::path(prefix).parent_path());
    arc::write_failure_images(prefix, far_img, near_img);
  }
  EXPECT_TRUE(diff.passed) << diff.summary() << " (far image and diff in build/test-output/gallery_far_*)";
}
