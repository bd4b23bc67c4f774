// The particle pass drawn as runs and held to the overdraw budget, headless through EGL: the
// runs give the one-draw picture (and effects apart on screen do not split each other's runs),
// particles a tilted wall's plane keeps out of reach skip the soft program, a frame under
// budget is untouched, and over budget the near particles shrink, the blended fragments fall
// and the estimate matches the count.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include <glm/gtc/quaternion.hpp>

#include "gfx/gl_features.h"
#include "gfx/image_compare.h"
#include "gfx_test_util.h"

namespace arc {
namespace {

using scenes::particle;

RenderView wall_view(Renderer& r) {
  RenderView v;
  v.camera.fov_y_radians = 0.9;
  v.camera.near_plane = 0.1;
  v.light_color = glm::vec3(0.6f);
  v.starfield_seed = 3;
  v.meshes.push_back({r.add_model(scenes::wall_model(8, 20, {0.4f, 0.45f, 0.5f, 1}, glm::vec3(0))), {-4.5, 0, -12}});
  // Smoke (ordered) and sparks (additive), soft, some within reach of the wall on the left and
  // the rest far from it on the right (flagged clear), in depth order interleaved.
  for (int i = 0; i < 120; ++i) {
    const float x = -7.0f + 0.12f * float(i), z = -11.0f - 0.8f * float(i % 5) + 0.5f * float(i % 3);
    const bool additive = i % 3 != 0;
    ParticleInstance p = particle({x, float(i % 7) - 3.0f, z}, 0.7f, additive ? glm::vec3(1, 0.6f, 0.2f) : glm::vec3(0.5f),
                                  additive ? 0.8f : 0.5f, additive ? 1.0f : 0.0f, SoftEdge::Linear);
    p.sprite = 0;
    v.particles.push_back(p);
  }
  return v;
}

TEST(ParticleDraws, RunsGiveTheOneDrawPicture) {
  REQUIRE_CONTEXT();
  Renderer r(RendererDesc{.offscreen = true});
  r.set_sprites({scenes::soft_sprite(64)});
  const RenderView v = wall_view(r);
  RenderSettings s = test::plain_settings();
  s.max_particle_draws = 1;
  r.set_render_settings(s);
  r.render(v, 320, 180);
  const Image one = r.read_pixels();
  ASSERT_EQ(r.last_stats().particle_draw_calls, 1);
  const int soft_one = r.last_stats().soft_shaded;
  s.max_particle_draws = 24;
  r.set_render_settings(s);
  r.render(v, 320, 180);
  const Image runs = r.read_pixels();
  test::dump_if_asked("particle_runs", runs);
  EXPECT_GT(r.last_stats().particle_draw_calls, 1);
  EXPECT_LE(r.last_stats().particle_draw_calls, 24);
  EXPECT_EQ(r.last_stats().soft_shaded, soft_one);
  EXPECT_GT(soft_one, 0);
  EXPECT_LT(soft_one, 120);
  // Additive particles regrouped among themselves round in another order: at most 1/255.
  EXPECT_LE(compare_images(one, runs).max_diff, 1);
}

// A wall turned 60° about the vertical: its box spans depths 7.4 to 12.6 and a wide strip of
// the screen, but its surface has one depth at each pixel. A particle 1.2 in front of the
// surface (its depth extent 0.4) lies inside the box's screen rectangle and depth range; only
// the wall's own plane separates them, and it must skip the depth read and look exactly as with
// soft edges off. One just in front of the surface must still be soft.
TEST(ParticleDraws, SoftEdgesSkipParticlesInFrontOfATiltedWall) {
  REQUIRE_CONTEXT();
  Renderer r(RendererDesc{.offscreen = true});
  r.set_sprites({scenes::soft_sprite(64)});
  RenderView v = test::dark_view();
  const double turn = 60.0 * 3.14159265358979 / 180.0;
  const glm::dquat yaw = glm::angleAxis(turn, glm::dvec3(0, 1, 0));
  v.meshes.push_back({r.add_model(scenes::wall_model(6, 20, {0.3f, 0.4f, 0.5f, 1}, glm::vec3(0))), {0, 0, -10}, yaw});
  const glm::vec3 normal = glm::vec3(yaw * glm::dvec3(0, 0, 1)), centre(0, 0, -10);
  auto render = [&](SoftEdge m) {
    RenderSettings s = test::plain_settings();
    s.soft_override = int(m);
    r.set_render_settings(s);
    r.render(v, 96, 64);
    return r.read_pixels();
  };
  for (float gap : {1.2f, 0.1f}) {
    v.particles = {particle(centre + normal * gap, 0.4f, glm::vec3(1, 0.5f, 0.2f), 0.7f, 0.0f)};
    const Image off = render(SoftEdge::Off);
    const Image soft = render(SoftEdge::Linear);
    test::dump_if_asked("tilted_wall_" + std::to_string(gap), soft);
    EXPECT_EQ(r.last_stats().soft_shaded, gap > 1.0f ? 0 : 1) << "gap " << gap;
    if (gap > 1.0f) EXPECT_EQ(compare_images(off, soft).max_diff, 0);
    else EXPECT_GT(compare_images(off, soft).max_diff, 4) << "soft edges must show";
  }
}

// Soft particles read the opaque depth from the framebuffer they draw into where the driver
// offers it (llvmpipe does), instead of a copy: the same depth values at the same pixels, so the
// same picture at full resolution (the scene's depth). At half resolution the fetch reads the
// half target's depth, the one its depth test uses, where the other path samples the scene's
// depth texture: along mesh edges a neighbouring texel. Every method, the particles within the
// wall's reach. A read one texel off at full resolution, or of a depth not yet written, fails.
TEST(ParticleDraws, DepthFetchGivesTheCopysPicture) {
  REQUIRE_CONTEXT();
  if (!has_depth_fetch()) GTEST_SKIP() << "the driver has no GL_ARM_shader_framebuffer_fetch_depth_stencil";
  Renderer r(RendererDesc{.offscreen = true});
  r.set_sprites({scenes::soft_sprite(64)});
  RenderView v = wall_view(r);
  v.camera.orientation = glm::angleAxis(0.15, glm::dvec3(1, 0, 0)) * glm::angleAxis(0.1, glm::dvec3(0, 1, 0));
  for (int i = 0; i < int(v.particles.size()); ++i) v.particles[size_t(i)].soft_edge = uint8_t(1 + i % 4);
  for (auto res : {RenderSettings::ParticleResolution::Full, RenderSettings::ParticleResolution::Half}) {
    const bool half = res == RenderSettings::ParticleResolution::Half;
    Image img[2];
    for (bool fetch : {false, true}) {
      RenderSettings s = test::plain_settings();
      s.particle_resolution = res;
      s.depth_fetch = fetch;
      r.set_render_settings(s);
      r.render(v, 320, 180);
      img[fetch] = r.read_pixels();
      const FrameStats& st = r.last_stats();
      EXPECT_EQ(st.depth_fetched, fetch) << (half ? "half" : "full");
      EXPECT_EQ(st.depth_copied, !fetch && !half) << (half ? "half" : "full");
      EXPECT_GT(st.soft_shaded, 0);
    }
    test::dump_if_asked(half ? "depth_fetch_half" : "depth_fetch_full", img[1]);
    const ImageDiff d = compare_images(img[0], img[1], {.tolerance = 0, .min_fraction = 1.0});
    std::printf("  %s resolution: %.4f %% of pixels differ, by %d/255 at most; %.1f dB\n", half ? "half" : "full",
                100.0 * (1.0 - d.fraction_within), d.max_diff, psnr_db(img[0], img[1]));
    if (half) {
      // The half target's depth is the scene's taken by a nearest blit, and of the 2 × 2 texels
      // under a half-resolution pixel the blit and the copy path's texture read take different
      // ones along mesh edges: 1.6 % of the pixels, by 5/255 at most (64 dB). The fetch reads
      // the very depth the fragment was tested against.
      EXPECT_LE(d.max_diff, 8) << d.summary();
      EXPECT_GE(psnr_db(img[0], img[1]), 55.0);
    } else {
      EXPECT_EQ(d.max_diff, 0) << d.summary();
    }
  }
}

// Two effects side by side, each with its soft particles interleaved in depth with the clear
// ones of the other: the back-to-front order alternates programs at every particle, but
// particles that share no pixel need no order between them, so the draw takes two runs (in
// depth order the hard runs would be single particles, folded into the soft program: every
// particle would pay the depth read), and the picture is the one-draw picture.
TEST(ParticleDraws, EffectsApartOnScreenDoNotInterleaveTheirRuns) {
  REQUIRE_CONTEXT();
  Renderer r(RendererDesc{.offscreen = true});
  r.set_sprites({scenes::soft_sprite(64)});
  RenderView v = test::dark_view();
  v.meshes.push_back({r.add_model(scenes::wall_model(4, 6, {0.3f, 0.4f, 0.5f, 1}, glm::vec3(0))), {-3, 0, -10}});
  for (int i = 0; i < 40; ++i) {  // smoke: alpha blended, so the order matters where they overlap
    const bool left = i % 2 == 0;
    v.particles.push_back(particle({left ? -3.0f : 3.0f, 0.05f * float(i) - 1.0f, -9.9f + 0.01f * float(i)}, 0.8f,
                                   glm::vec3(0.6f), 0.5f, 0.0f, SoftEdge::Linear));
  }
  RenderSettings s = test::plain_settings();
  s.max_particle_draws = 1;
  r.set_render_settings(s);
  r.render(v, 160, 90);
  const Image one = r.read_pixels();
  s.max_particle_draws = 24;
  r.set_render_settings(s);
  r.render(v, 160, 90);
  test::dump_if_asked("effects_apart", r.read_pixels());
  EXPECT_EQ(r.last_stats().soft_shaded, 20);
  EXPECT_EQ(r.last_stats().particle_draw_calls, 2);
  EXPECT_EQ(compare_images(one, r.read_pixels()).max_diff, 0);
}

TEST(ParticleDraws, BudgetLeavesAFrameUnderItUntouched) {
  REQUIRE_CONTEXT();
  Renderer r(RendererDesc{.offscreen = true});
  r.set_sprites({scenes::soft_sprite(64)});
  const RenderView v = wall_view(r);
  RenderSettings s = test::plain_settings();
  r.set_render_settings(s);
  r.render(v, 320, 180);
  const Image none = r.read_pixels();
  s.overdraw_budget = 64.0f;
  r.set_render_settings(s);
  r.render(v, 320, 180);
  EXPECT_EQ(r.last_stats().particles_reduced, 0);
  EXPECT_EQ(compare_images(none, r.read_pixels()).max_diff, 0);
}

TEST(ParticleDraws, BudgetShrinksNearParticlesAndItsEstimateMatchesTheCount) {
  REQUIRE_CONTEXT();
  Renderer r(RendererDesc{.offscreen = true});
  r.set_sprites({scenes::soft_sprite(64)});
  RenderView v = wall_view(r);
  for (int i = 0; i < 36; ++i)  // big puffs right at the eye
    v.particles.push_back(particle({float(i % 6) - 2.5f, float(i / 6) * 0.5f - 1.25f, -2.5f}, 1.2f, glm::vec3(0.3f), 0.4f, 0.0f));
  RenderSettings s = test::plain_settings();
  r.set_render_settings(s);
  r.count_particle_fragments(true);
  r.render(v, 320, 180);
  const FrameStats free = r.last_stats();
  const double pixels = 320.0 * 180.0;
  EXPECT_NEAR(free.overdraw_estimated_layers, double(free.particle_fragments) / pixels, 0.15 * free.overdraw_estimated_layers);
  ASSERT_GT(free.overdraw_estimated_layers, 3.0);
  s.overdraw_budget = 2.0f;
  r.set_render_settings(s);
  r.restart_smoothing();
  r.render(v, 320, 180);
  const FrameStats held = r.last_stats();
  test::dump_if_asked("particle_budget", r.read_pixels());
  EXPECT_GT(held.particles_reduced, 0);
  EXPECT_NEAR(held.overdraw_budgeted_layers, 2.0, 0.1);
  EXPECT_LT(held.particle_fragments, free.particle_fragments * 3 / 4);
  EXPECT_NEAR(held.overdraw_budgeted_layers, double(held.particle_fragments) / pixels, 0.15 * held.overdraw_budgeted_layers);
}

// Half resolution (render.particle_resolution = half): the particles blend into a quarter of
// the pixels and are put over the scene as S + T·scene, which must equal the chained blend
// (Ilmonen eq. 3) wherever the particles cover whole 2×2 blocks: a stack of broad flat
// particles, alpha-blended, half burnt and additive, over a lit wall.
TEST(ParticleDraws, HalfResolutionChainsTheSameBlend) {
  REQUIRE_CONTEXT();
  Renderer r(RendererDesc{.offscreen = true});
  RenderView v = wall_view(r);
  v.particles.clear();
  const glm::vec3 colours[3] = {{0.2f, 0.5f, 0.9f}, {0.9f, 0.4f, 0.1f}, {0.3f, 0.9f, 0.3f}};
  for (int i = 0; i < 3; ++i)  // a white 1×1 sprite: flat squares
    v.particles.push_back(particle({0, 0, -6.0f - float(i)}, 3.0f, colours[i], 0.5f, 0.5f * float(i)));
  RenderSettings s = test::plain_settings();
  r.set_render_settings(s);
  r.count_particle_fragments(true);
  r.render(v, 160, 90);
  const Image full = r.read_pixels();
  test::dump_if_asked("particles_full_resolution", full);
  const FrameStats full_stats = r.last_stats();
  s.particle_resolution = RenderSettings::ParticleResolution::Half;
  r.set_render_settings(s);
  r.render(v, 160, 90);
  const Image half = r.read_pixels();
  test::dump_if_asked("particles_half_resolution", half);
  EXPECT_EQ(r.last_stats().particle_target_pixels, 80.0 * 45.0);
  EXPECT_NEAR(double(r.last_stats().particle_fragments), double(full_stats.particle_fragments) / 4.0,
              0.02 * double(full_stats.particle_fragments));
  // Inside the squares over the wall, away from their edges: the same colour within rounding.
  // (Over bright stars the 8-bit scene clips the additive particle before the others darken
  // it, where the half target sums the light apart from the scene: not compared.) The
  // scene's alpha stays 1 everywhere.
  int worst = 0;
  for (int y = 30; y < 60; ++y)
    for (int x = 62; x < 72; ++x)
      for (int c = 0; c < 3; ++c) {
        const size_t k = (size_t(y) * 160 + size_t(x)) * 4 + size_t(c);
        worst = std::max(worst, std::abs(int(full.rgba[k]) - int(half.rgba[k])));
      }
  EXPECT_LE(worst, 3);
  int alpha_min = 255;
  for (size_t k = 3; k < half.rgba.size(); k += 4) alpha_min = std::min(alpha_min, int(half.rgba[k]));
  EXPECT_EQ(alpha_min, 255);
  EXPECT_GT(test::channel(full, 80, 45, 2), 0.1f) << "the particles are there";
}

// A scene stored top row first (RendererDesc::top_down_scene, what a window gets) gives the
// bottom-up scene's picture: the passes draw it with the upper-left origin, the depth copy and
// the composite take their rectangles as rows are stored, and the resolve turns it upright.
// Compared at full resolution (soft particles reading the depth copy over the wall) and at
// half resolution (the half target and its composite), with the near fade on and an asymmetric
// view (the wall's left edge crosses the screen off centre, the particles' pattern repeats
// every seven rows). At full resolution they are the same within 1/255 (measured: 0 pixels
// over 2/255). At half resolution a half pixel's centre lies between two scene rows, and the
// nearest-filtered depth (the half target's, and the soft particles' read) takes the other one
// when the rows are stored the other way round: 3/255 at most, in 176 pixels at the soft
// particles' edges over the wall. A frame turned upside down, a sky baked mirrored (tried:
// 9/255 over the whole sky), or a rectangle taken from the wrong rows, fails.
TEST(ParticleDraws, TopDownSceneGivesTheBottomUpPicture) {
  REQUIRE_CONTEXT();
  Renderer bottom_up(RendererDesc{.offscreen = true, .top_down_scene = RendererDesc::TopDownScene::Off});
  Renderer top_down(RendererDesc{.offscreen = true, .top_down_scene = RendererDesc::TopDownScene::On});
  for (Renderer* r : {&bottom_up, &top_down}) r->set_sprites({scenes::soft_sprite(64)});
  RenderView v = wall_view(bottom_up);
  wall_view(top_down);  // the same model id in the second renderer
  v.camera.orientation = glm::angleAxis(0.15, glm::dvec3(1, 0, 0)) * glm::angleAxis(0.1, glm::dvec3(0, 1, 0));
  for (auto res : {RenderSettings::ParticleResolution::Full, RenderSettings::ParticleResolution::Half}) {
    RenderSettings s = test::plain_settings();
    s.near_fade = 4.0f;
    s.particle_resolution = res;
    const bool half = res == RenderSettings::ParticleResolution::Half;
    Image img[2];
    FrameStats st[2];
    int k = 0;
    for (Renderer* r : {&bottom_up, &top_down}) {
      r->set_render_settings(s);
      r->render(v, 320, 180);
      img[k] = r->read_pixels();
      st[k++] = r->last_stats();
    }
    test::dump_if_asked(half ? "top_down_half" : "top_down_full", img[1]);
    test::dump_if_asked(half ? "bottom_up_half" : "bottom_up_full", img[0]);
    EXPECT_EQ(st[1].particles_half_res, half);
    if (half) EXPECT_GT(st[1].composite_share, 0.0);
    else EXPECT_TRUE(st[1].reads_depth()) << "soft particles within the wall's reach read the depth";
    EXPECT_GT(st[1].soft_shaded, 0);
    int differ = 0, worst = 0, mirrored_differ = 0;
    for (int y = 0; y < 180; ++y)
      for (int x = 0; x < 320; ++x) {
        int d = 0, m = 0;
        for (int c = 0; c < 3; ++c) {
          const size_t a = (size_t(y) * 320 + size_t(x)) * 4 + size_t(c);
          const size_t b = (size_t(179 - y) * 320 + size_t(x)) * 4 + size_t(c);
          d = std::max(d, std::abs(int(img[0].rgba[a]) - int(img[1].rgba[a])));
          m = std::max(m, std::abs(int(img[0].rgba[b]) - int(img[1].rgba[a])));
        }
        differ += d > 2;
        mirrored_differ += m > 2;
        worst = std::max(worst, d);
      }
    std::printf("  %s: %d of 57600 pixels differ by more than 2/255 (worst %d); upside down %d\n", half ? "half" : "full",
                differ, worst, mirrored_differ);
    EXPECT_LE(worst, half ? 4 : 1) << (half ? "half" : "full") << " resolution";
    EXPECT_LE(differ, half ? 57600 / 100 : 0) << (half ? "half" : "full") << " resolution";
    EXPECT_GT(mirrored_differ, 57600 / 10) << "the view is not symmetric top to bottom, so a flipped frame would show";
    EXPECT_GT(psnr_db(img[0], img[1]), 40.0);
  }
}

// render.particle_resolution = auto: half resolution while the particles blend more than one
// screen layer, full again only under 0.6 (in between, the last frame's choice stays).
TEST(ParticleDraws, AutoResolutionFollowsTheLayersWithHysteresis) {
  REQUIRE_CONTEXT();
  Renderer r(RendererDesc{.offscreen = true});
  RenderSettings s = test::plain_settings();
  s.particle_resolution = RenderSettings::ParticleResolution::Auto;
  r.set_render_settings(s);
  auto frame_with = [&](int puffs) {
    RenderView v;
    v.camera.fov_y_radians = 0.9;
    v.camera.near_plane = 0.1;
    for (int i = 0; i < puffs; ++i)
      v.particles.push_back(particle({float(i % 6) - 2.5f, float(i / 6) * 0.5f - 1.25f, -2.5f}, 1.2f, glm::vec3(0.3f), 0.4f, 0.0f));
    r.render(v, 320, 180);
    return r.last_stats();
  };
  FrameStats f = frame_with(2);
  ASSERT_LT(f.overdraw_budgeted_layers, 0.6);
  EXPECT_FALSE(f.particles_half_res);
  f = frame_with(36);
  ASSERT_GT(f.overdraw_budgeted_layers, 1.0);
  EXPECT_TRUE(f.particles_half_res);
  EXPECT_EQ(f.particle_target_pixels, 160.0 * 90.0);
  int between = 0;
  for (int n = 35; n > 0; --n) {
    f = frame_with(n);
    if (f.overdraw_budgeted_layers >= 0.6 && f.overdraw_budgeted_layers <= 1.0) {
      ++between;
      EXPECT_TRUE(f.particles_half_res) << n << " puffs, " << f.overdraw_budgeted_layers << " layers: stays half";
    }
    if (f.overdraw_budgeted_layers < 0.6) break;
  }
  EXPECT_GT(between, 0) << "the sweep must cross the band";
  EXPECT_FALSE(f.particles_half_res);
  EXPECT_EQ(f.particle_target_pixels, 320.0 * 180.0);
}

}  // namespace
}  // namespace arc

namespace arc {
namespace {

// The first frame after a settings change draws a tiny particle per program into the scene and
// the half-resolution target first (renderer.cpp, warm_up_particles); the frame must not show
// it: the first frame, with and without particles of its own, equals the one drawn after it.
TEST(ParticleDraws, ShaderWarmUpLeavesNoMark) {
  REQUIRE_CONTEXT();
  for (bool with_particles : {false, true}) {
    Renderer r(RendererDesc{.offscreen = true});
    r.set_sprites({scenes::soft_sprite(64)});
    RenderView v = wall_view(r);
    if (!with_particles) v.particles.clear();
    RenderSettings s = test::plain_settings();
    s.particle_resolution = RenderSettings::ParticleResolution::Half;
    r.set_render_settings(s);
    r.render(v, 320, 180);
    const Image first = r.read_pixels();
    r.render(v, 320, 180);
    EXPECT_EQ(compare_images(first, r.read_pixels()).max_diff, 0) << "with particles: " << with_particles;
  }
}

// FrameStats splits the frame by pass on the CPU: the opaque pass, the particle target (the
// depth copy, or the half-resolution target taking the scene's depth), the composite, the post
// pass and the HUD. Each is a part of the wall-clock time render() took, and the steps a frame
// does not take stay 0.
TEST(ParticleDraws, FrameStatsSplitTheFrameByPass) {
  REQUIRE_CONTEXT();
  Renderer r(RendererDesc{.offscreen = true});
  r.set_sprites({scenes::soft_sprite(64)});
  const RenderView v = wall_view(r);
  auto split_sum = [](const FrameStats& st) {
    return st.opaque_cpu_ms + st.particle_cpu_ms + st.post_cpu_ms + st.hud_cpu_ms;
  };
  for (auto res : {RenderSettings::ParticleResolution::Full, RenderSettings::ParticleResolution::Half}) {
    RenderSettings s = test::plain_settings();
    s.particle_resolution = res;
    r.set_render_settings(s);
    r.render(v, 320, 180);  // shader variants compiled, targets sized
    const auto t0 = std::chrono::steady_clock::now();
    r.render(v, 320, 180);
    const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const FrameStats st = r.last_stats();
    const bool half = res == RenderSettings::ParticleResolution::Half;
    SCOPED_TRACE(half ? "half resolution" : "full resolution");
    ASSERT_EQ(st.particles_half_res, half);
    ASSERT_GT(st.soft_shaded, 0);
    EXPECT_GT(st.opaque_cpu_ms, 0.0);
    // The depth copy, or the half target's depth; nothing at full resolution when the soft
    // particles read the scene's depth from the framebuffer.
    EXPECT_EQ(st.particle_target_cpu_ms > 0.0, half || st.depth_copied);
    EXPECT_NE(st.depth_copied, st.depth_fetched);
    EXPECT_EQ(st.particle_composite_cpu_ms > 0.0, half);
    EXPECT_GE(st.post_cpu_ms, 0.0);
    EXPECT_GE(st.hud_cpu_ms, 0.0);
    EXPECT_LE(st.particle_prep_ms + st.particle_target_cpu_ms + st.particle_composite_cpu_ms, st.particle_cpu_ms);
    EXPECT_LE(split_sum(st), wall);
  }
  // Soft edges off at full resolution: no depth copy, no composite.
  RenderSettings s = test::plain_settings();
  s.soft_override = 0;
  r.set_render_settings(s);
  r.render(v, 320, 180);
  EXPECT_FALSE(r.last_stats().reads_depth());
  EXPECT_EQ(r.last_stats().particle_target_cpu_ms, 0.0);
  EXPECT_EQ(r.last_stats().particle_composite_cpu_ms, 0.0);
}

}  // namespace
}  // namespace arc
