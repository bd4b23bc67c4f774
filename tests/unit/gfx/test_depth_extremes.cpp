// Depth at its extremes (tests/README.md, "Extremes"), headless through EGL: a near plane of
// 0.01 m with a box 3 cm away and a ship-sized box 1e7 m away in one frame, both drawn, the far
// one in front of a wall only 0.1 % farther without z-fighting; and the soft-edge fade of a
// particle just in front of a surface, right to 1 % of the particle's size both at 5 cm and at
// 1e7 m. Reversed-Z float depth (DESIGN.md) is what makes both hold; the tests need clip
// control (llvmpipe has it) and skip without it. And a particle at the camera in the overdraw
// budget's estimate (no GL).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gfx/overdraw_budget.h"
#include "gfx_test_util.h"

namespace arc {
namespace {

constexpr int kW = 320, kH = 180;

RenderView near_far_view() {
  RenderView v = test::dark_view();
  v.camera.near_plane = 0.01;
  v.ambient = glm::vec3(1.0f);  // unlit colours: each surface shows its base colour
  return v;
}

// Pixel (x, y) of an RGBA8 image as 0..1 floats.
glm::vec3 rgb(const Image& img, int x, int y) {
  return {test::channel(img, x, y, 0), test::channel(img, x, y, 1), test::channel(img, x, y, 2)};
}

TEST(DepthExtremes, NearPlane1cmAndAShip1e7AwayBothDrawnWithoutZFighting) {
  REQUIRE_CONTEXT();
  auto r = std::make_unique<Renderer>(RendererDesc{.offscreen = true});
  if (!r->has_clip_control()) GTEST_SKIP() << "no clip control: reversed-Z float depth is not available";
  r->set_render_settings(test::plain_settings());
  const ModelId near_box = r->add_model(scenes::box_model({0.004f, 0.004f, 0.004f}, {0, 1, 0, 1}, glm::vec3(0)));
  const ModelId ship = r->add_model(scenes::box_model({3e5f, 3e5f, 3e5f}, {1, 0, 0, 1}, glm::vec3(0)));
  const ModelId wall = r->add_model(scenes::wall_model(4e6f, 4e6f, {0, 0, 1, 1}, glm::vec3(0)));
  RenderView v = near_far_view();
  v.meshes.push_back({near_box, {-0.012, 0, -0.03}});
  v.meshes.push_back({ship, {2e6, 0, -1e7}});         // its front face at 0.97e7
  v.meshes.push_back({wall, {2e6, 0, -1e7 - 3.1e5}});  // 0.1 % behind the box's back face
  r->render(v, kW, kH);
  const Image img = r->read_pixels();
  test::dump_if_asked("depth_near_far", img);
  // The near box left of centre, the ship right of it, the wall around the ship.
  const float f = float(kH) * 0.5f / std::tan(0.45f);  // pixels per unit of x/z
  const int near_x = int(kW * 0.5f - f * 0.012f / 0.03f), ship_x = int(kW * 0.5f + f * 2e6f / 0.97e7f);
  EXPECT_GT(rgb(img, near_x, kH / 2).g, 0.5f) << "the box 3 cm away is drawn";
  int ship_px = 0, wall_in_ship = 0;
  for (int y = kH / 2 - 4; y <= kH / 2 + 4; ++y)
    for (int x = ship_x - 4; x <= ship_x + 4; ++x) {
      const glm::vec3 c = rgb(img, x, y);
      ship_px += c.r > 0.5f && c.b < 0.2f;
      wall_in_ship += c.b > 0.2f;
    }
  EXPECT_EQ(ship_px, 81) << "the ship 1e7 m away is drawn over its whole centre";
  EXPECT_EQ(wall_in_ship, 0) << "the wall 0.1 % behind shows through the ship: z-fighting";
  const int wall_x = int(kW * 0.5f + f * 2e6f / 1.031e7f) + int(f * 1.2e6f / 1.031e7f);
  EXPECT_GT(rgb(img, wall_x, kH / 2).b, 0.5f) << "the wall around the ship is drawn";
}

// The linear soft edge's factor at the particle's centre: its light with the surface `gap`
// behind it over its light with soft edges off (Ilmonen: clamp(gap / size)).
double soft_factor(Renderer& r, ModelId wall, double distance, float size, double gap) {
  RenderView v = near_far_view();
  v.ambient = glm::vec3(0.0f);  // a black wall: the pixel is the particle's light alone
  v.meshes.push_back({wall, {0, 0, -(distance + gap)}});
  double light[2] = {};
  for (int soft = 0; soft < 2; ++soft) {
    v.particles = {scenes::particle({0, 0, float(-distance)}, size, glm::vec3(0.5f), 1.0f, 1.0f,
                                    soft ? SoftEdge::Linear : SoftEdge::Off)};
    r.render(v, kW, kH);
    const std::vector<float> px = r.read_pixels_float();
    light[soft] = px[(size_t(kH / 2) * kW + kW / 2) * 4 + 1];
  }
  return light[1] / light[0];
}

TEST(DepthExtremes, SoftFadeIsRightTo1PercentOfTheSizeNearAndFar) {
  REQUIRE_CONTEXT();
  auto r = std::make_unique<Renderer>(RendererDesc{.offscreen = true, .float_scene = true});
  if (!r->has_clip_control()) GTEST_SKIP() << "no clip control: reversed-Z float depth is not available";
  r->set_render_settings(test::plain_settings());
  r->set_sprites({scenes::soft_sprite(64)});
  // Each wall a few times the particle's size, as a hull behind smoke would be.
  const ModelId near_wall = r->add_model(scenes::wall_model(0.05f, 0.05f, {0, 0, 0, 1}, glm::vec3(0)));
  const ModelId far_wall = r->add_model(scenes::wall_model(5e6f, 5e6f, {0, 0, 0, 1}, glm::vec3(0)));
  struct Case {
    double distance;
    float size;
    ModelId wall;
  };
  for (const Case c : {Case{0.05, 0.005f, near_wall}, Case{1e7, 5e5f, far_wall}})
    for (double share : {0.25, 0.5, 0.75}) {
      const double got = soft_factor(*r, c.wall, c.distance, c.size, share * c.size);
      EXPECT_NEAR(got, share, 0.01) << "particle " << c.size << " m at " << c.distance << " m, surface "
                                    << share << " of its size behind";
    }
}

// A particle exactly at the camera: the overdraw budget's estimate (which sizes every
// particle's quad on screen, as particle.vert does) stays finite and clamped, and the others
// are left alone; the renderer draws it with finite pixels (Renderer.DegenerateBillboards...).
TEST(DepthExtremes, AParticleAtTheCameraKeepsTheOverdrawEstimateFinite) {
  std::vector<ParticleInstance> ps = {scenes::particle({0, 0, 0}, 1.0f, glm::vec3(1), 1.0f, 1.0f),
                                      scenes::particle({0, 0, -20}, 1.0f, glm::vec3(1), 1.0f, 1.0f)};
  OverdrawFrame f;
  f.tan_half_y = std::tan(0.45f);
  f.near = 0.1f;
  f.size_clamp = 0.5f;
  f.width = 1280;
  f.height = 720;
  std::vector<float> areas;
  OverdrawBudget b;
  const OverdrawStats st = b.apply(ps, areas, f, {.budget_layers = 3.0f});
  ASSERT_EQ(areas.size(), 2u);
  EXPECT_TRUE(std::isfinite(areas[0]) && std::isfinite(st.estimated_layers));
  EXPECT_LE(areas[0], 360.0f * 360.0f + 1.0f) << "at most the size clamp: half the screen height across";
  EXPECT_EQ(st.reduced, 0);
}

}  // namespace
}  // namespace arc
