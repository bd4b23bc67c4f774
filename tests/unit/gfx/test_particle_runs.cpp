// Runs by shader variant on the CPU, no GL: clear particles stay out of soft runs, pure
// additive ones are regrouped only among themselves, ordered ones keep their order against
// every particle they share screen cells with (and only those), and the count of draws is
// bounded by folding the smallest hard runs into soft neighbours.
#include <gtest/gtest.h>

#include <limits>

#include "gfx/particle_occluders.h"
#include "gfx/particle_runs.h"
#include "scene_models.h"

namespace arc {
namespace {

using scenes::particle;

// An additive (burn 1) or ordered (alpha-blended) particle, soft (needs the depth copy) or
// clear; x tags it so the order can be checked.
ParticleInstance make(float x, bool additive, bool soft) {
  ParticleInstance p = particle({x, 0, -10}, 0.5f, glm::vec3(1), 1.0f, additive ? 1.0f : 0.0f, SoftEdge::Linear);
  if (!soft) p.soft_edge |= kSoftClear;
  return p;
}

std::vector<float> tags(const std::vector<ParticleInstance>& ps) {
  std::vector<float> t;
  for (auto& p : ps) t.push_back(p.pos[0]);
  return t;
}

TEST(ParticleRuns, ClearParticlesAreDrawnByTheHardProgram) {
  std::vector<ParticleInstance> ps = {make(0, false, false), make(1, false, true), make(2, false, false)};
  std::vector<float> areas(ps.size(), 1e6f);  // large: nothing is folded
  std::vector<ParticleRun> runs;
  group_runs(ps, areas, {}, 24, runs);
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_FALSE(runs[0].soft);
  EXPECT_TRUE(runs[1].soft);
  EXPECT_FALSE(runs[2].soft);
  EXPECT_EQ(runs[1].first, 1u);
  EXPECT_EQ(runs[1].count, 1u);
  EXPECT_EQ(tags(ps), (std::vector<float>{0, 1, 2}));
}

// A run takes the contrast and density-extent variants only when one of its soft particles
// uses that method: the linear program has neither the curve nor the texture-alpha division.
TEST(ParticleRuns, RunsTakeTheContrastAndDensityExtentVariantsOnlyWhenAParticleUsesThem) {
  auto with = [](float x, bool soft, SoftEdge m) {
    ParticleInstance p = make(x, false, soft);
    p.soft_edge = uint8_t(uint8_t(m) | (p.soft_edge & kSoftClear));
    return p;
  };
  // soft linear | hard (clear density extent) | soft linear + density extent | hard | soft contrast
  std::vector<ParticleInstance> ps = {with(0, true, SoftEdge::Linear), with(1, false, SoftEdge::DensityExtent),
                                      with(2, true, SoftEdge::Linear), with(3, true, SoftEdge::DensityExtent),
                                      with(4, false, SoftEdge::Linear), with(5, true, SoftEdge::Contrast)};
  std::vector<float> areas(ps.size(), 1e6f);
  std::vector<ParticleRun> runs;
  group_runs(ps, areas, {}, 24, runs);
  ASSERT_EQ(runs.size(), 5u);
  const bool density[5] = {false, false, true, false, false}, contrast[5] = {false, false, false, false, true};
  for (size_t r = 0; r < runs.size(); ++r) {
    EXPECT_EQ(runs[r].density_extent, density[r]) << "run " << r;
    EXPECT_EQ(runs[r].contrast, contrast[r]) << "run " << r;
  }
  // Folded into one soft run (a limit of 1), the run needs both.
  std::vector<ParticleRun> one;
  group_runs(ps, areas, {}, 1, one);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_TRUE(one[0].soft);
  EXPECT_TRUE(one[0].density_extent);
  EXPECT_TRUE(one[0].contrast);
}

TEST(ParticleRuns, RegroupsAdditiveStretchesAndKeepsOrderedOnesInPlace) {
  // ordered-soft, then additive h s h s h, then ordered-hard, then additive s h s
  std::vector<ParticleInstance> ps = {make(0, false, true),  make(1, true, false), make(2, true, true),
                                      make(3, true, false),  make(4, true, true),  make(5, true, false),
                                      make(6, false, false), make(7, true, true),  make(8, true, false),
                                      make(9, true, true)};
  std::vector<float> areas(ps.size(), 1e6f);
  std::vector<ParticleRun> runs;
  group_runs(ps, areas, {}, 24, runs);
  // The first stretch opens with the previous (soft) kind, ends with the next (hard) one;
  // the last opens with the hard kind before it.
  EXPECT_EQ(tags(ps), (std::vector<float>{0, 2, 4, 1, 3, 5, 6, 8, 7, 9}));
  ASSERT_EQ(runs.size(), 3u);  // soft 0 2 4 | hard 1 3 5 6 8 | soft 7 9
  EXPECT_TRUE(runs[0].soft);
  EXPECT_EQ(runs[0].count, 3u);
  EXPECT_FALSE(runs[1].soft);
  EXPECT_EQ(runs[1].count, 5u);
  EXPECT_TRUE(runs[2].soft);
  EXPECT_EQ(areas.size(), ps.size());
}

TEST(ParticleRuns, PureAdditiveBatchesNeedAtMostTwoDraws) {
  std::vector<ParticleInstance> ps;
  for (int i = 0; i < 100; ++i) ps.push_back(make(float(i), true, i % 3 == 0));
  std::vector<float> areas(ps.size(), 1e6f);
  std::vector<ParticleRun> runs;
  group_runs(ps, areas, {}, 24, runs);
  EXPECT_EQ(runs.size(), 2u);
}

TEST(ParticleRuns, FoldsTheSmallestHardRunsIntoSoftOnesToStayUnderTheLimit) {
  // 200 ordered particles alternating soft and hard: 200 runs unfolded.
  std::vector<ParticleInstance> ps;
  std::vector<float> areas;
  for (int i = 0; i < 200; ++i) {
    ps.push_back(make(float(i), false, i % 2 == 0));
    areas.push_back(i % 2 ? 1e5f + float(i) : 10.0f);  // hard ones large, the larger the later
  }
  std::vector<ParticleRun> runs;
  group_runs(ps, areas, {}, 24, runs);
  EXPECT_LE(runs.size(), 24u);
  EXPECT_GE(runs.size(), 20u);
  uint32_t total = 0;
  for (const ParticleRun& r : runs) total += r.count;
  EXPECT_EQ(total, 200u);
  EXPECT_EQ(tags(ps)[57], 57.0f);  // ordered particles never move
  // The hard runs kept are the largest: the last twelve (177, 179, ..., 199).
  ASSERT_EQ(runs.size(), 24u);
  EXPECT_TRUE(runs[0].soft);
  EXPECT_EQ(runs[0].count, 177u);
  EXPECT_FALSE(runs[1].soft);
  EXPECT_EQ(ps[runs[1].first].pos[0], 177.0f);
  EXPECT_FALSE(runs.back().soft);
  EXPECT_EQ(ps[runs.back().first].pos[0], 199.0f);
  // Small hard runs are folded even under the limit.
  std::vector<ParticleInstance> few = {make(0, false, true), make(1, false, false), make(2, false, true)};
  std::vector<float> small(3, 100.0f);
  group_runs(few, small, {}, 24, runs);
  EXPECT_EQ(runs.size(), 1u);
  EXPECT_TRUE(runs[0].soft);
}

// Screen boxes: the left or right third of the screen, or all of it.
constexpr ScreenBox kLeft{-1.0f, -1.0f, -0.4f, 1.0f}, kRight{0.4f, -1.0f, 1.0f, 1.0f}, kWide{-1.0f, -0.2f, 1.0f, 0.2f};

TEST(ParticleRuns, ParticlesThatShareNoPixelAreNotOrderedAgainstEachOther) {
  // Ordered particles alternating soft (left) and hard (right) in depth order: two runs.
  std::vector<ParticleInstance> ps;
  std::vector<ScreenBox> boxes;
  for (int i = 0; i < 10; ++i) {
    ps.push_back(make(float(i), false, i % 2 == 0));
    boxes.push_back(i % 2 == 0 ? kLeft : kRight);
  }
  std::vector<float> areas(ps.size(), 1e6f);
  std::vector<ParticleRun> runs;
  group_runs(ps, areas, boxes, 24, runs);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_TRUE(runs[0].soft);
  EXPECT_EQ(tags(ps), (std::vector<float>{0, 2, 4, 6, 8, 1, 3, 5, 7, 9}));
  // A hard particle across the screen between soft ones on the left: the ones after it must
  // follow it; a hard one on the right after them need only follow the wide one.
  ps = {make(0, false, true), make(1, false, false), make(2, false, true), make(3, false, false)};
  boxes = {kLeft, kWide, kLeft, kRight};
  areas.assign(ps.size(), 1e6f);
  group_runs(ps, areas, boxes, 24, runs);
  EXPECT_EQ(tags(ps), (std::vector<float>{0, 1, 3, 2}));
  ASSERT_EQ(runs.size(), 3u);  // soft 0 | hard 1 3 | soft 2
  EXPECT_EQ(runs[1].count, 2u);
  // A box that is not finite is the whole screen: everything keeps its order.
  const float inf = std::numeric_limits<float>::infinity();
  ps = {make(0, false, true), make(1, false, false), make(2, false, true)};
  boxes = {kLeft, {-inf, -inf, inf, inf}, kRight};
  areas.assign(ps.size(), 1e6f);
  group_runs(ps, areas, boxes, 24, runs);
  EXPECT_EQ(tags(ps), (std::vector<float>{0, 1, 2}));
  EXPECT_EQ(runs.size(), 3u);
}

TEST(ParticleRuns, PureAdditiveParticlesFollowOnlyTheOrderedOnesTheyOverlap) {
  // Additive soft, ordered hard, additive soft, all on the left; an additive soft on the right.
  std::vector<ParticleInstance> ps = {make(0, true, true), make(1, false, false), make(2, true, true), make(3, true, true)};
  std::vector<ScreenBox> boxes = {kLeft, kLeft, kLeft, kRight};
  std::vector<float> areas(ps.size(), 1e6f);
  std::vector<ParticleRun> runs;
  group_runs(ps, areas, boxes, 24, runs);
  EXPECT_EQ(tags(ps), (std::vector<float>{0, 3, 1, 2}));
  ASSERT_EQ(runs.size(), 3u);
}

TEST(ParticleRuns, AOnlyHardBatchIsOneHardDraw) {
  std::vector<ParticleInstance> ps = {make(0, false, false), make(1, true, false)};
  ps[1].soft_edge = 0;  // method off
  std::vector<float> areas(2, 1.0f);
  std::vector<ParticleRun> runs;
  group_runs(ps, areas, {}, 1, runs);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_FALSE(runs[0].soft);
}

}  // namespace
}  // namespace arc
