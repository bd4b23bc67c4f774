// The effect gallery left running: repeated level effects must end as well as start (a
// lightning channel spawned as a free level effect needs an owner and an end, or the gallery
// would gain a bolt every 2 s for good). Ten minutes of game time, no rendering.
#include <gtest/gtest.h>

#include <algorithm>

#include "game/sim/game.h"
#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

TEST(GallerySoak, TenMinutesKeepTheLiveClustersAndParticlesBounded) {
  Game g = Game::load_level(test::repo("levels/gallery.json"), test::options());
  const uint64_t minute = uint64_t(60.0 / g.tick_seconds() + 0.5);
  ParticleStats after_first_minute, most;
  for (uint64_t t = 1; t <= 10 * minute; ++t) {
    g.step(InputFrame{});
    const ParticleStats s = g.world().particles->stats();
    if (t == minute) after_first_minute = s;
    if (t < minute) continue;
    most.live_clusters = std::max(most.live_clusters, s.live_clusters);
    most.live_particles = std::max(most.live_particles, s.live_particles);
  }
  ASSERT_GT(after_first_minute.live_clusters, 0u);
  // Nothing accumulates: the busiest moment of minutes 1..10 stays within twice the count after
  // the first minute (1.4 times with the bolts ending; 4.6 times when they piled up).
  EXPECT_LE(most.live_clusters, after_first_minute.live_clusters * 2)
      << "after one minute " << after_first_minute.live_clusters;
  EXPECT_LE(most.live_particles, after_first_minute.live_particles * 2)
      << "after one minute " << after_first_minute.live_particles;
  EXPECT_EQ(g.world().particles->stats().refused_particles, 0u);
}

}  // namespace
}  // namespace arc
