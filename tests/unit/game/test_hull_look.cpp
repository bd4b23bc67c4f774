// tests/unit/game/test_hull_look.cpp — hulls that read in battle, rendered
// headless through EGL at 1280x720 with the game's own models and mesh shader:
// ClassesReadApartAt300Metres: a Viper, a Dart and a Warden of one team 300 m away each cover
// a readable patch, stand out from the sky and differ from one another in colour;
// BacklitHullKeepsItsSilhouette: a Viper with the light straight behind it (toward the camera)
// is not a black cut-out: the fill light shapes it and the Fresnel rim brightens its outline
// (the figures before both are in the test).
// Only meshes are drawn (particles and HUD off); ARCFIRE_GFX_DUMP=DIR saves the frames.
#include <gtest/gtest.h>

#include <cmath>
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

struct Frames {
  Image lit, sky;  // with the ships, and the same view without them
  RenderView view;
};

// Renders the level's first tick with only its meshes, then without them; `light` (the
// direction light travels) replaces the default when non-zero.
Frames render_ships(const std::string& level, const glm::vec3& light, const char* dump) {
  Game game = Game::load_level(level, test::options());
  game.step(InputFrame{});
  Renderer renderer(RendererDesc{.offscreen = true});
  // The default look (HDR, bloom) without the edge filter: these tests read the shading of
  // the outline pixels, which FXAA blends with the sky (Antialias.* in test_gfx test that).
  Settings settings = all_settings();
  settings.set("render.antialias", "off", "test_hull_look");
  renderer.apply_settings(settings);
  const std::vector<ModelId> models = load_scene_resources(renderer, game.world(), arc::data_root());
  HudState no_hud;
  no_hud.show_hud = false;
  Frames f;
  build_render_view(game.world(), models, 1.0, CameraSettings{}, no_hud, kWidth, kHeight, f.view);
  f.view.particles.clear();
  f.view.hud = HudLayer{};
  if (glm::length(light) > 0.0f) f.view.light_direction = light;
  renderer.render(f.view, kWidth, kHeight);
  f.lit = renderer.read_pixels();
  RenderView empty = f.view;
  empty.meshes.clear();
  renderer.render(empty, kWidth, kHeight);
  f.sky = renderer.read_pixels();
  if (const char* dir = std::getenv("ARCFIRE_GFX_DUMP"); dir && *dir) save_image(std::string(dir) + "/" + dump + ".png", f.lit);
  return f;
}

glm::vec3 rgb(const Image& img, int x, int y) {
  const size_t i = (size_t(y) * img.width + x) * 4;
  return glm::vec3(img.rgba[i], img.rgba[i + 1], img.rgba[i + 2]) / 255.0f;
}

float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// A pixel the ship covers: the frame differs from the sky there.
bool covered(const Frames& f, int x, int y) {
  const glm::vec3 d = glm::abs(rgb(f.lit, x, y) - rgb(f.sky, x, y));
  return std::max(d.r, std::max(d.g, d.b)) > 6.0f / 255.0f;
}

struct Patch {
  int pixels = 0;
  glm::vec3 mean{0.0f};
  float sky_luminance = 0.0f;
};

Patch patch(const Frames& f, glm::dvec2 centre, int half) {
  Patch p;
  float sky = 0.0f;
  int sky_n = 0;
  for (int y = std::max(0, int(centre.y) - half); y < std::min(kHeight, int(centre.y) + half); ++y)
    for (int x = std::max(0, int(centre.x) - half); x < std::min(kWidth, int(centre.x) + half); ++x) {
      if (!covered(f, x, y)) {
        sky += luminance(rgb(f.sky, x, y)), ++sky_n;
        continue;
      }
      p.mean += rgb(f.lit, x, y);
      ++p.pixels;
    }
  p.mean /= float(std::max(p.pixels, 1));
  p.sky_luminance = sky / float(std::max(sky_n, 1));
  return p;
}

TEST(HullLook, ClassesReadApartAt300Metres) {
  std::string why;
  if (!test::headless(why)) GTEST_SKIP() << "no EGL context: " << why;
  const char* classes[] = {"viper", "dart", "warden"};
  std::string ships;
  for (int i = 0; i < 3; ++i)
    ships += std::string(i ? ", " : "") + R"({ "name": ")" + classes[i] + R"(", "class": ")" + classes[i] +
             R"(", "team": "blue", "ai": "none", "position": [)" + std::to_string(-45 + 45 * i) +
             R"(, 0, -300], "orientation": [60, 30, 0] })";
  const std::string level = test::write_level("classes_300m.json", test::level_text(ships, R"(
  "camera": { "mode": "fixed", "position": [0, 0, 0], "look_at": [0, 0, -300], "fov": 60 },)"));
  const Frames f = render_ships(level, glm::vec3(0.0f), "classes_300m");
  const Projector pr = Projector::of(f.view.camera, kWidth, kHeight);
  std::vector<Patch> patches;
  for (int i = 0; i < 3; ++i) {
    glm::dvec2 at;
    ASSERT_TRUE(pr.project({-45.0 + 45.0 * i, 0.0, -300.0}, at));
    patches.push_back(patch(f, at, 40));
    const Patch& p = patches.back();
    std::printf("%s at 300 m: %d pixels, mean colour %.3f %.3f %.3f (luminance %.3f, sky %.3f)\n", classes[i], p.pixels,
                p.mean.r, p.mean.g, p.mean.b, luminance(p.mean), p.sky_luminance);
    EXPECT_GT(p.pixels, 60) << classes[i];
    EXPECT_GT(luminance(p.mean), 0.2f) << classes[i] << " stands out from the sky";
    EXPECT_GT(luminance(p.mean), 4.0f * p.sky_luminance) << classes[i];
  }
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      EXPECT_GT(glm::length(patches[size_t(i)].mean - patches[size_t(j)].mean), 0.08f) << classes[i] << " / " << classes[j];
}

TEST(HullLook, BacklitHullKeepsItsSilhouette) {
  std::string why;
  if (!test::headless(why)) GTEST_SKIP() << "no EGL context: " << why;
  const std::string level = test::write_level("backlit.json", test::level_text(
      R"({ "name": "Viper", "class": "viper", "team": "blue", "ai": "none", "position": [0, 0, -40], "orientation": [60, 20, 0] })",
      R"(
  "camera": { "mode": "fixed", "position": [0, 0, 0], "look_at": [0, 0, -40], "fov": 60 },)"));
  // The light travels toward the camera: every face the camera sees is turned away from it.
  const Frames f = render_ships(level, glm::vec3(0.0f, 0.0f, 1.0f), "backlit_viper");
  double edge = 0.0, inner = 0.0;
  int edges = 0, inners = 0;
  for (int y = 1; y + 1 < kHeight; ++y)
    for (int x = 1; x + 1 < kWidth; ++x) {
      if (!covered(f, x, y)) continue;
      const bool on_edge = !covered(f, x - 1, y) || !covered(f, x + 1, y) || !covered(f, x, y - 1) || !covered(f, x, y + 1);
      (on_edge ? edge : inner) += luminance(rgb(f.lit, x, y));
      ++(on_edge ? edges : inners);
    }
  ASSERT_GT(inners, 2000);
  edge /= std::max(edges, 1);
  inner /= inners;
  std::printf("backlit viper: outline luminance %.3f over %d pixels, inside %.3f over %d\n", edge, edges, inner, inners);
  // Measured in 8-bit: 0.245 inside and 0.295 on the outline; with ambient light alone (before
  // the fill and the rim) 0.084 and 0.158, a dark shape that only its glowing parts gave away.
  // In HDR through the tone curve (the default): 0.424 inside, 0.403 on the outline: the whole
  // hull reads against the sky and the outline stays about as bright as the hull.
  EXPECT_GT(inner, 0.16) << "the fill light keeps the hull's shape";
  EXPECT_GT(edge, 0.22) << "the rim outlines the silhouette";
  EXPECT_GT(edge, 0.9 * inner);
}

}  // namespace
}  // namespace arc
