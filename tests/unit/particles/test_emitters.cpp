// Emitter shapes: every sample lies where its shape says; mesh sampling is area-weighted.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/emitter.h"

namespace arc {
namespace {

constexpr int kSamples = 4000;

TEST(Emitter, SphereVolumeAndSurface) {
  EmitterDef e;
  e.shape = EmitterShape::Sphere;
  e.radius = 2.0;
  e.offset = {1, 1, 1};
  int inner = 0;
  for (int i = 0; i < kSamples; ++i) {
    const EmitSample s = sample_emitter(e, Rng{1, 2, 3}, uint64_t(i) * 16);
    const double r = glm::length(s.position - e.offset);
    EXPECT_LE(r, 2.0 + 1e-12);
    inner += r < 2.0 * std::cbrt(0.5);
    EXPECT_NEAR(glm::length(s.direction), 1.0, 1e-12);
  }
  EXPECT_NEAR(inner / double(kSamples), 0.5, 0.05);  // uniform in volume: half inside r·∛½
  e.shape = EmitterShape::SphereSurface;
  for (int i = 0; i < 100; ++i)
    EXPECT_NEAR(glm::length(sample_emitter(e, Rng{1, 2, 3}, uint64_t(i) * 16).position - e.offset), 2.0, 1e-12);
}

TEST(Emitter, ConeDirectionsWithinAngleAroundAxis) {
  EmitterDef e;
  e.shape = EmitterShape::Cone;
  e.angle = 0.3;
  for (int i = 0; i < kSamples; ++i) {
    const EmitSample s = sample_emitter(e, Rng{4, 5, 6}, uint64_t(i) * 16);
    EXPECT_LE(std::acos(std::clamp(-s.direction.z, -1.0, 1.0)), 0.3 + 1e-9);
  }
  e.axis_rotation = glm::dquat(0, 1, 0, 0);  // −Z turned to +Z
  for (int i = 0; i < 100; ++i) EXPECT_GT(sample_emitter(e, Rng{4, 5, 6}, uint64_t(i) * 16).direction.z, 0.9);
}

TEST(Emitter, BoxAndLineWithinExtents) {
  EmitterDef e;
  e.shape = EmitterShape::Box;
  e.half_extents = {1, 2, 3};
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec3 p = sample_emitter(e, Rng{7, 8, 9}, uint64_t(i) * 16).position;
    EXPECT_LE(std::fabs(p.x), 1.0);
    EXPECT_LE(std::fabs(p.y), 2.0);
    EXPECT_LE(std::fabs(p.z), 3.0);
  }
  e.shape = EmitterShape::Line;
  e.length = 10;
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec3 p = sample_emitter(e, Rng{7, 8, 9}, uint64_t(i) * 16).position;
    EXPECT_EQ(p.x, 0.0);
    EXPECT_EQ(p.y, 0.0);
    EXPECT_LE(std::fabs(p.z), 5.0);
  }
}

TEST(Emitter, MeshSurfaceIsAreaWeightedAndOnTheTriangles) {
  EmitterDef e;
  e.shape = EmitterShape::Mesh;
  // Triangle A (area 0.5) in z = 0, triangle B (area 1.5) in z = 5.
  e.triangles = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 5}, {3, 0, 5}, {0, 1, 5}};
  e.area_prefix = {0.5, 2.0};
  int on_b = 0;
  for (int i = 0; i < kSamples; ++i) {
    const EmitSample s = sample_emitter(e, Rng{3, 3, 3}, uint64_t(i) * 16);
    const glm::dvec3 p = s.position;
    ASSERT_TRUE(std::fabs(p.z) < 1e-9 || std::fabs(p.z - 5.0) < 1e-9) << p.z;
    const bool on_big = p.z > 2.5;
    const double xmax = on_big ? 3.0 : 1.0;
    EXPECT_GE(p.x, -1e-12);
    EXPECT_GE(p.y, -1e-12);
    EXPECT_LE(p.x / xmax + p.y, 1.0 + 1e-9);
    EXPECT_NEAR(s.direction.z, 1.0, 1e-12);  // counter-clockwise winding: normal +Z
    on_b += on_big;
  }
  EXPECT_NEAR(on_b / double(kSamples), 0.75, 0.03);
}

}  // namespace
}  // namespace arc
