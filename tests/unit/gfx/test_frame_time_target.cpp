// The frame-time target's controller on synthetic frame-time series (gfx/frame_time_target.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "gfx/frame_time_target.h"

namespace arc {
namespace {

// A frame's time as a level sets it: a fixed part and a part the level scales (particle fill),
// with ±jitter of a keyed hash, as a shared machine gives.
double plant(double level, double fixed_ms, double scaled_ms, double jitter, uint64_t frame) {
  uint64_t h = frame * 0x9E3779B97F4A7C15ull;
  h ^= h >> 31;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 29;
  const double u = double(h % 10000) / 10000.0 * 2.0 - 1.0;
  return (fixed_ms + scaled_ms * level) * (1.0 + jitter * u);
}

struct Series {
  std::vector<double> levels, ms;
};

Series run(FrameTimeTarget& t, int frames, double fixed_ms, double scaled_ms, double jitter, uint64_t from = 0) {
  Series r;
  for (int i = 0; i < frames; ++i) {
    const double ms = plant(t.level(), fixed_ms, scaled_ms, jitter, from + uint64_t(i));
    t.observe(ms, t.level() < 1.0);
    r.levels.push_back(t.level());
    r.ms.push_back(ms);
  }
  return r;
}

// Times the level turns from falling to rising or back.
int reversals(const std::vector<double>& v, size_t from) {
  int n = 0, dir = 0;
  for (size_t i = from + 1; i < v.size(); ++i) {
    const int d = v[i] > v[i - 1] * (1 + 1e-9) ? 1 : v[i] < v[i - 1] * (1 - 1e-9) ? -1 : 0;
    if (d != 0 && dir != 0 && d != dir) ++n;
    if (d != 0) dir = d;
  }
  return n;
}

TEST(FrameTimeTarget, OffKeepsLevelOne) {
  FrameTimeTarget t;
  for (int i = 0; i < 100; ++i) t.observe(100.0, true);
  EXPECT_EQ(t.level(), 1.0);
  t.set_target(16.7);
  for (int i = 0; i < 100; ++i) t.observe(10.0, false);
  EXPECT_EQ(t.level(), 1.0) << "frames under the target leave the settings as they are";
}

TEST(FrameTimeTarget, ConvergesAndHolds) {
  // 45 ms at level 1, 16.7 ms reached near level 0.3: settles within two seconds at 60 Hz and
  // then holds without cycling, its frames near the target.
  FrameTimeTarget t;
  t.set_target(16.7);
  Series r = run(t, 1200, 6.0, 39.0, 0.05);
  const double settled = r.levels[120];
  double lo = 1, hi = 0, worst = 0;
  for (size_t i = 120; i < r.levels.size(); ++i) {
    lo = std::min(lo, r.levels[i]);
    hi = std::max(hi, r.levels[i]);
  }
  std::vector<double> late(r.ms.begin() + 120, r.ms.end());
  std::sort(late.begin(), late.end());
  worst = late[size_t(0.99 * double(late.size() - 1))];
  EXPECT_LT(settled, 0.5);
  EXPECT_GT(settled, 0.2);
  EXPECT_LT(hi / lo, 1.15) << "the level stays within a narrow band once settled";
  EXPECT_LE(reversals(r.levels, 120), 6) << "no oscillation around the target";
  EXPECT_LT(worst, 16.7 * 1.25) << "p99 of the settled frames";
}

TEST(FrameTimeTarget, RecoversWhenTheLoadGoes) {
  FrameTimeTarget t;
  t.set_target(16.7);
  run(t, 300, 6.0, 39.0, 0.05);
  EXPECT_LT(t.level(), 0.5);
  Series r = run(t, 600, 4.0, 6.0, 0.05, 300);  // the explosion is over: 10 ms at level 1
  EXPECT_EQ(t.level(), 1.0);
  EXPECT_EQ(reversals(r.levels, 0), 0) << "back up without a dip";
  for (size_t i = 1; i < r.levels.size(); ++i) EXPECT_LE(r.levels[i] / r.levels[i - 1], 1.0 + FrameTimeTarget::kMaxRise + 1e-9);
}

TEST(FrameTimeTarget, SingleHitchMovesLittle) {
  FrameTimeTarget t;
  t.set_target(16.7);
  run(t, 200, 4.0, 8.0, 0.02);
  t.observe(500.0, false);  // a window drag or a compile
  EXPECT_GT(t.level(), 0.9);
}

TEST(FrameTimeTarget, StepsAreBounded) {
  FrameTimeTarget t;
  t.set_target(16.7);
  Series r = run(t, 400, 30.0, 60.0, 0.3);
  for (size_t i = 1; i < r.levels.size(); ++i) {
    EXPECT_GE(r.levels[i] / r.levels[i - 1], 1.0 - FrameTimeTarget::kMaxFall - 1e-9);
    EXPECT_LE(r.levels[i] / r.levels[i - 1], 1.0 + FrameTimeTarget::kMaxRise + 1e-9);
  }
  EXPECT_EQ(t.level(), FrameTimeTarget::kMinLevel) << "a load no level can meet ends at the floor";
}

TEST(FrameTimeTarget, VsyncCappedFramesRiseOnlyWhenUnused) {
  FrameTimeTarget t;
  t.set_target(16.7);
  run(t, 200, 6.0, 39.0, 0.0);
  const double low = t.level();
  for (int i = 0; i < 300; ++i) t.observe(16.6, true);  // held at the display's rate, level in use
  EXPECT_NEAR(t.level(), low, 1e-12);
  for (int i = 0; i < 300; ++i) t.observe(16.6, false);  // level changes nothing seen
  EXPECT_EQ(t.level(), 1.0);
}

}  // namespace
}  // namespace arc
