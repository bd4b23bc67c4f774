// cover_boxes: every triangle inside one box, at most 2^levels boxes, and tighter than the
// bounding box where a model has empty space between its parts. No GL context needed.
#include <gtest/gtest.h>

#include <random>

#include "gfx/cover_boxes.h"

namespace arc {
namespace {

bool inside(const Box3& b, const glm::vec3& p) {
  return glm::all(glm::lessThanEqual(b.lo, p)) && glm::all(glm::lessThanEqual(p, b.hi));
}

float volume(const Box3& b) {
  const glm::vec3 e = b.hi - b.lo;
  return e.x * e.y * e.z;
}

MeshPrimitive cube(glm::vec3 centre, float half) {
  MeshPrimitive p;
  for (int i = 0; i < 8; ++i)
    p.positions.push_back(centre + half * glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
  // Two triangles per face.
  p.indices = {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1, 2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
  return p;
}

TEST(CoverBoxes, EveryTriangleLiesWhollyInOneBox) {
  std::mt19937 gen(1234);
  std::uniform_real_distribution<float> u(-50.0f, 50.0f), small(-2.0f, 2.0f);
  std::vector<MeshPrimitive> prims(3);
  for (MeshPrimitive& p : prims)
    for (int t = 0; t < 300; ++t) {
      const glm::vec3 c(u(gen), u(gen), u(gen));
      for (int k = 0; k < 3; ++k) {
        p.indices.push_back(uint32_t(p.positions.size()));
        p.positions.push_back(c + glm::vec3(small(gen), small(gen), small(gen)));
      }
    }
  for (int levels = 0; levels <= 5; ++levels) {
    const std::vector<Box3> boxes = cover_boxes(prims, levels);
    ASSERT_FALSE(boxes.empty());
    EXPECT_LE(boxes.size(), size_t(1) << levels);
    for (const MeshPrimitive& p : prims)
      for (size_t i = 0; i < p.indices.size(); i += 3) {
        bool held = false;
        for (const Box3& b : boxes)
          held = held || (inside(b, p.positions[p.indices[i]]) && inside(b, p.positions[p.indices[i + 1]]) &&
                          inside(b, p.positions[p.indices[i + 2]]));
        EXPECT_TRUE(held) << "triangle " << i / 3 << " at levels " << levels;
      }
  }
  // Level 0 is the bounding box of the triangles.
  const std::vector<Box3> one = cover_boxes(prims, 0);
  ASSERT_EQ(one.size(), 1u);
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const MeshPrimitive& p : prims)
    for (const glm::vec3& q : p.positions) lo = glm::min(lo, q), hi = glm::max(hi, q);
  EXPECT_EQ(one[0].lo, lo);
  EXPECT_EQ(one[0].hi, hi);
}

TEST(CoverBoxes, LeaveTheGapBetweenPartsEmpty) {
  // Two cubes 20 apart: the bounding box is 22 × 2 × 2; every cover box stays within one cube
  // (boxes of one cube's triangles may overlap, but none reaches into the gap).
  const std::vector<MeshPrimitive> prims = {cube({-10, 0, 0}, 1.0f), cube({10, 0, 0}, 1.0f)};
  for (int levels = 1; levels <= 4; ++levels) {
    const std::vector<Box3> boxes = cover_boxes(prims, levels);
    EXPECT_GE(boxes.size(), 2u);
    for (const Box3& b : boxes) {
      EXPECT_TRUE(b.hi.x <= -9.0f || b.lo.x >= 9.0f) << "box from x " << b.lo.x << " to " << b.hi.x;
      EXPECT_LE(volume(b), 8.0f + 1e-4f);
    }
  }
}

TEST(CoverBoxes, EmptyAndMalformedInput) {
  EXPECT_TRUE(cover_boxes({}, 3).empty());
  MeshPrimitive bad;
  bad.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  bad.indices = {0, 1, 7, 0, 1};  // one triangle out of range, then two stray indices
  EXPECT_TRUE(cover_boxes({bad}, 3).empty());
  bad.indices = {0, 1, 2};
  const std::vector<Box3> one = cover_boxes({bad}, 3);
  ASSERT_EQ(one.size(), 1u) << "four or fewer triangles are not split";
  EXPECT_EQ(one[0].lo, glm::vec3(0, 0, 0));
  EXPECT_EQ(one[0].hi, glm::vec3(1, 1, 0));
}

}  // namespace
}  // namespace arc
