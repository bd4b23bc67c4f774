// The particle batch prepared per cluster stretch (render.particle_prep = cluster) against the
// per-particle path, headless through EGL: the same picture within the golden tolerance for
// every soft-edge method and sorting mode, with particles off screen, behind the camera and dark
// among them; and the device classification the "auto" choice rests on.
#include <gtest/gtest.h>

#include <string>

#include <glm/gtc/quaternion.hpp>

#include "gfx/device_class.h"
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
                  int soft_override) {
  RenderSettings s = test::plain_settings();
  s.particle_prep = prep;
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
  for (int soft : {-1, 0, 1, 2, 3, 4}) {
    const Image per_particle = render_with(r, v, Prep::PerParticle, Sorting::Full, soft);
    const int kept = r.last_stats().particles_drawn;
    const Image by_cluster = render_with(r, v, Prep::PerCluster, Sorting::Full, soft);
    test::dump_if_asked("prep_cluster_" + std::to_string(soft), by_cluster);
    EXPECT_EQ(r.last_stats().particle_draw_calls, 1);
    EXPECT_GE(r.last_stats().particles_drawn, kept);
    EXPECT_LT(r.last_stats().particles_drawn, int(v.particles.size())) << "dark and off-screen clusters are culled";
    // Runs regroup additive particles, which round in another order: 1/255 at most.
    const ImageDiff d = compare_images(per_particle, by_cluster);
    EXPECT_TRUE(d.passed) << "soft " << soft << ": " << d.summary();
    EXPECT_LE(d.max_diff, 1) << "soft " << soft;
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
