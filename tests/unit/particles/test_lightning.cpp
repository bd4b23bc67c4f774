// Lightning channel statistics (Hadwiger §5.2).
#include <gtest/gtest.h>

#include <cmath>

#include "particles/lightning_channel.h"

namespace arc {
namespace {

LightningDef beam() {
  LightningDef d;
  d.seed_length = 8.0;
  d.max_length = 400.0;
  d.max_angle = 25.0 * M_PI / 180.0;
  d.length_jitter = 0.4;
  d.sizzle_ticks = 3;
  return d;
}

TEST(Lightning, EverySegmentWithinAngleAndLengthBoundsAndTotalWithinMax) {
  const LightningDef d = beam();
  const glm::dvec3 dir = glm::normalize(glm::dvec3(0.3, -0.2, -1.0));
  for (uint64_t epoch = 0; epoch < 200; ++epoch) {
    LightningChannel ch;
    ch.origin = {1, 2, 3};
    ch.direction = dir;
    build_lightning(d, 1.0, Rng{42, 7, epoch}, ch);
    ASSERT_GE(ch.points.size(), 3u);
    double total = 0.0;
    for (size_t i = 1; i < ch.points.size(); ++i) {
      const glm::dvec3 seg = ch.points[i] - ch.points[i - 1];
      const double len = glm::length(seg);
      total += len;
      if (i == 1) {
        EXPECT_NEAR(glm::length(seg - dir * d.seed_length), 0.0, 1e-12);
        continue;
      }
      EXPECT_GE(len, d.seed_length * (1 - d.length_jitter) - 1e-9);
      EXPECT_LE(len, d.seed_length * (1 + d.length_jitter) + 1e-9);
      const double angle = std::acos(std::clamp(glm::dot(seg / len, dir), -1.0, 1.0));
      EXPECT_LE(angle, d.max_angle + 1e-9) << "epoch " << epoch << " segment " << i;
    }
    EXPECT_LE(total, d.max_length + 1e-9);
    EXPECT_GT(total, d.max_length - d.seed_length * (1 + d.length_jitter));
    EXPECT_NEAR(ch.length(), total, 1e-9);
  }
}

TEST(Lightning, DeviationsUseTheWholeAllowedAngle) {
  const LightningDef d = beam();
  double largest = 0.0;
  for (uint64_t epoch = 0; epoch < 20; ++epoch) {
    LightningChannel ch;
    build_lightning(d, 1.0, Rng{1, 1, epoch}, ch);
    for (size_t i = 2; i < ch.points.size(); ++i) {
      const glm::dvec3 s = glm::normalize(ch.points[i] - ch.points[i - 1]);
      largest = std::max(largest, std::acos(std::clamp(-s.z, -1.0, 1.0)));
    }
  }
  EXPECT_GT(largest, d.max_angle * 0.9);
}

TEST(Lightning, SeedUnchangedAcrossSizzlesSameSeedSameChannel) {
  const LightningDef d = beam();
  LightningChannel a, b, c;
  build_lightning(d, 1.0, Rng{5, 3, 30}, a);
  build_lightning(d, 1.0, Rng{5, 3, 30}, b);
  build_lightning(d, 1.0, Rng{5, 3, 33}, c);
  EXPECT_EQ(a.points, b.points);
  ASSERT_GE(c.points.size(), 3u);
  EXPECT_EQ(a.points[0], c.points[0]);
  EXPECT_EQ(a.points[1], c.points[1]);
  EXPECT_NE(a.points[2], c.points[2]);
}

TEST(Lightning, EpochChangesEveryNTicks) {
  EXPECT_EQ(lightning_epoch(10, 10, 3), 10u);
  EXPECT_EQ(lightning_epoch(12, 10, 3), 10u);
  EXPECT_EQ(lightning_epoch(13, 10, 3), 13u);
  EXPECT_EQ(lightning_epoch(17, 10, 1), 17u);
}

TEST(Lightning, PointAtWalksThePolylineAndClamps) {
  LightningChannel ch;
  ch.points = {{0, 0, 0}, {0, 0, -10}, {10, 0, -10}};
  EXPECT_EQ(ch.point_at(5), glm::dvec3(0, 0, -5));
  EXPECT_EQ(ch.point_at(15), glm::dvec3(5, 0, -10));
  EXPECT_EQ(ch.point_at(100), glm::dvec3(10, 0, -10));
  EXPECT_EQ(ch.point_at(-3), glm::dvec3(0, 0, 0));
}

}  // namespace
}  // namespace arc
