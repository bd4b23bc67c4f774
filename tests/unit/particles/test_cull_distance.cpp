// particles.cull_distance: a cluster beyond it from the camera is neither animated nor drawn,
// costs no per-particle evaluation while it stays there, and when the camera comes near it is
// caught up to exactly the state of a cluster that was evaluated every tick.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "particles/effect_library.h"
#include "particles/particle_world.h"

namespace arc {
namespace {

const EffectLibrary& library() {
  static EffectLibrary lib = [] {
    EffectLibrary l;
    l.load_text(R"({ "clusters": [ { "sprite": "smoke",
      "animation": { "type": "linear", "drag": 0.5, "acceleration": [0, -1, 0] },
      "emitter": { "shape": "sphere", "radius": 1, "rate": 40, "burst": 30 },
      "particles": { "speed": [1, 4], "lifetime": [1, 3], "size": [1, 2] } } ] })",
                "smoke.json");
    return l;
  }();
  return lib;
}

// On the +Z axis looking at the origin (-Z), `distance` away: the cluster is in the frustum
// from every distance, so only the cull distance can leave it out.
ParticleCamera camera_at(double distance) {
  ParticleCamera c;
  c.position = {0, 0, distance};
  return c;
}

constexpr double kCull = 500.0;

TEST(CullDistance, AFarClusterCostsNoParticleWorkUntilSeenThenCatchesUpExactly) {
  ParticleWorld near_all_along(ParticleConfig{.seed = 7, .cull_distance = kCull}, &library());
  ParticleWorld far_then_near(ParticleConfig{.seed = 7, .cull_distance = kCull}, &library());
  near_all_along.spawn("smoke", {});
  far_then_near.spawn("smoke", {});
  for (uint64_t t = 1; t <= 60; ++t) {
    near_all_along.step(t, camera_at(100));
    far_then_near.step(t, camera_at(t <= 40 ? 2000 : 100));
    const ParticleStats far = far_then_near.stats();
    ASSERT_GT(far.live_particles, 0u) << "tick " << t;
    EXPECT_EQ(far.live_particles, near_all_along.stats().live_particles) << "tick " << t;
    if (t <= 40) {
      EXPECT_EQ(far.animated_particles, 0u) << "tick " << t << ": a cluster beyond the cull distance was evaluated";
      EXPECT_EQ(far.skipped_clusters, 1u) << "tick " << t;
      EXPECT_EQ(far.skipped_particles, far.live_particles) << "tick " << t;
      std::vector<ParticleInstance> none;
      far_then_near.collect(camera_at(2000), none);
      EXPECT_TRUE(none.empty()) << "tick " << t << ": a cluster beyond the cull distance was drawn";
    } else {
      EXPECT_EQ(far.animated_particles, far.live_particles) << "tick " << t;
      EXPECT_EQ(far.caught_up_clusters, t == 41 ? 1u : 0u) << "tick " << t;
    }
  }
  std::vector<ParticleInstance> a, b;
  near_all_along.collect(camera_at(100), a);
  far_then_near.collect(camera_at(100), b);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 0u);
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(ParticleInstance)), 0);
}

// The same camera 2000 away sees the cluster once the cull distance is beyond it.
TEST(CullDistance, AFartherCullDistanceAnimatesTheSameCluster) {
  ParticleWorld w(ParticleConfig{.seed = 7, .cull_distance = 5000}, &library());
  w.spawn("smoke", {});
  for (uint64_t t = 1; t <= 10; ++t) w.step(t, camera_at(2000));
  EXPECT_EQ(w.stats().skipped_clusters, 0u);
  EXPECT_EQ(w.stats().animated_particles, w.stats().live_particles);
  std::vector<ParticleInstance> seen;
  w.collect(camera_at(2000), seen);
  EXPECT_EQ(seen.size(), size_t(w.stats().live_particles));
}

}  // namespace
}  // namespace arc
