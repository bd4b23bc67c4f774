// The usage examples in the banners of engine/gfx headers, as tests. Each example runs here
// between "example begin" and "example end", and HeaderExamples.MatchTheirTests fails when a
// banner and its test no longer say the same thing, so an example cannot go stale.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "gfx_test_util.h"

namespace arc {
namespace {

TEST(RendererExample, DrawsAView) {
  REQUIRE_CONTEXT();
  // example begin
  Renderer renderer({.offscreen = true});
  int ship = renderer.add_model(load_model(ARCFIRE_SOURCE_DIR "/assets/models/viper.glb"));
  RenderView view;
  view.meshes.push_back({ship, {0, 0, -20}});
  renderer.set_sprites({load_sprite(ARCFIRE_SOURCE_DIR "/assets/textures/sprite_smoke.png")});
  renderer.apply_settings(Settings::defaults());
  renderer.render(view, 640, 360);
  Image frame = renderer.read_pixels();
  // example end
  EXPECT_EQ(frame.width, 640);
  EXPECT_EQ(frame.height, 360);
  EXPECT_GT(renderer.last_stats().draw_calls, 2) << "the sky's two draws and the ship's";
  float lit = 0;
  for (int y = 170; y < 190; ++y)
    for (int x = 310; x < 330; ++x) lit = std::max(lit, test::channel(frame, x, y, 0) + test::channel(frame, x, y, 1));
  EXPECT_GT(lit, 0.2f) << "the ship in the middle of the frame";
}

TEST(RenderViewExample, DescribesAFrame) {
  REQUIRE_CONTEXT();
  // example begin
  RenderView view;
  view.camera.position = {0.0, 2.0, 30.0};
  view.camera.fov_y_radians = 1.0;
  view.meshes.push_back({.model = 0, .position = {0.0, 0.0, 0.0}});  // the first Renderer::add_model()
  ParticleInstance spark{};
  spark.pos[2] = -30.0f;                   // relative to the camera: 30 units ahead
  spark.size = 0.5f;
  spark.color[0] = spark.color[3] = 1.0f;  // rgb premultiplied by alpha, then alpha
  spark.burn = 1.0f;                       // additive
  view.particles.push_back(spark);
  view.hud.texts.push_back({8, 8, 1.0f, {1, 1, 1, 1}, "SHIELD 100"});
  // example end
  Renderer renderer({.offscreen = true});
  renderer.add_model(scenes::box_model({2, 1, 3}, {0.6f, 0.6f, 0.6f, 1}, glm::vec3(0.1f)));
  renderer.render(view, 160, 90);
  const FrameStats stats = renderer.last_stats();
  EXPECT_EQ(stats.particles_drawn, 1);
  EXPECT_EQ(stats.draw_calls, 5) << "sky (2), the box, the spark, the HUD";
}

std::vector<std::string> read_lines(const std::string& path) {
  std::ifstream f(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(f, line);) lines.push_back(line);
  return lines;
}

// The lines under "// example: <this file>, <test>" in a header, without their "//   ".
std::vector<std::string> banner_example(const std::string& header, const std::string& test) {
  const std::vector<std::string> lines = read_lines(header);
  std::vector<std::string> example;
  const std::string marker = "// example: tests/unit/gfx/test_examples.cpp, " + test;
  auto it = std::find(lines.begin(), lines.end(), marker);
  if (it == lines.end()) return example;
  for (++it; it != lines.end() && it->rfind("//   ", 0) == 0; ++it) example.push_back(it->substr(5));
  return example;
}

// The lines between "example begin" and "example end" in the body of `test`, unindented.
std::vector<std::string> test_example(const std::string& test) {
  const std::vector<std::string> lines = read_lines(ARCFIRE_SOURCE_DIR "/tests/unit/gfx/test_examples.cpp");
  const std::string suite = test.substr(0, test.find('.')), name = test.substr(test.find('.') + 1);
  auto it = std::find(lines.begin(), lines.end(), "TEST(" + suite + ", " + name + ") {");
  std::vector<std::string> example;
  it = std::find(it, lines.end(), "  // example begin");
  if (it == lines.end()) return example;
  for (++it; it != lines.end() && *it != "  // example end"; ++it) example.push_back(it->substr(std::min<size_t>(2, it->size())));
  return example;
}

TEST(HeaderExamples, MatchTheirTests) {
  const std::pair<const char*, const char*> examples[] = {
      {"engine/gfx/renderer.h", "RendererExample.DrawsAView"},
      {"engine/gfx/render_view.h", "RenderViewExample.DescribesAFrame"},
  };
  for (const auto& [header, test] : examples) {
    const std::vector<std::string> in_banner = banner_example(std::string(ARCFIRE_SOURCE_DIR "/") + header, test);
    ASSERT_FALSE(in_banner.empty()) << header << " names no example in " << test;
    EXPECT_EQ(in_banner, test_example(test)) << header << " and " << test << " differ";
  }
}

}  // namespace
}  // namespace arc
