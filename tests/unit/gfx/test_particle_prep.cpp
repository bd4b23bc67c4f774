// The particle batch prepared per cluster stretch (render.particle_prep = cluster) against the
// per-particle path, headless through EGL: the same picture within the golden tolerance for
// every soft-edge method, sorting mode and depth-key width, with particles off screen, behind the
// camera and dark among them; the indexed batch against the copied one; the back-to-front order
// of the sorted indices; and the device classification the "auto" choice rests on.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include <glm/gtc/quaternion.hpp>

#include "gfx/cover_boxes.h"
#include "gfx/device_class.h"
#include "gfx/particle_batch.h"
#include "gfx/image_compare.h"
#include "gfx_test_util.h"

namespace arc {
namespace {

using scenes::particle;

// A wall on the left; smoke (ordered) and sparks (additive) in clusters of eight, some within
// its reach, the rest clear of it; plus clusters wholly off screen, behind the camera and dark.
RenderView crowd_view(Renderer& r) {
  RenderView v = test::dark_view();
  v.light_color = glm::vec3(0.6f);
  v.camera.orientation = glm::angleAxis(0.15, glm::dvec3(1, 0, 0)) * glm::angleAxis(0.1, glm::dvec3(0, 1, 0));
  v.meshes.push_back({r.add_model(scenes::wall_model(8, 20, {0.4f, 0.45f, 0.5f, 1}, glm::vec3(0))), {-4.5, 0, -12}});
  for (int i = 0; i < 160; ++i) {
    const float x = -7.0f + 0.1f * float(i), z = -11.0f - 0.8f * float(i % 5) + 0.5f * float(i % 3);
    const bool additive = i % 3 != 0;
    ParticleInstance p = particle({x, float(i % 7) - 3.0f, z}, 0.7f, additive ? glm::vec3(1, 0.6f, 0.2f) : glm::vec3(0.5f),
                                  additive ? 0.8f : 0.5f, additive ? 1.0f : 0.0f, SoftEdge(1 + i % 4));
    p.sprite = 0;
    p.cluster = uint32_t(1 + i / 8);
    v.particles.push_back(p);
  }
  for (int i = 0; i < 24; ++i) {
    const glm::vec3 where = i < 8 ? glm::vec3(60.0f + float(i), 0, -10) : i < 16 ? glm::vec3(0, float(i), 12) : glm::vec3(0, 0, -8);
    ParticleInstance p = particle(where, 0.5f, i < 16 ? glm::vec3(1) : glm::vec3(0), i < 16 ? 0.6f : 0.0f, 0.0f);
    p.cluster = uint32_t(100 + i / 8);
    v.particles.push_back(p);
  }
  return v;
}

Image render_with(Renderer& r, const RenderView& v, RenderSettings::ParticlePrep prep, RenderSettings::Sorting sorting,
                  int soft_override, int sort_bits = 22) {
  RenderSettings s = test::plain_settings();
  s.particle_prep = prep;
  s.particle_sort_bits = sort_bits;
  s.sorting = sorting;
  s.soft_override = soft_override;
  r.set_render_settings(s);
  r.render(v, 320, 180);
  return r.read_pixels();
}

TEST(ParticlePrep, ByClusterGivesThePerParticlePicture) {
  REQUIRE_CONTEXT();
  Renderer r(RendererDesc{.offscreen = true});
  r.set_sprites({scenes::soft_sprite(64)});
  const RenderView v = crowd_view(r);
  using Prep = RenderSettings::ParticlePrep;
  using Sorting = RenderSettings::Sorting;
  for (int soft : {-1, 0, 1, 2, 3, 4}) for (int bits : {22, 32}) {
    const Image per_particle = render_with(r, v, Prep::PerParticle, Sorting::Full, soft);
    const int kept = r.last_stats().particles_drawn;
    const Image by_cluster = render_with(r, v, Prep::PerCluster, Sorting::Full, soft, bits);
    if (bits == 22) test::dump_if_asked("prep_cluster_" + std::to_string(soft), by_cluster);
    EXPECT_EQ(r.last_stats().particle_draw_calls, 1);
    EXPECT_GE(r.last_stats().particles_drawn, kept);
    EXPECT_LT(r.last_stats().particles_drawn, int(v.particles.size())) << "dark and off-screen clusters are culled";
    // Runs regroup additive particles, which round in another order: 1/255 at most.
    const ImageDiff d = compare_images(per_particle, by_cluster);
    EXPECT_TRUE(d.passed) << "soft " << soft << ", " << bits << " bits: " << d.summary();
    EXPECT_LE(d.max_diff, 1) << "soft " << soft << ", " << bits << " bits";
  }
  // Unsorted, both paths draw in the view's order.
  const Image a = render_with(r, v, Prep::PerParticle, Sorting::Off, -1);
  const Image b = render_with(r, v, Prep::PerCluster, Sorting::Off, -1);
  EXPECT_LE(compare_images(a, b).max_diff, 1);
}

// The soft flag is decided per stretch, conservatively: a stretch out of every mesh's reach
// is drawn with the hard program and a stretch within it keeps its soft edges.
TEST(ParticlePrep, ClearStretchesSkipTheDepthRead) {
  REQUIRE_CONTEXT();
  Renderer r(RendererDesc{.offscreen = true});
  r.set_sprites({scenes::soft_sprite(64)});
  RenderView v = test::dark_view();
  v.meshes.push_back({r.add_model(scenes::wall_model(4, 4, {0.4f, 0.45f, 0.5f, 1}, glm::vec3(0))), {-3, 0, -12}});
  v.particles = {particle({3, 0, -6}, 0.3f, glm::vec3(1), 0.5f, 0.0f, SoftEdge::Linear)};
  RenderSettings s = test::plain_settings();
  s.particle_prep = RenderSettings::ParticlePrep::PerCluster;
  r.set_render_settings(s);
  r.render(v, 96, 64);
  EXPECT_EQ(r.last_stats().soft_shaded, 0);
  v.particles[0].pos[0] = -3.0f, v.particles[0].pos[2] = -11.9f;
  r.render(v, 96, 64);
  EXPECT_EQ(r.last_stats().soft_shaded, 1);
}

// The indexed batch (the view's particles as they are, an order of indices with the clear bit,
// the override left to the vertex shader) names the same particles in the same order as the
// copying batch a view too large for one buffer gets, with the same soft byte once patched.
TEST(ParticlePrep, IndexedBatchNamesTheCopiedParticles) {
  RenderView v = test::dark_view();
  for (int i = 0; i < 3000; ++i) {
    const float x = float(i % 40) * 0.3f - 6.0f, y = float((i / 40) % 20) * 0.3f - 3.0f, z = -5.0f - float(i % 97) * 0.2f;
    ParticleInstance p = particle({x, y, z}, 0.4f, glm::vec3(0.6f), 0.5f, float(i % 3 == 0), SoftEdge(i % 5));
    p.cluster = uint32_t(i / 37);
    v.particles.push_back(p);
  }
  const ModelCoverBoxes no_meshes;
  const ViewProjection vp = make_view_projection(v.camera, 16.0 / 9.0, true, true);
  for (int soft : {-1, 0, 2}) for (int bits : {11, 22, 32}) {
    ParticleBatchOptions o;
    o.by_cluster = true;
    o.soft_override = soft;
    o.sort_bits = bits;
    ParticleBatch copied, indexed;
    copied.prepare(v, vp, no_meshes, o);  // max_source 0: copies
    o.max_source = v.particles.size();
    indexed.prepare(v, vp, no_meshes, o);
    ASSERT_FALSE(copied.indexed());
    ASSERT_TRUE(indexed.indexed());
    ASSERT_EQ(indexed.order.size(), copied.particles.size());
    EXPECT_EQ(indexed.sorted, copied.sorted);
    EXPECT_EQ(indexed.soft_shaded, copied.soft_shaded);
    for (size_t i = 0; i < indexed.order.size(); ++i) {
      const uint32_t e = indexed.order[i];
      ParticleInstance q = v.particles[e & ParticleBatch::kOrderIndex];
      if (soft >= 0) q.soft_edge = uint8_t(soft);
      if ((e & ParticleBatch::kOrderClear) && q.soft_edge != 0) q.soft_edge |= kSoftClear;
      ASSERT_EQ(std::memcmp(&q, &copied.particles[i], sizeof q), 0) << "place " << i << ", soft " << soft << ", " << bits << " bits";
    }
  }
}

// Smoke in three colours stacked along the view axis, listed nearest first and in two clusters,
// with an additive glow (burn 1) before them: drawn back to front, the nearest smoke's blue
// covers the centre and the glow adds over it; any other order shows red or green through, or
// darkens the glow. Every depth-key width keeps the order of depths 1 m apart.
TEST(ParticlePrep, SortedIndicesBlendBackToFront) {
  REQUIRE_CONTEXT();
  Renderer r(RendererDesc{.offscreen = true});
  RenderView v = test::dark_view();
  const glm::vec3 colours[3] = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
  ParticleInstance glow = particle({0, 0, -5}, 0.5f, glm::vec3(1.0f, 0.0f, 0.0f), 0.6f, 1.0f);
  glow.cluster = 1;
  v.particles.push_back(glow);
  for (int i = 0; i < 3; ++i) {
    ParticleInstance p = particle({0, 0, -6.0f - float(i)}, 1.0f + 0.3f * float(i), colours[i], 0.9f, 0.0f);
    p.cluster = i == 0 ? 1u : 2u;
    v.particles.push_back(p);
  }
  for (int i = 0; i < 200; ++i) {  // far particles widen the quantised depth range
    ParticleInstance p = particle({float(i) * 0.5f - 50.0f, 20.0f, -300.0f}, 0.5f, glm::vec3(0.2f), 0.3f, 0.0f);
    p.cluster = 3;
    v.particles.push_back(p);
  }
  using Prep = RenderSettings::ParticlePrep;
  using Sorting = RenderSettings::Sorting;
  const Image per_particle = render_with(r, v, Prep::PerParticle, Sorting::Full, -1);
  for (int bits : {11, 22, 32}) {
    const Image img = render_with(r, v, Prep::PerCluster, Sorting::Full, -1, bits);
    EXPECT_GE(r.last_stats().sorted, 4) << bits << " bits";
    const int cx = img.width / 2, cy = img.height / 2;
    EXPECT_GT(test::channel(img, cx, cy, 2), 0.8f) << bits << " bits: the nearest smoke on top";
    EXPECT_LT(test::channel(img, cx, cy, 1), 0.2f) << bits << " bits";
    EXPECT_GT(test::channel(img, cx, cy, 0), 0.4f) << bits << " bits: the glow added last";
    EXPECT_LE(compare_images(per_particle, img).max_diff, 1) << bits << " bits";
  }
  const Image unsorted = render_with(r, v, Prep::PerCluster, Sorting::Off, -1);
  EXPECT_GT(test::channel(unsorted, unsorted.width / 2, unsorted.height / 2, 0), 0.5f) << "the test sees a wrong order";
  EXPECT_GT(compare_images(per_particle, unsorted).max_diff, 100);
}

TEST(DeviceClass, SoftwareRasterisersByName) {
  EXPECT_TRUE(is_software_rasteriser("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_TRUE(is_software_rasteriser("softpipe"));
  EXPECT_TRUE(is_software_rasteriser("Mesa X11 swrast"));
  EXPECT_TRUE(is_software_rasteriser("LLVMPIPE"));
  EXPECT_FALSE(is_software_rasteriser("NVIDIA H200/PCIe/SSE2"));
  EXPECT_FALSE(is_software_rasteriser("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.6, DRM 3.54)"));
  EXPECT_FALSE(is_software_rasteriser("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
  EXPECT_FALSE(is_software_rasteriser(""));
}

}  // namespace
}  // namespace arc
