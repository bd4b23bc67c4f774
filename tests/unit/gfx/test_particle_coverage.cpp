// Where the half-resolution composite is drawn (gfx/particle_coverage.h): the tiles a box
// reaches and nothing else, rectangles merged down a column of equal runs, and, drawn by the
// renderer itself, every pixel a particle lights lies inside the rectangles the batch marks.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "gfx/particle_batch.h"
#include "gfx_test_util.h"

namespace arc {
namespace {

TEST(ParticleCoverage, MarksTheTilesABoxReachesAndNoOthers) {
  ParticleCoverage c;
  c.reset(320, 180);  // 10 × 6 tiles, the last row 20 pixels tall
  c.add_box(100.0f, 50.0f, 10.0f, 5.0f);  // x 86..114 and y 41..59 with the margin: tiles 2..3, 1
  std::vector<PixelRect> r;
  c.rects(r);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].x0, 64);
  EXPECT_EQ(r[0].x1, 128);
  EXPECT_EQ(r[0].y0, 32);
  EXPECT_EQ(r[0].y1, 64);
  EXPECT_NEAR(c.share(), 64.0 * 32.0 / (320.0 * 180.0), 1e-12);
  c.add_box(-500.0f, 50.0f, 10.0f, 10.0f);  // wholly off screen: nothing more
  c.rects(r);
  EXPECT_EQ(r.size(), 1u);
  c.add_box(315.0f, 175.0f, 30.0f, 30.0f);  // the corner: clipped to the screen's edge
  c.rects(r);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[1].x1, 320);
  EXPECT_EQ(r[1].y1, 180);
}

TEST(ParticleCoverage, MergesEqualRunsDownAndKeepsUnequalOnesApart) {
  ParticleCoverage c;
  c.reset(256, 256);
  c.add_box(48.0f, 80.0f, 10.0f, 60.0f);   // columns 1, rows 0..4
  c.add_box(200.0f, 16.0f, 2.0f, 2.0f);    // column 6, row 0
  std::vector<PixelRect> r;
  c.rects(r);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].y0, 0);
  EXPECT_EQ(r[0].y1, 160);  // one rectangle down five rows
  EXPECT_EQ(r[1].x0, 192);
  EXPECT_EQ(r[1].y1, 32);
}

TEST(ParticleCoverage, WholeScreenForANonFiniteBox) {
  ParticleCoverage c;
  c.reset(100, 50);
  c.add_box(std::nanf(""), 10.0f, 1.0f, 1.0f);
  EXPECT_TRUE(c.whole_screen());
  std::vector<PixelRect> r;
  c.rects(r);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].x1, 100);
  EXPECT_EQ(r[0].y1, 50);
  EXPECT_EQ(c.share(), 1.0);
}

// Camera-facing sprites at every rotation and axis-locked segments tilted in depth (their far
// end projects shorter than their near end), near and far, some half off screen: drawn at full
// resolution over a black sky, every pixel they change must lie in the batch's rectangles, and
// those must leave most of the screen out.
TEST(ParticleCoverage, EveryLitPixelLiesInTheMarkedTiles) {
  REQUIRE_CONTEXT();
  Renderer r(RendererDesc{.offscreen = true});
  RenderView v = test::dark_view();
  v.starfield_seed = 0;
  Rng rng{11, 0, 0};
  for (int i = 0; i < 40; ++i) {
    const glm::vec3 pos(float(rng.uniform(uint64_t(i) * 5) * 16.0 - 8.0), float(rng.uniform(uint64_t(i) * 5 + 1) * 9.0 - 4.5),
                        -float(1.5 + rng.uniform(uint64_t(i) * 5 + 2) * 20.0));
    ParticleInstance p = scenes::particle(pos, 0.15f, glm::vec3(0.8f, 0.6f, 0.3f), 1.0f, 1.0f);
    p.rotation = float(rng.uniform(uint64_t(i) * 5 + 3) * 6.283);
    if (i % 2) {
      p.billboard = uint8_t(Billboard::AxisLocked);
      const float t = float(rng.uniform(uint64_t(i) * 5 + 4) * 6.283);
      p.axis[0] = 1.5f * std::cos(t);
      p.axis[1] = 0.7f * std::sin(t);
      p.axis[2] = 2.5f;  // tilted toward the camera
      p.size = 0.05f;
    }
    v.particles.push_back(p);
  }
  RenderSettings s = test::plain_settings();
  s.particle_resolution = RenderSettings::ParticleResolution::Full;
  r.set_render_settings(s);
  const int w = 320, h = 180;
  const auto [background, lit] = test::render_without_and_with_particles(r, v, w, h);
  test::dump_if_asked("particle_coverage", lit);

  ParticleBatch batch;
  ParticleBatchOptions o;
  o.width = w;
  o.height = h;
  o.size_clamp = s.size_clamp;
  batch.prepare(v, make_view_projection(v.camera, double(w) / double(h), s.reversed_z, s.infinite_far), {}, o);
  std::vector<PixelRect> rects;
  batch.coverage.rects(rects);
  const test::ChangedPixels px = test::changed_pixels(background, lit, rects);
  EXPECT_GT(px.changed, 500);
  EXPECT_EQ(px.outside, 0);
  EXPECT_LT(batch.coverage.share(), 0.8);
  EXPECT_FALSE(batch.coverage.whole_screen());
}

}  // namespace
}  // namespace arc
