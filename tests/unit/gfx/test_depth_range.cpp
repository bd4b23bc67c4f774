// The standard-depth fallback (render.depth_mode=standard, used where clip control is missing)
// keeps objects visible up to the far plane. Its float depth buffer rounds 1 − near/d to exactly
// 1, the clear value, beyond about near × 1.7e7 (8e6 m at the game's near plane of 0.5 m), so a
// GL_LESS test dropped a ship at 9e6 m inside a 1e7 m far plane; reversed-Z never rounds so.
#include <gtest/gtest.h>

#include "gfx_test_util.h"

namespace arc {
namespace {

TEST(DepthRange, StandardDepthKeepsObjectsVisibleUpToTheFarPlane) {
  REQUIRE_CONTEXT();
  RendererDesc d;
  d.offscreen = true;
  Renderer r(d);
  const glm::vec3 green(0.1f, 0.9f, 0.2f);
  const ModelId wall = r.add_model(scenes::wall_model(1, 1, {0, 0, 0, 1}, green));
  for (bool reversed : {false, true})
    for (bool infinite : {false, true}) {
      RenderSettings s = test::plain_settings();
      s.reversed_z = reversed;
      s.infinite_far = infinite;
      r.set_render_settings(s);
      for (double distance : {1.0e3, 2.0e6, 5.0e6, 9.0e6, 9.9e6}) {
        RenderView v = test::dark_view();
        v.camera.near_plane = 0.5;  // the game's camera
        v.camera.far_plane = 1.0e7;
        v.meshes.push_back({wall, {0, 0, -distance}});
        v.meshes.back().scale = distance * 0.5;  // half the view wide at any distance
        r.render(v, 64, 64);
        const Image img = r.read_pixels();
        EXPECT_NEAR(test::channel(img, 32, 32, 1), green.g, 0.02f)
            << "wall at " << distance << " m, " << (reversed ? "reversed" : "standard") << " depth, "
            << (infinite ? "infinite" : "finite") << " far plane";
      }
    }
}

}  // namespace
}  // namespace arc
