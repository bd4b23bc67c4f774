#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/hash.h"
#include "core/rng.h"

TEST(KeyedRng, ValueDependsOnlyOnKey) {
  arc::Rng a{7, 3, 100}, b{7, 3, 100};
  // Drawing in a different order gives the same values.
  double a5 = a.uniform(5), a1 = a.uniform(1);
  double b1 = b.uniform(1), b5 = b.uniform(5);
  EXPECT_EQ(a5, b5);
  EXPECT_EQ(a1, b1);
}

TEST(KeyedRng, EveryKeyWordChangesTheValue) {
  std::set<uint64_t> seen;
  seen.insert(arc::key_hash(1, 2, 3, 4));
  seen.insert(arc::key_hash(2, 2, 3, 4));
  seen.insert(arc::key_hash(1, 3, 3, 4));
  seen.insert(arc::key_hash(1, 2, 4, 4));
  seen.insert(arc::key_hash(1, 2, 3, 5));
  seen.insert(arc::key_hash(4, 3, 2, 1));
  EXPECT_EQ(seen.size(), 6u);
}

TEST(KeyedRng, UniformIsInRangeWithPlausibleMean) {
  arc::Rng r{42, 0, 0};
  double sum = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    double u = r.uniform(i);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
  }
  EXPECT_NEAR(sum / n, 0.5, 0.01);
}

TEST(KeyedRng, UnitVectorsHaveUnitLengthAndZeroMean) {
  arc::Rng r{9, 1, 2};
  glm::dvec3 mean{0.0};
  for (int i = 0; i < 20000; ++i) {
    glm::dvec3 v = r.unit_vector(i);
    ASSERT_NEAR(std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z), 1.0, 1e-12);
    mean += v;
  }
  mean /= 20000.0;
  EXPECT_NEAR(mean.x, 0.0, 0.02);
  EXPECT_NEAR(mean.y, 0.0, 0.02);
  EXPECT_NEAR(mean.z, 0.0, 0.02);
}

TEST(StateHasher, OrderAndSignOfZeroMatter) {
  arc::StateHasher a, b, c, d;
  a.add_f64(1.0); a.add_f64(2.0);
  b.add_f64(2.0); b.add_f64(1.0);
  c.add_f64(0.0);
  d.add_f64(-0.0);
  EXPECT_NE(a.value(), b.value());
  EXPECT_NE(c.value(), d.value());
  arc::StateHasher e;
  e.add_f64(1.0); e.add_f64(2.0);
  EXPECT_EQ(a.value(), e.value());
}
