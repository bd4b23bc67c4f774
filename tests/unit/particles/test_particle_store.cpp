// ParticleStore hands out power-of-two blocks that never overlap, merges them back whole, and
// refuses (counting) when full; a ParticlePool keeps its particles as it moves between blocks,
// falls back to the heap when the store has no room, and gives its block back when it goes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/rng.h"
#include "particles/particle_pool.h"
#include "particles/particle_store.h"

namespace arc {
namespace {

TEST(ParticleStore, RoundsTheBudgetUpToWholeTopBlocks) {
  EXPECT_EQ(ParticleStore(1000).capacity(), 1024u);
  EXPECT_EQ(ParticleStore(1000).top_block(), 1024u);
  const ParticleStore big(200000);
  EXPECT_EQ(big.top_block(), ParticleStore::kTopBlock);
  EXPECT_EQ(big.capacity(), 13u * ParticleStore::kTopBlock);
  EXPECT_EQ(big.bytes(), particle_block_bytes(big.capacity()));
  // Every column lies inside the allocation, after the one before it.
  for (size_t i = 1; i < kParticleColumns; ++i)
    EXPECT_EQ(big.column(i) - big.column(i - 1), std::ptrdiff_t(kParticleColumnBytes[i - 1] * big.capacity() + kParticleColumnStagger));
}

TEST(ParticleStore, TakesTheSmallestPowerOfTwoLowestAddressFirst) {
  ParticleStore s(4096);
  const ParticleBlock a = s.take(300);
  EXPECT_EQ(a.capacity, 512u);
  EXPECT_EQ(a.first, 0u);
  const ParticleBlock b = s.take(1);
  EXPECT_EQ(b.capacity, ParticleStore::kMinBlock);
  EXPECT_EQ(b.first, 512u);
  const ParticleBlock c = s.take(17);
  EXPECT_EQ(c.capacity, 32u);
  EXPECT_EQ(c.first, 544u);
  EXPECT_EQ(s.in_use(), 512u + 16u + 32u);
  s.give_back(a);
  EXPECT_EQ(s.take(400).first, 0u);  // the freed block is the lowest again
}

TEST(ParticleStore, AFullStoreRefusesAndCountsIt) {
  ParticleStore s(1000);
  const ParticleBlock all = s.take(1000);
  EXPECT_EQ(all.capacity, 1024u);
  EXPECT_EQ(s.take(1).capacity, 0u);
  EXPECT_EQ(s.take(5000).capacity, 0u);  // larger than a top block: never from the store
  EXPECT_EQ(s.refusals(), 2u);
  s.give_back(all);
  EXPECT_EQ(s.take(1).capacity, ParticleStore::kMinBlock);
}

// Random takes and give-backs: blocks stay inside the store and disjoint, and once all are
// back, every top block can be taken whole again (the buddies merged).
TEST(ParticleStore, BlocksNeverOverlapAndMergeBackWhole) {
  ParticleStore s(3 * ParticleStore::kTopBlock);
  std::vector<ParticleBlock> held;
  Rng rng{11, 2, 0};
  for (uint64_t step = 0; step < 4000; ++step) {
    if (!held.empty() && rng.range(step * 3, 0.0, 1.0) < 0.45) {
      const size_t i = size_t(rng.range(step * 3 + 1, 0.0, double(held.size()) - 1e-9));
      s.give_back(held[i]);
      held.erase(held.begin() + std::ptrdiff_t(i));
      continue;
    }
    const ParticleBlock b = s.take(uint32_t(rng.range(step * 3 + 2, 1.0, 3000.0)));
    if (b.capacity == 0) continue;
    ASSERT_LE(size_t(b.first) + b.capacity, s.capacity());
    ASSERT_EQ(b.first % b.capacity, 0u) << "a block is aligned to its size";
    for (const ParticleBlock& h : held)
      ASSERT_TRUE(b.first + b.capacity <= h.first || h.first + h.capacity <= b.first) << "step " << step;
    held.push_back(b);
  }
  uint32_t in_use = 0;
  for (const ParticleBlock& h : held) in_use += h.capacity;
  EXPECT_EQ(s.in_use(), in_use);
  for (const ParticleBlock& h : held) s.give_back(h);
  EXPECT_EQ(s.in_use(), 0u);
  for (int t = 0; t < 3; ++t) EXPECT_EQ(s.take(ParticleStore::kTopBlock).capacity, ParticleStore::kTopBlock) << "top block " << t;
}

void fill(ParticlePool& p, size_t from, size_t to) {
  for (size_t i = from; i < to; ++i) {
    p.px[i] = float(i) * 0.5f, p.spin[i] = -float(i);
    p.uid[i] = uint32_t(i), p.sprite[i] = uint16_t(i % 7), p.flags[i] = uint8_t(i % 2);
  }
}

void expect_filled(const ParticlePool& p, size_t n) {
  ASSERT_EQ(p.count(), n);
  for (size_t i = 0; i < n; ++i) {
    ASSERT_EQ(p.px[i], float(i) * 0.5f) << i;
    ASSERT_EQ(p.spin[i], -float(i)) << i;
    ASSERT_EQ(p.uid[i], uint32_t(i)) << i;
    ASSERT_EQ(p.sprite[i], uint16_t(i % 7)) << i;
    ASSERT_EQ(p.flags[i], uint8_t(i % 2)) << i;
  }
}

TEST(ParticlePoolStorage, GrowsThroughTheStoreKeepingItsParticlesAndGivesTheBlockBack) {
  ParticleStore s(8192);
  {
    ParticlePool p(&s);
    for (size_t n : {10, 40, 300, 2000}) {
      const size_t old = p.count();
      p.resize(n);
      EXPECT_EQ(p.r[n - 1], 0.0f) << "new particles are zeroed";
      fill(p, old, n);
      expect_filled(p, n);
      EXPECT_TRUE(p.in_store());
      EXPECT_EQ(s.in_use(), p.capacity());
    }
    p.resize(5);  // shrinking keeps the block
    EXPECT_EQ(s.in_use(), p.capacity());
    ParticlePool moved = std::move(p);
    EXPECT_EQ(p.count(), 0u);
    EXPECT_EQ(p.capacity(), 0u);
    expect_filled(moved, 5);
    EXPECT_EQ(s.in_use(), moved.capacity());
  }
  EXPECT_EQ(s.in_use(), 0u);
}

TEST(ParticlePoolStorage, TakesTheHeapWhenTheStoreIsFull) {
  ParticleStore s(1000);
  ParticlePool a(&s), b(&s);
  a.resize(1000);
  EXPECT_TRUE(a.in_store());
  b.resize(100);
  fill(b, 0, 100);
  EXPECT_FALSE(b.in_store());
  expect_filled(b, 100);
  a = ParticlePool(&s);  // the block goes back; b's next growth finds room in the store
  b.resize(600);
  fill(b, 100, 600);
  EXPECT_TRUE(b.in_store());
  expect_filled(b, 600);
}

TEST(ParticlePoolStorage, ACopyHoldsTheSameParticlesOnTheHeapAndAssignmentKeepsTheSource) {
  ParticleStore s(4096);
  ParticlePool p(&s);
  p.resize(700);
  fill(p, 0, 700);
  const ParticlePool copy = p;
  EXPECT_FALSE(copy.in_store());
  expect_filled(copy, 700);
  ParticlePool scratch(&s);
  scratch = copy;
  EXPECT_TRUE(scratch.in_store());
  expect_filled(scratch, 700);
  EXPECT_EQ(s.in_use(), p.capacity() + scratch.capacity());
}

}  // namespace
}  // namespace arc
