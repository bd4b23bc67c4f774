// The usage examples of the renderer's CPU headers (no GL) as tests (HeaderExamples.MatchTheirTests
// keeps each banner and its test the same text).
#include <gtest/gtest.h>

#include <vector>

#include "assets/image.h"
#include "gfx/color_space.h"
#include "gfx/cover_boxes.h"
#include "gfx/frame_time_target.h"
#include "gfx/image_compare.h"
#include "gfx/overdraw_budget.h"
#include "gfx/particle_batch.h"
#include "gfx/particle_coverage.h"
#include "gfx/particle_occluders.h"
#include "gfx/particle_runs.h"
#include "gfx/sprite_trim.h"
#include "gfx/view_projection.h"
#include "scene_models.h"

namespace arc {
namespace {

// A camera at the origin looking along −Z, with a few particles ahead of it.
RenderView particle_view() {
  RenderView view;
  view.camera.fov_y_radians = 0.9;
  view.camera.near_plane = 0.1;
  for (int i = 0; i < 6; ++i)
    view.particles.push_back(scenes::particle({float(i) - 3.0f, 0.0f, -10.0f}, 1.0f, {1, 0.5f, 0.2f}, 0.5f,
                                              i % 2 ? 1.0f : 0.0f, i % 3 ? SoftEdge::Off : SoftEdge::Linear));
  return view;
}

TEST(GfxCpuExamples, LinearLight) {
  glm::vec3 lin = srgb_to_linear(glm::vec3(1.0f, 0.55f, 0.2f));
  Image texels = premultiply_linear_srgb(load_image("assets/textures/sprite_smoke.png"));
  EXPECT_FLOAT_EQ(lin.x, 1.0f);
  EXPECT_LT(lin.y, 0.55f) << "sRGB mid-tones are darker in linear light";
  EXPECT_TRUE(texels.premultiplied);
}

TEST(GfxCpuExamples, CompareImages) {
  const Image expected = load_image("assets/textures/sprite_smoke.png");
  const Image actual = expected;
  ImageDiff d = compare_images(expected, actual);
  if (!d.passed) write_failure_images("build/test-output/soft_edges", actual, expected);
  EXPECT_TRUE(d.passed) << d.summary();
  EXPECT_EQ(d.max_diff, 0);
}

TEST(GfxCpuExamples, OverdrawBudget) {
  std::vector<ParticleInstance> particles = particle_view().particles;
  std::vector<float> areas;
  OverdrawFrame frame;
  frame.width = 320;
  frame.height = 180;
  OverdrawBudget budget;
  OverdrawStats s = budget.apply(particles, areas, frame, {.budget_layers = 3, .near = 40});
  // particles: shrunk, faded and thinned in place; areas[i]: each one's blended pixels after it
  EXPECT_GT(s.estimated_layers, 0.0);
  EXPECT_LE(s.budgeted_layers, 3.0) << "within the budget";
  EXPECT_EQ(areas.size(), particles.size());
}

TEST(GfxCpuExamples, FrameTimeTarget) {
  FrameTimeTarget t;
  t.set_target(16.7);
  t.observe(40.0, true);  // a slow frame: level() falls below 1
  EXPECT_LT(t.level(), 1.0);
}

TEST(GfxCpuExamples, PrepareABatch) {
  const RenderView view = particle_view();
  const ModelCoverBoxes model_boxes;
  const double aspect = 16.0 / 9.0;
  int depth_copies = 0;
  std::vector<uint32_t> draws;
  ParticleBatch batch;
  batch.prepare(view, make_view_projection(view.camera, aspect, true, true), model_boxes, {});
  if (batch.any_soft) depth_copies += 1;                 // the depth buffer is copied first
  for (const ParticleRun& run : batch.runs) draws.push_back(run.count);  // one draw each
  EXPECT_EQ(depth_copies, 0) << "no opaque surface within the soft particles' reach";
  EXPECT_FALSE(draws.empty());
  EXPECT_EQ(batch.particles.size(), view.particles.size());
}

TEST(GfxCpuExamples, CoveredTiles) {
  ParticleCoverage c;
  c.reset(1280, 720);
  c.add_box(640.0f, 360.0f, 50.0f, 20.0f);  // centre (y up) and half-extents, pixels
  std::vector<PixelRect> rects;
  c.rects(rects);   // row runs of marked 32-pixel tiles, merged down while equal
  EXPECT_FALSE(rects.empty());
}

TEST(GfxCpuExamples, SoftCanMatter) {
  const RenderView view = particle_view();
  const ModelCoverBoxes model_boxes;
  const glm::mat3 to_view(1.0f);
  const float tan_half_y = 0.5f, tan_half_x = tan_half_y * 16.0f / 9.0f, axis_len = 1.0f, near = 0.1f;
  const ParticleInstance& particle = view.particles[0];
  OccluderSet occluders;
  occluders.gather(view, model_boxes, to_view, tan_half_x, tan_half_y);
  bool soft = occluders.soft_can_matter(particle, quad_bounds(particle, to_view, axis_len), near);
  EXPECT_EQ(occluders.size(), 0u);
  EXPECT_FALSE(soft) << "no opaque surface near it";
}

TEST(GfxCpuExamples, GroupRuns) {
  std::vector<ParticleInstance> particles = particle_view().particles;
  std::vector<float> areas(particles.size(), 100.0f);
  std::vector<ScreenBox> boxes(particles.size(), ScreenBox{0, 0, 10, 10});
  const int hard = 0, soft[2][2] = {{1, 2}, {3, 4}};
  std::vector<int> programs;
  auto draw = [&](uint32_t, uint32_t, int program) { programs.push_back(program); };
  std::vector<ParticleRun> runs;
  group_runs(particles, areas, boxes, /*max_runs=*/24, runs);
  for (auto& r : runs) draw(r.first, r.count, r.soft ? soft[r.contrast][r.density_extent] : hard);
  EXPECT_FALSE(programs.empty());
  EXPECT_LE(programs.size(), 24u);
}

TEST(GfxCpuExamples, TrimBoxes) {
  const std::vector<Image> layers{scenes::soft_sprite(64)};
  const int layer = 0, level = 1, w = 64, h = 64;
  std::vector<TrimBox> boxes = trim_boxes(layers);   // layers: premultiplied, one size
  TrimBox b = boxes[size_t(layer) * mip_levels(w, h) + level];  // u, v in [0, 1]
  EXPECT_EQ(boxes.size(), size_t(mip_levels(w, h)));
  (void)b;
}

}  // namespace
}  // namespace arc
