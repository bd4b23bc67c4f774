// The particle engine at its extremes (tests/README.md, "Extremes"): tick rates 10 and 480
// with drag k·dt from 0 to 100, the particle budget at its minimum and maximum under a burst of
// a million, and lightning channels of one segment and of the most segments a file may ask for.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "particles/animation.h"
#include "particles/effect_library.h"
#include "particles/lightning_channel.h"
#include "particles/particle_world.h"
#include "particles/world_state.h"

namespace arc {
namespace {

// x(t) with drag k and acceleration a, in long double: x0 + (a/k)·t + (v0 − a/k)·(1 − e^(−kt))/k.
long double closed_x(long double x0, long double v0, long double a, long double k, long double t) {
  if (k == 0) return x0 + v0 * t + a * t * t / 2;
  return x0 + (a / k) * t + (v0 - a / k) * (-std::expm1(-k * t)) / k;
}

// At 10 and 480 ticks per second, for k·dt from 0 to 100, the table the particles move by and
// the positions they get are the closed form to 1e-6 (relative, and 1e-6 m near zero), never NaN.
TEST(Extremes, TickRates10And480KeepTheClosedFormsExact) {
  for (int rate : {10, 480}) {
    const double h = 1.0 / rate;
    for (double kdt : {0.0, 1e-9, 1e-4, 0.5, 1.0, 2.5, 10.0, 100.0}) {
      const double k = kdt / h;
      const double life = 2.0;
      auto table = MotionTable::build(k, h, life);
      ParticlePool p;
      p.resize(1);
      p.p0x[0] = 3.0f, p.vx[0] = 20.0f, p.birth[0] = 0;
      for (uint32_t n : {0u, 1u, 2u, 7u, uint32_t(rate), table->last()}) {
        animate_linear(p, n, *table, glm::vec3(-9.0f, 0.0f, 0.0f));
        const long double want = closed_x(3.0L, 20.0L, -9.0L, k, n * (long double)h);
        ASSERT_TRUE(std::isfinite(p.px[0])) << "rate " << rate << " k*dt " << kdt << " tick " << n;
        EXPECT_NEAR(p.px[0], double(want), 1e-6 * (1.0 + std::fabs(double(want))))
            << "rate " << rate << " k*dt " << kdt << " tick " << n;
        const double g = drag_g(k, n * h), f = drag_f(k, n * h);
        EXPECT_NEAR(3.0 + 20.0 * g - 9.0 * f, double(want), 1e-9 * (1.0 + std::fabs(double(want))));
      }
    }
  }
}

const EffectLibrary& burst_library() {
  static EffectLibrary lib = [] {
    EffectLibrary l;
    l.load_text(R"({ "clusters": [ { "sprite": "spark", "animation": { "type": "linear" },
      "emitter": { "burst": 1000000 }, "particles": { "lifetime": [5, 5], "speed": [1, 2], "size": [1, 1] } } ] })",
                "million.json");
    return l;
  }();
  return lib;
}

// Budget 1000 (the least --set allows) and 4,000,000 (the most): a burst of a million asked
// for in one tick leaves at most the budget alive, counts every particle it refused, no pool
// holds room for more particles than the budget, and the store is the budget rounded up to
// whole top blocks (particle_store.h).
TEST(Extremes, BudgetHoldsAtItsMinimumAndMaximumUnderAMillionParticleBurst) {
  for (uint32_t budget : {1000u, 4000000u}) {
    ParticleWorld w(ParticleConfig{.seed = 2, .budget = budget}, &burst_library());
    w.spawn("million", SpawnParams{.priority = 1});
    w.step(1, ParticleCamera{});
    const ParticleStats st = w.stats();
    EXPECT_LE(st.live_particles, budget) << "budget " << budget;
    EXPECT_EQ(st.live_particles + st.refused_particles, 1000000u) << "budget " << budget;
    EXPECT_EQ(st.live_particles, std::min(budget, 1000000u)) << "budget " << budget;
    size_t heap = 0;
    for (const Cluster& c : ParticleWorldAccess::state(w).slots)
      if (!c.pool.in_store()) heap += c.pool.capacity();
    EXPECT_LE(heap, size_t(budget)) << "budget " << budget << ": room for more particles than it admits";
    const ParticleStore& store = *ParticleWorldAccess::state(w).store;
    EXPECT_GE(store.capacity(), budget);
    EXPECT_LT(store.capacity(), budget + store.top_block()) << "budget " << budget;
  }
}

LightningDef channel(double seed, double max) {
  LightningDef d;
  d.seed_length = seed;
  d.max_length = max;
  d.max_angle = 20.0 * M_PI / 180.0;
  d.length_jitter = 0.0;
  return d;
}

// max_length = seed_length: the seed segment alone. The most a file may ask for (4096
// segments, effect_library.cpp): every point finite, the total within max_length.
TEST(Extremes, LightningChannelsOfOneSegmentAndOfTheMost) {
  LightningChannel one;
  build_lightning(channel(5.0, 5.0), 1.0, Rng{1, 2, 3}, one);
  ASSERT_EQ(one.points.size(), 2u);
  EXPECT_NEAR(one.length(), 5.0, 1e-12);
  LightningChannel most;
  build_lightning(channel(1.0, 4096.0), 1.0, Rng{1, 2, 3}, most);
  EXPECT_EQ(most.points.size(), 4097u);
  EXPECT_LE(most.length(), 4096.0 + 1e-6);
  for (const glm::dvec3& q : most.points) ASSERT_TRUE(std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z));
  EffectLibrary lib;
  EXPECT_THROW(lib.load_text(R"({ "clusters": [ { "sprite": "spark",
      "animation": { "type": "lightning", "seed_length": 1, "max_length": 4097, "length_jitter": 0 } } ] })",
                             "too_many.json"),
               InputError);
}

}  // namespace
}  // namespace arc
