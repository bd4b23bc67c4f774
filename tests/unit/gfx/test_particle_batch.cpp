// The particle batch on the CPU, no GL context: culling against the frustum's sides, the
// back-to-front sort (and its absence for pure additive particles), the draw limit, stretches
// culled whole as their particles would be, and the
// soft-edge flag set only where an opaque mesh is within a particle's reach (a part box's face
// planes included).
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "gfx/particle_batch.h"
#include "scene_models.h"

namespace arc {
namespace {

using scenes::particle;

// Camera at the origin looking along −Z, a square view: the horizontal half-angle is the
// vertical one, 0.45 rad.
RenderView base_view() {
  RenderView v;
  v.camera.fov_y_radians = 0.9;
  v.camera.near_plane = 0.1;
  return v;
}

ParticleBatch prepare(const RenderView& v, const ParticleBatchOptions& options = {}, const ModelCoverBoxes& boxes = {}) {
  ParticleBatch batch;
  batch.prepare(v, make_view_projection(v.camera, 1.0, true, true), boxes, options);
  return batch;
}

std::vector<float> depths(const ParticleBatch& batch) {
  std::vector<float> z;
  for (const ParticleInstance& p : batch.particles) z.push_back(p.pos[2]);
  return z;
}

TEST(ParticleBatch, CullsParticlesWhollyOffTheFrustum) {
  RenderView v = base_view();
  const float edge = 10.0f * std::tan(0.45f);  // the right edge at depth 10
  v.particles.push_back(particle({0, 0, -10}, 1.0f, glm::vec3(1), 1.0f, 1.0f));
  v.particles.push_back(particle({edge + 3.0f, 0, -10}, 1.0f, glm::vec3(1), 1.0f, 1.0f));   // off by 2 quad sizes
  v.particles.push_back(particle({0, -edge - 3.0f, -10}, 1.0f, glm::vec3(1), 1.0f, 1.0f));  // below
  v.particles.push_back(particle({edge + 0.5f, 0, -10}, 1.0f, glm::vec3(1), 1.0f, 1.0f));   // reaches in
  v.particles.push_back(particle({0, 0, 5}, 1.0f, glm::vec3(1), 1.0f, 1.0f));              // behind the camera
  v.particles.push_back(particle({0, 0, -10}, 1.0f, glm::vec3(0), 0.0f, 1.0f));            // dark: invisible
  const ParticleBatch batch = prepare(v);
  EXPECT_EQ(batch.culled_offscreen, 2);
  ASSERT_EQ(batch.particles.size(), 2u);
  EXPECT_EQ(batch.visible, 2);
  EXPECT_EQ(batch.particles[0].pos[0], 0.0f);
  EXPECT_EQ(batch.particles[1].pos[0], edge + 0.5f);
}

// Whole stretches of a cluster are culled or left out for their size before any particle of
// them is looked at; the answer must be each particle's. The same particles in three clusters
// (stretches of up to 300) and each in its own (stretches of one) give the same batch: a far
// cluster wholly under min_px, one wholly off the right side, one around the camera.
TEST(ParticleBatch, StretchesAreCulledAsTheirParticlesWouldBe) {
  RenderView v = base_view();
  uint32_t seed = 12345;
  auto unit = [&seed] {  // in [−1, 1)
    seed = seed * 1664525u + 1013904223u;
    return float(seed >> 8) / float(1u << 23) - 1.0f;
  };
  const glm::vec3 centres[3] = {{0, 0, -900}, {200, 0, -50}, {0, 0, 0}};
  const float spreads[3] = {20, 10, 60};
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 300; ++i) {
      const glm::vec3 pos = centres[c] + spreads[c] * glm::vec3(unit(), unit(), unit());
      ParticleInstance p = particle(pos, 0.9f + 0.6f * unit(), glm::vec3(0.5f), i % 17 == 0 ? 0.0f : 0.5f, 0.0f);
      if (i % 17 == 0) p.color[0] = p.color[1] = p.color[2] = 0.0f;  // dark
      p.screen_priority = uint8_t(i % 5 == 0 ? ScreenPriority::High : ScreenPriority::Low);
      p.cluster = uint32_t(c);
      v.particles.push_back(p);
    }
  RenderView each = v;
  for (size_t i = 0; i < each.particles.size(); ++i) each.particles[i].cluster = uint32_t(100 + i);
  ParticleBatchOptions options;
  options.overdraw.min_px = 3.0f;
  const ParticleBatch whole = prepare(v, options), single = prepare(each, options);
  EXPECT_EQ(whole.culled_offscreen, single.culled_offscreen);
  EXPECT_EQ(whole.overdraw.dropped, single.overdraw.dropped);
  EXPECT_EQ(whole.overdraw.reduced, single.overdraw.reduced);
  EXPECT_GT(whole.culled_offscreen, 250);
  EXPECT_GT(whole.overdraw.dropped, 200);
  ASSERT_EQ(whole.particles.size(), single.particles.size());
  ASSERT_GT(whole.particles.size(), 50u);
  for (size_t i = 0; i < whole.particles.size(); ++i) {
    EXPECT_EQ(whole.particles[i].pos[0], single.particles[i].pos[0]);
    EXPECT_EQ(whole.particles[i].pos[2], single.particles[i].pos[2]);
    EXPECT_EQ(whole.particles[i].color[3], single.particles[i].color[3]);
  }
}

TEST(ParticleBatch, KeepsAnAxisLockedSegmentThatReachesIntoView) {
  RenderView v = base_view();
  const float edge = 10.0f * std::tan(0.45f);
  ParticleInstance beam = particle({-edge - 2.0f, 0, -10}, 0.3f, glm::vec3(1), 1.0f, 1.0f);
  beam.billboard = uint8_t(Billboard::AxisLocked);
  beam.axis[0] = 6.0f;  // centre off the left edge, the segment runs 1 unit into the view
  v.particles.push_back(beam);
  EXPECT_EQ(prepare(v).particles.size(), 1u);
  v.particles[0].axis[0] = 2.0f;  // now it ends 1 unit short of the edge
  EXPECT_EQ(prepare(v).culled_offscreen, 1);
}

// Three particles at depths 5, 9 and 7, in that order, all with the same burn.
RenderView three_at_depths_5_9_7(float burn) {
  RenderView v = base_view();
  for (float z : {-5.0f, -9.0f, -7.0f}) v.particles.push_back(particle({0, 0, z}, 1.0f, glm::vec3(1), 0.8f, burn));
  return v;
}

TEST(ParticleBatch, SortsAlphaParticlesBackToFront) {
  const ParticleBatch batch = prepare(three_at_depths_5_9_7(0.0f));
  EXPECT_EQ(depths(batch), (std::vector<float>{-9.0f, -7.0f, -5.0f}));
  EXPECT_EQ(batch.sorted, 3);
}

TEST(ParticleBatch, LeavesPureAdditiveParticlesInTheirOrder) {
  const ParticleBatch batch = prepare(three_at_depths_5_9_7(1.0f));
  EXPECT_EQ(depths(batch), (std::vector<float>{-5.0f, -9.0f, -7.0f}));
  EXPECT_EQ(batch.sorted, 0);
}

// An additive glow in front of smoke must not be darkened by it: one alpha-blended particle
// orders the whole set.
TEST(ParticleBatch, OneAlphaParticleOrdersTheAdditiveOnesToo) {
  RenderView v = three_at_depths_5_9_7(1.0f);
  v.particles[2].burn = 0.5f;
  const ParticleBatch batch = prepare(v);
  EXPECT_EQ(depths(batch), (std::vector<float>{-9.0f, -7.0f, -5.0f}));
  ParticleBatchOptions off;
  off.sorting = RenderSettings::Sorting::Off;
  EXPECT_EQ(depths(prepare(v, off)), (std::vector<float>{-5.0f, -9.0f, -7.0f}));
  EXPECT_EQ(prepare(v, off).sorted, 0);
}

// Cluster 1 = {at 5, at 9}, mean 7; cluster 0 = {at 8}: cluster 0 first, then cluster 1 in
// its own order.
TEST(ParticleBatch, ClusterSortingOrdersWholeClustersByMeanDepth) {
  RenderView v = base_view();
  v.particles = {particle({0, 0, -5}, 1.0f, glm::vec3(1), 1.0f, 0.0f), particle({0, 0, -9}, 1.0f, glm::vec3(1), 1.0f, 0.0f),
                 particle({0, 0, -8}, 1.0f, glm::vec3(1), 1.0f, 0.0f)};
  v.particles[0].cluster = v.particles[1].cluster = 1;
  ParticleBatchOptions options;
  options.sorting = RenderSettings::Sorting::Cluster;
  EXPECT_EQ(depths(prepare(v, options)), (std::vector<float>{-8.0f, -5.0f, -9.0f}));
}

TEST(ParticleBatch, KeepsTheNearestParticlesPastTheDrawLimit) {
  RenderView v = base_view();
  for (float z : {-8.0f, -5.0f, -4.0f}) v.particles.push_back(particle({0, 0, z}, 0.5f, glm::vec3(1), 1.0f, 0.0f));
  ParticleBatchOptions options;
  options.max_particles = 2;
  const ParticleBatch batch = prepare(v, options);
  EXPECT_EQ(batch.over_draw_limit, 1);
  EXPECT_EQ(batch.visible, 3);
  EXPECT_EQ(depths(batch), (std::vector<float>{-5.0f, -4.0f}));
}

// A wall 6 × 20 covering the left half of the view at depth 10 (model 0). Soft particles of
// size 0.5 (their depth extent): one just in front of it, one far in front, one beside it on
// the right half, one hidden behind it, and one near it with soft edges off.
struct ReachScene {
  RenderView view = base_view();
  ModelCoverBoxes boxes;
  ReachScene() {
    const ModelData wall = scenes::wall_model(6, 20, {0.3f, 0.4f, 0.5f, 1}, glm::vec3(0));
    boxes.push_back(cover_boxes(wall.primitives, 3));
    view.meshes.push_back({ModelId{1u}, {-3.2, 0, -10}});
    view.meshes.push_back({ModelId{8u}, {0, 0, -10.2}});  // an unknown model: no occluder
    for (float z : {-9.8f, -5.0f}) view.particles.push_back(particle({-3, 0, z}, 0.5f, glm::vec3(1), 1.0f, 1.0f, SoftEdge::Linear));
    view.particles.push_back(particle({3, 0, -10}, 0.5f, glm::vec3(1), 1.0f, 1.0f, SoftEdge::Linear));
    view.particles.push_back(particle({-3, 0, -12}, 0.5f, glm::vec3(1), 1.0f, 1.0f, SoftEdge::Linear));
    view.particles.push_back(particle({-3, 0, -9.8f}, 0.5f, glm::vec3(1), 1.0f, 1.0f, SoftEdge::Off));
  }
};

// The soft-edge byte of the kept particle at (x, z) whose method was `method` (the runs
// regroup additive particles, so they are found by place, not by index).
int soft_at(const ParticleBatch& batch, float x, float z, SoftEdge method) {
  for (const ParticleInstance& p : batch.particles)
    if (p.pos[0] == x && p.pos[2] == z && (p.soft_edge & 0x7F) == uint8_t(method)) return p.soft_edge;
  return -1;
}

TEST(ParticleBatch, FlagsSoftEdgesClearWhereNoMeshIsWithinReach) {
  ReachScene scene;
  const ParticleBatch batch = prepare(scene.view, {}, scene.boxes);
  ASSERT_EQ(batch.particles.size(), 5u);
  const int linear = int(SoftEdge::Linear);
  EXPECT_EQ(soft_at(batch, -3, -9.8f, SoftEdge::Linear), linear) << "just in front of the wall: soft";
  EXPECT_EQ(soft_at(batch, -3, -5, SoftEdge::Linear), linear | kSoftClear) << "far in front of it";
  EXPECT_EQ(soft_at(batch, 3, -10, SoftEdge::Linear), linear | kSoftClear) << "beside it on screen";
  EXPECT_EQ(soft_at(batch, -3, -12, SoftEdge::Linear), linear | kSoftClear) << "behind it";
  EXPECT_EQ(soft_at(batch, -3, -9.8f, SoftEdge::Off), 0) << "soft edges off stay off, unflagged";
  EXPECT_EQ(batch.soft_shaded, 1);
  EXPECT_TRUE(batch.any_soft);
  EXPECT_FALSE(batch.any_contrast);
  EXPECT_FALSE(prepare(scene.view).any_soft) << "no mesh at all: nothing needs the depth copy";
}

// A wall turned 60° about the vertical, centred at depth 10: its box's screen rectangle and
// depth range (7.4 to 12.6) hold particles that are far in front of its surface, which its own
// plane keeps out of reach. A particle 1.2 in front of the surface (extent 0.4) is clear; one
// 0.1 in front, and one 1.2 in front with an extent of 2, are soft; one 1.2 behind is hidden.
TEST(ParticleBatch, ATiltedWallsPlaneKeepsParticlesInFrontOfItClear) {
  RenderView v = base_view();
  ModelCoverBoxes boxes{cover_boxes(scenes::wall_model(6, 20, {0.3f, 0.4f, 0.5f, 1}, glm::vec3(0)).primitives, 3)};
  const glm::dquat yaw = glm::angleAxis(60.0 * 3.14159265358979 / 180.0, glm::dvec3(0, 1, 0));
  v.meshes.push_back({ModelId{1u}, {0, 0, -10}, yaw});
  const glm::vec3 normal = glm::vec3(yaw * glm::dvec3(0, 0, 1)), centre(0, 0, -10);
  struct Case {
    float gap, extent;
    bool soft;
  } cases[] = {{1.2f, 0.4f, false}, {0.1f, 0.4f, true}, {1.2f, 2.0f, true}, {-1.2f, 0.4f, false}};
  for (const Case& c : cases) {
    ParticleInstance p = particle(centre + normal * c.gap, 0.4f, glm::vec3(1), 1.0f, 1.0f, SoftEdge::Linear);
    p.soft_extent = c.extent;
    v.particles = {p};
    const ParticleBatch batch = prepare(v, {}, boxes);
    ASSERT_EQ(batch.particles.size(), 1u);
    EXPECT_EQ(batch.soft_shaded, c.soft ? 1 : 0) << "gap " << c.gap << ", extent " << c.extent;
  }
}

// The depth copy is filled only where a particle that reads it can be: the tiles of the soft
// particle just in front of the wall (left of centre), not those of the clear ones beside it.
TEST(ParticleBatch, MarksTheDepthReadsOfSoftParticlesOnly) {
  ReachScene scene;
  ParticleBatchOptions options;
  options.width = 320, options.height = 320;  // the square view of base_view()
  const ParticleBatch batch = prepare(scene.view, options, scene.boxes);
  ASSERT_EQ(batch.soft_shaded, 1);
  std::vector<PixelRect> rects;
  batch.depth_reads.rects(rects);
  ASSERT_FALSE(rects.empty());
  // The soft one is at x = −3 at depth 9.8 (tan 0.45 = 0.483 across half the view): about
  // pixel 58 of 320, size 0.5 (8 pixels), so within the first few 32-pixel tiles.
  for (const PixelRect& r : rects) {
    EXPECT_LT(r.x1, 160) << "nothing right of the centre";
    EXPECT_LE(r.x0, 58);
    EXPECT_GE(r.x1, 58);
  }
  EXPECT_LT(batch.depth_reads.share(), 0.1);
  // Every particle soft and reaching a surface: the whole screen.
  RenderView v = scene.view;
  v.particles = {v.particles[0]};
  const ParticleBatch one = prepare(v, options, scene.boxes);
  ASSERT_EQ(one.soft_shaded, 1);
  EXPECT_EQ(one.depth_reads.share(), 1.0);
}

TEST(ParticleBatch, SoftOverrideAppliesToEveryParticle) {
  ReachScene scene;
  ParticleBatchOptions options;
  options.soft_override = int(SoftEdge::Off);
  const ParticleBatch off = prepare(scene.view, options, scene.boxes);
  EXPECT_FALSE(off.any_soft);
  for (const ParticleInstance& p : off.particles) EXPECT_EQ(p.soft_edge, 0);
  options.soft_override = int(SoftEdge::Contrast);
  const ParticleBatch contrast = prepare(scene.view, options, scene.boxes);
  EXPECT_EQ(contrast.soft_shaded, 2) << "the one in front and the one that had soft edges off";
  EXPECT_TRUE(contrast.any_contrast);
  int unflagged = 0;
  for (const ParticleInstance& p : contrast.particles) unflagged += p.soft_edge == uint8_t(SoftEdge::Contrast);
  EXPECT_EQ(unflagged, 2);
}

TEST(RadixSort, BackToFrontAndStable) {
  std::vector<uint32_t> keys = {5, 0x80000000u, 5, 7, 0, 0xFFFFFFFFu, 300, 70000};
  std::vector<uint32_t> order;
  radix_sort_back_to_front(keys, order);
  ASSERT_EQ(order.size(), keys.size());
  for (size_t i = 1; i < order.size(); ++i) {
    EXPECT_GE(keys[order[i - 1]], keys[order[i]]);
    if (keys[order[i - 1]] == keys[order[i]]) {
      EXPECT_LT(order[i - 1], order[i]);
    }
  }
  EXPECT_EQ(order.front(), 5u);
}

TEST(RadixSort, SortableBitsKeepTheOrderOfFloats) {
  const float values[] = {-1e30f, -2.5f, -0.0f, 0.0f, 1e-30f, 3.0f, 1e30f};
  for (size_t i = 1; i < std::size(values); ++i) EXPECT_LE(sortable_bits(values[i - 1]), sortable_bits(values[i]));
  EXPECT_LT(sortable_bits(-2.5f), sortable_bits(3.0f));
}

}  // namespace
}  // namespace arc
