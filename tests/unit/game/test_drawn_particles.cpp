// Particles attached to a ship are drawn at the same interpolated moment as its mesh: for any
// alpha between ticks, the offset of the player's exhaust cluster from the player's drawn mesh
// is the offset at the tick. Particles collected at the tick under an interpolated mesh would
// sit up to one tick's travel ahead of the hull.
#include <gtest/gtest.h>

#include "game/render/render_view_builder.h"
#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

// The centroid of one cluster's particles, in world space.
glm::dvec3 cluster_centre(const RenderView& v, uint32_t cluster) {
  glm::dvec3 sum(0.0);
  int n = 0;
  for (const ParticleInstance& p : v.particles)
    if (p.cluster == cluster) sum += glm::dvec3(p.pos[0], p.pos[1], p.pos[2]), ++n;
  EXPECT_GT(n, 0);
  return v.camera.position + sum / double(std::max(n, 1));
}

TEST(DrawnParticles, AttachedClusterStaysOnItsInterpolatedShip) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  InputFrame full;
  full.throttle = 127;
  full.buttons = kAfterburner;
  for (int i = 0; i < 90; ++i) g.step(full);
  const World& w = g.world();
  const Ship& me = w.ship(w.player);
  ASSERT_FALSE(me.exhaust_fx.empty());
  ASSERT_FALSE(me.exhaust_fx[0].clusters.empty());
  const uint32_t exhaust = me.exhaust_fx[0].clusters[0].index;
  const double travel = glm::length(me.position - me.prev_position);
  ASSERT_GT(travel, 2.0) << "the ship must move several metres a tick for the test to mean anything";

  CameraSettings fixed;
  fixed.mode = CameraMode::Fixed;  // a camera that does not follow the ship
  glm::dvec3 tick_offset(0.0);
  for (double alpha : {1.0, 0.0, 0.25, 0.5, 0.75}) {
    RenderView v;
    build_render_view(w, {}, alpha, fixed, HudState{}, 1280, 720, v);
    const glm::dvec3 hull = v.meshes.at(w.player.index()).position;
    const glm::dvec3 offset = cluster_centre(v, exhaust) - hull;
    if (alpha == 1.0) tick_offset = offset;
    EXPECT_LT(glm::length(offset - tick_offset), 0.01 * travel) << "alpha " << alpha;
  }
}

}  // namespace
}  // namespace arc
