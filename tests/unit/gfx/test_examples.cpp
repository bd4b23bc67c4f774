// The usage examples in the banners of engine/gfx headers, as tests. Each example runs here
// between "example begin" and "example end", and HeaderExamples.MatchTheirTests (tests/unit/
// core) fails when a banner's lines are not in its test, so an example cannot go stale.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gfx_test_util.h"
#include "core/data_root.h"

namespace arc {
namespace {

TEST(RendererExample, DrawsAView) {
  REQUIRE_CONTEXT();
  // example begin
  Renderer renderer({.offscreen = true});
  ModelId ship = renderer.add_model(load_model(data_root() + "/assets/models/viper.glb"));
  RenderView view;
  view.meshes.push_back({ship, {0, 0, -20}});
  renderer.set_sprites({load_sprite(data_root() + "/assets/textures/sprite_smoke.png")});
  Settings settings;
  register_render_settings(settings);  // the render.* keys at their defaults
  renderer.apply_settings(settings);
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
  Renderer renderer({.offscreen = true});
  const ModelId ship = renderer.add_model(scenes::box_model({2, 1, 3}, {0.6f, 0.6f, 0.6f, 1}, glm::vec3(0.1f)));
  // example begin
  RenderView view;
  view.camera.position = {0.0, 2.0, 30.0};
  view.camera.fov_y_radians = 1.0;
  view.meshes.push_back({.model = ship, .position = {0.0, 0.0, 0.0}});  // ship: from Renderer::add_model()
  ParticleInstance spark{};
  spark.pos[2] = -30.0f;                   // relative to the camera: 30 units ahead
  spark.size = 0.5f;
  spark.color[0] = spark.color[3] = 1.0f;  // rgb premultiplied by alpha, then alpha
  spark.burn = 1.0f;                       // additive
  view.particles.push_back(spark);
  view.hud.texts.push_back({8, 8, 1.0f, {1, 1, 1, 1}, "SHIELD 100"});
  // example end
  renderer.render(view, 160, 90);
  const FrameStats stats = renderer.last_stats();
  EXPECT_EQ(stats.particles_drawn, 1);
  EXPECT_EQ(stats.draw_calls, 5) << "sky (2), the box, the spark, the HUD";
}

}  // namespace
}  // namespace arc
