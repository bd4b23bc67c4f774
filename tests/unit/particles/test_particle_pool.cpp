// ParticlePool::retire() keeps what it knows of the next death between calls: the same particles
// die on the same ticks as by a pass over the whole pool, however births and deaths interleave,
// and changes() moves exactly when the set of particles does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/rng.h"
#include "particles/particle_pool.h"

namespace arc {
namespace {

// The plain rule: every particle whose death tick has come goes, the rest keep their order.
std::vector<uint32_t> retire_by_hand(std::vector<std::pair<uint32_t, uint32_t>>& uid_death, uint32_t now) {
  std::vector<uint32_t> gone;
  std::vector<std::pair<uint32_t, uint32_t>> kept;
  for (auto& p : uid_death) (p.second <= now ? gone.push_back(p.first) : kept.push_back(p));
  uid_death = kept;
  return gone;
}

void append(ParticlePool& pool, uint32_t uid, uint32_t death) {
  const size_t k = pool.count();
  pool.resize(k + 1);
  pool.uid[k] = uid;
  pool.death[k] = death;
}

TEST(ParticlePool, RetireMatchesAPassOverEveryParticleAsBirthsAndDeathsInterleave) {
  ParticlePool pool;
  std::vector<std::pair<uint32_t, uint32_t>> model;
  Rng rng{7, 3, 0};
  uint32_t next_uid = 0;
  for (uint32_t now = 0; now < 400; ++now) {
    const size_t died = pool.retire(now);
    const std::vector<uint32_t> expected = retire_by_hand(model, now);
    ASSERT_EQ(died, expected.size()) << "tick " << now;
    ASSERT_EQ(pool.count(), model.size());
    for (size_t i = 0; i < model.size(); ++i) ASSERT_EQ(pool.uid[i], model[i].first) << "tick " << now;
    // Bursts and quiet spells, short and long lives (some shorter than older particles').
    const int births = now % 50 < 10 ? int(rng.range(now * 4, 0, 6)) : 0;
    for (int b = 0; b < births; ++b) {
      const uint32_t life = 1 + uint32_t(rng.range(now * 4 + 1 + uint64_t(b) * 1000, 0, 90));
      append(pool, next_uid, now + life);
      model.push_back({next_uid++, now + life});
    }
  }
}

TEST(ParticlePool, ChangesMoveWithTheSetOfParticlesOnly) {
  ParticlePool pool;
  const uint64_t c0 = pool.changes();
  append(pool, 0, 10);
  append(pool, 1, 20);
  const uint64_t c1 = pool.changes();
  EXPECT_GT(c1, c0);
  EXPECT_EQ(pool.retire(5), 0u);
  EXPECT_EQ(pool.changes(), c1);  // nobody died: the set is the same
  EXPECT_EQ(pool.retire(10), 1u);
  EXPECT_GT(pool.changes(), c1);
  EXPECT_EQ(pool.retire(11), 0u);  // knows now that the next death is at 20
  const uint64_t c2 = pool.changes();
  pool.touch();  // arrays written from outside (a snapshot read)
  EXPECT_GT(pool.changes(), c2);
  pool.death[0] = 12;  // so touch() must also forget the next death it knew (20)
  EXPECT_EQ(pool.retire(12), 1u);
}

}  // namespace
}  // namespace arc
