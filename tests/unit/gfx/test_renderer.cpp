// Renderer tests, headless through EGL (Mesa llvmpipe). They skip, with the reason, when no
// EGL context can be made.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <glm/gtc/quaternion.hpp>

#include "game/app/all_settings.h"
#include "gfx/gl_features.h"
#include "gfx/image_compare.h"
#include "gfx_test_util.h"
#include "core/data_root.h"

namespace arc {
namespace {

using test::channel;
using scenes::particle;

RenderView base_view() { return test::dark_view(); }

std::unique_ptr<Renderer> make_renderer(bool float_scene = false) {
  RendererDesc d;
  d.offscreen = true;
  d.float_scene = float_scene;
  auto r = std::make_unique<Renderer>(d);
  r->set_render_settings(test::plain_settings());
  return r;
}

TEST(Renderer, ReportsVersionAndClipControl) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  EXPECT_FALSE(r->gl_version().empty());
  RenderSettings s = test::plain_settings();
  s.reversed_z = true;
  r->set_render_settings(s);
  EXPECT_EQ(r->render_settings().reversed_z, r->has_clip_control());
}

// Ilmonen eq. 3: result = rgb·alpha + (1 − alpha·(1 − burn))·background, per channel.
TEST(Renderer, BurnBlendMatchesEquation3) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  const glm::vec3 bgs[] = {{0.2f, 0.4f, 0.6f}, {0.9f, 0.1f, 0.3f}};
  const glm::vec3 fg(0.8f, 0.5f, 0.1f);
  const float alpha = 0.6f;
  ModelId wall_models[2] = {r->add_model(scenes::wall_model(100, 100, {0, 0, 0, 1}, bgs[0])),
                        r->add_model(scenes::wall_model(100, 100, {0, 0, 0, 1}, bgs[1]))};
  for (int b = 0; b < 2; ++b)
    for (float burn : {0.0f, 0.25f, 0.5f, 1.0f}) {
      RenderView v = base_view();
      v.meshes.push_back({wall_models[b], {0, 0, -20}});
      v.particles.push_back(particle({0, 0, -10}, 2.0f, fg, alpha, burn));
      r->render(v, 64, 64);
      Image img = r->read_pixels();
      for (int c = 0; c < 3; ++c) {
        float expect = std::min(1.0f, fg[c] * alpha + (1 - alpha * (1 - burn)) * bgs[b][c]);
        EXPECT_NEAR(channel(img, 32, 32, c), expect, 1.0f / 255 + 1e-4f) << "burn " << burn << " channel " << c;
      }
      float over = fg[0] * alpha + (1 - alpha) * bgs[b][0];
      float add = std::min(1.0f, fg[0] * alpha + bgs[b][0]);
      if (burn == 0.0f) {
        EXPECT_NEAR(channel(img, 32, 32, 0), over, 1.0f / 255 + 1e-4f);
      }
      if (burn == 1.0f) {
        EXPECT_NEAR(channel(img, 32, 32, 0), add, 1.0f / 255 + 1e-4f);
      }
    }
  EXPECT_EQ(r->last_stats().particle_draw_calls, 1);
}

// A wall turned 60° about Y so its depth changes across the image; a particle sits on it.
struct CutScene {
  RenderView view;
  int width = 200, height = 100;
};

CutScene cut_scene(Renderer& r, SoftEdge soft) {
  CutScene s;
  s.view = base_view();
  ModelId wall = r.add_model(scenes::wall_model(60, 60, {0, 0, 0, 1}, glm::vec3(0.05f, 0.05f, 0.1f)));
  s.view.meshes.push_back({wall, {0, 0, -12}, glm::angleAxis(glm::radians(60.0), glm::dvec3(0, 1, 0))});
  s.view.particles.push_back(particle({0, 0, -12}, 3.0f, glm::vec3(1.0f, 0.8f, 0.5f), 0.9f, 0.0f, soft));
  return s;
}

// Only the columns around the particle: the wall's far edge and the stars make steps too.
float largest_step_along_row(const Image& img, int y) {
  float worst = 0;
  for (int x = 61; x < 138; ++x)
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(channel(img, x, y, c) - channel(img, x - 1, y, c)));
  return worst;
}

TEST(Renderer, SoftEdgesRemoveTheHardCut) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  r->set_sprites({scenes::soft_sprite(64)});
  CutScene hard = cut_scene(*r, SoftEdge::Off);
  r->render(hard.view, hard.width, hard.height);
  Image hard_img = r->read_pixels();
  test::dump_if_asked("cut_hard", hard_img);
  float hard_step = largest_step_along_row(hard_img, hard.height / 2);
  EXPECT_GT(hard_step, 0.5f) << "without soft edges the cut must be a hard edge";
  std::vector<Image> images;
  for (SoftEdge m : {SoftEdge::Linear, SoftEdge::Contrast, SoftEdge::AverageDensity, SoftEdge::DensityExtent}) {
    CutScene soft = cut_scene(*r, m);
    // The depth read from a copy, then (where the driver offers it) from the framebuffer itself:
    // the same values, the same picture.
    Image img[2];
    for (bool fetch : {false, true}) {
      RenderSettings s = r->render_settings();
      s.depth_fetch = fetch;
      r->set_render_settings(s);
      r->render(soft.view, soft.width, soft.height);
      img[fetch] = r->read_pixels();
      EXPECT_EQ(r->last_stats().depth_fetched, fetch && has_depth_fetch());
      EXPECT_EQ(r->last_stats().depth_copied, !r->last_stats().depth_fetched);
    }
    images.push_back(img[1]);
    test::dump_if_asked("cut_soft_" + std::to_string(int(m)), img[1]);
    float step = largest_step_along_row(img[1], soft.height / 2);
    EXPECT_LT(step, 0.2f) << "soft method " << int(m);
    EXPECT_EQ(compare_images(img[0], img[1]).max_diff, 0) << "depth fetched and copied, soft method " << int(m);
  }
  // Each method shapes the fade differently: no two images may be the same.
  for (size_t a = 0; a < images.size(); ++a)
    for (size_t b = a + 1; b < images.size(); ++b)
      EXPECT_GE(compare_images(images[a], images[b]).max_diff, 8) << "methods " << a + 1 << " and " << b + 1;
}

// Meshes and particles near the origin, then everything (camera included) moved by 1e9 and 1e12.
RenderView offset_scene(Renderer& r, ModelId wall, ModelId box, glm::dvec3 offset) {
  RenderView v = base_view();
  v.light_color = glm::vec3(1.0f, 0.95f, 0.9f);
  v.ambient = glm::vec3(0.1f);
  v.camera.position = offset + glm::dvec3(0.3, 0.7, 2.0);
  v.camera.orientation = glm::angleAxis(0.2, glm::dvec3(0, 1, 0));
  v.meshes.push_back({wall, offset + glm::dvec3(0, 0, -25)});
  v.meshes.push_back({box, offset + glm::dvec3(-2, 0.5, -12), glm::angleAxis(0.7, glm::normalize(glm::dvec3(1, 1, 0)))});
  for (int i = 0; i < 40; ++i) {
    glm::dvec3 world = offset + glm::dvec3(-4 + 0.2 * i, std::sin(i * 0.7), -14 + 0.1 * i);
    glm::vec3 rel(world - v.camera.position);
    v.particles.push_back(particle(rel, 0.8f, glm::vec3(1.0f, 0.5f + 0.01f * i, 0.2f), 0.7f, (i % 3) * 0.5f,
                                   SoftEdge(i % 5)));
  }
  return v;
}

TEST(Renderer, LargeCoordinatesRenderLikeTheOrigin) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  r->set_sprites({scenes::soft_sprite(64)});
  ModelId wall = r->add_model(scenes::wall_model(80, 80, {0.5f, 0.5f, 0.55f, 1}, glm::vec3(0)));
  ModelId box = r->add_model(scenes::box_model({1.5f, 1.0f, 2.5f}, {0.7f, 0.3f, 0.2f, 1}, glm::vec3(0.05f)));
  r->render(offset_scene(*r, wall, box, glm::dvec3(0)), 320, 180);
  Image a = r->read_pixels();
  test::dump_if_asked("origin", a);
  for (double far : {1e9, 1e12}) {  // 1e12: far beyond the level files' limit (kSpace, game/sim/def_parsing.h)
    r->render(offset_scene(*r, wall, box, glm::dvec3(far, -far, far)), 320, 180);
    Image b = r->read_pixels();
    test::dump_if_asked(far > 1e10 ? "level_limit" : "far_away", b);
    ImageDiff d = compare_images(a, b);
    if (!d.passed) write_failure_images("test_gfx_large_coordinates", b, a);
    EXPECT_TRUE(d.passed) << far << ": " << d.summary();
  }
}

TEST(Renderer, DegenerateBillboardsGiveFinitePixels) {
  REQUIRE_CONTEXT();
  auto r = make_renderer(true);
  r->set_sprites({scenes::soft_sprite(32)});
  ModelId wall = r->add_model(scenes::wall_model(50, 50, {0.3f, 0.3f, 0.3f, 1}, glm::vec3(0.1f)));
  RenderView v = base_view();
  v.meshes.push_back({wall, {0, 0, -10}});
  auto at_camera = particle({0, 0, 0}, 1.0f, glm::vec3(1, 0.5, 0.2), 0.8f, 0.3f, SoftEdge::Linear);
  auto zero_size = particle({0.5f, 0, -5}, 0.0f, glm::vec3(1), 1.0f, 0.0f, SoftEdge::Contrast);
  auto along_view = particle({0, 0.2f, -5}, 0.3f, glm::vec3(0.2, 0.6, 1), 0.9f, 1.0f, SoftEdge::DensityExtent);
  along_view.billboard = uint8_t(Billboard::AxisLocked);
  along_view.axis[2] = -4.0f;
  auto zero_axis = particle({-0.5f, 0, -5}, 0.4f, glm::vec3(1), 0.5f, 0.5f, SoftEdge::AverageDensity);
  zero_axis.billboard = uint8_t(Billboard::AxisLocked);
  auto tiny_extent = particle({0, -0.5f, -10}, 1e-9f, glm::vec3(1), 1.0f, 0.0f, SoftEdge::Linear);
  v.particles = {at_camera, zero_size, along_view, zero_axis, tiny_extent};
  for (bool reversed : {true, false}) {
    RenderSettings s = test::plain_settings();
    s.reversed_z = reversed;
    s.near_fade = 1.0f;
    r->set_render_settings(s);
    r->render(v, 96, 96);
    std::vector<float> px = r->read_pixels_float();
    size_t bad = 0;
    for (float f : px) bad += !std::isfinite(f);
    EXPECT_EQ(bad, 0u) << (reversed ? "reversed" : "standard");
    EXPECT_EQ(r->last_stats().particles_drawn, 5);
  }
  // The segment seen end-on still covers pixels (it becomes a camera-facing quad), and its
  // colour is there: a bluish spot above the centre.
  Image img = r->read_pixels();
  test::dump_if_asked("degenerate", img);
  EXPECT_GT(channel(img, 48, 44, 2), channel(img, 48, 44, 0));
}

// The near-camera fade (render.near_fade) scales a particle by clamp((depth − near)/fade): one
// 0.6 from the camera (near plane 0.1) with a fade of 2 keeps about a quarter of its light, so
// flying through a cloud does not pop; one far beyond the fade distance is untouched.
TEST(Renderer, NearFadeDimsOnlyParticlesCloseToTheCamera) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  auto centre = [&](float z, float size, float fade) {
    RenderSettings s = test::plain_settings();
    s.near_fade = fade;
    r->set_render_settings(s);
    RenderView v = base_view();
    v.starfield_seed = 0;
    v.particles = {particle({0, 0, z}, size, glm::vec3(0.8f), 1.0f, 1.0f)};
    r->render(v, 32, 32);
    return r->read_pixels();
  };
  const float near_off = channel(centre(-0.6f, 0.1f, 0.0f), 16, 16, 0);
  const float near_on = channel(centre(-0.6f, 0.1f, 2.0f), 16, 16, 0);
  ASSERT_GT(near_off, 0.3f);
  EXPECT_NEAR(near_on / near_off, 0.25f, 0.04f);
  EXPECT_EQ(compare_images(centre(-20.0f, 2.0f, 0.0f), centre(-20.0f, 2.0f, 2.0f)).max_diff, 0);
}

TEST(Renderer, ReversedAndStandardDepthAgree) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  r->set_sprites({scenes::soft_sprite(64)});
  ModelId wall = r->add_model(scenes::wall_model(80, 80, {0.5f, 0.5f, 0.55f, 1}, glm::vec3(0)));
  ModelId box = r->add_model(scenes::box_model({1.5f, 1.0f, 2.5f}, {0.7f, 0.3f, 0.2f, 1}, glm::vec3(0.05f)));
  Image images[2];
  for (int i = 0; i < 2; ++i) {
    RenderSettings s = test::plain_settings();
    s.reversed_z = i == 0;
    s.infinite_far = i == 0;
    r->set_render_settings(s);
    r->render(offset_scene(*r, wall, box, glm::dvec3(0)), 320, 180);
    images[i] = r->read_pixels();
  }
  ImageDiff d = compare_images(images[0], images[1]);
  if (!d.passed) write_failure_images("test_gfx_depth_modes", images[1], images[0]);
  EXPECT_TRUE(d.passed) << d.summary();
}

// All four depth modes linearise the copied depth the same way (the shader folds the sign of
// the denominator into its uniform), so soft particles cut by geometry look alike in each.
TEST(Renderer, SoftEdgesAgreeInEveryDepthMode) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  r->set_sprites({scenes::soft_sprite(64)});
  Image ref;
  for (int mode = 0; mode < 4; ++mode) {
    RenderSettings s = test::plain_settings();
    s.reversed_z = mode < 2;
    s.infinite_far = mode % 2 == 0;
    s.soft_override = int(SoftEdge::Linear);
    r->set_render_settings(s);
    CutScene cut = cut_scene(*r, SoftEdge::Linear);
    cut.view.camera.far_plane = 200.0;
    r->render(cut.view, cut.width, cut.height);
    Image img = r->read_pixels();
    if (mode == 0) {
      ref = img;
      continue;
    }
    ImageDiff d = compare_images(ref, img);
    EXPECT_TRUE(d.passed) << "depth mode " << mode << ": " << d.summary();
    EXPECT_LT(largest_step_along_row(img, cut.height / 2), 0.2f) << "depth mode " << mode;
  }
}

// The contrast curve at power 2 runs a squaring shader and at power 1 the plain linear one;
// both must match the general pow() curve next to them.
TEST(Renderer, ContrastShortcutsMatchTheGeneralCurve) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  r->set_sprites({scenes::soft_sprite(64)});
  auto render_power = [&](float power, SoftEdge method) {
    RenderSettings s = test::plain_settings();
    s.contrast_power = power;
    r->set_render_settings(s);
    CutScene cut = cut_scene(*r, method);
    r->render(cut.view, cut.width, cut.height);
    return r->read_pixels();
  };
  Image square = render_power(2.0f, SoftEdge::Contrast), general = render_power(2.0001f, SoftEdge::Contrast);
  ImageDiff d = compare_images(general, square);
  EXPECT_TRUE(d.passed) << d.summary();
  EXPECT_LE(d.max_diff, 2);
  Image identity = render_power(1.0f, SoftEdge::Contrast), linear = render_power(1.0f, SoftEdge::Linear);
  EXPECT_EQ(compare_images(linear, identity).max_diff, 0);
  Image near_identity = render_power(1.0001f, SoftEdge::Contrast);
  EXPECT_LE(compare_images(near_identity, identity).max_diff, 2);
  // And the curve does something at power 2.
  EXPECT_GE(compare_images(linear, square).max_diff, 8);
}

TEST(Renderer, DepthCopyOnlyWhenASoftParticleIsVisible) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  RenderView v = base_view();
  v.particles.push_back(particle({0, 0, -5}, 1.0f, glm::vec3(1), 1.0f, 0.0f, SoftEdge::Off));
  r->render(v, 32, 32);
  EXPECT_FALSE(r->last_stats().reads_depth());
  auto invisible = particle({0, 0, -5}, 1.0f, glm::vec3(0), 0.0f, 0.0f, SoftEdge::Linear);
  v.particles.push_back(invisible);
  r->render(v, 32, 32);
  EXPECT_FALSE(r->last_stats().reads_depth()) << "an invisible soft particle needs no depth read";
  EXPECT_EQ(r->last_stats().particles_drawn, 1);
  v.particles.push_back(particle({0, 0, -6}, 1.0f, glm::vec3(1), 0.5f, 0.0f, SoftEdge::Linear));
  r->render(v, 32, 32);
  EXPECT_FALSE(r->last_stats().reads_depth()) << "no opaque surface anywhere: soft edges change nothing";
  v.meshes.push_back({r->add_model(scenes::wall_model(40, 40, {0.5f, 0.5f, 0.5f, 1}, glm::vec3(0))), {0, 0, -6.5}});
  r->render(v, 32, 32);
  EXPECT_TRUE(r->last_stats().reads_depth()) << "the soft particle reaches the wall";
  EXPECT_EQ(r->last_stats().soft_shaded, 1);
  RenderSettings s = test::plain_settings();
  s.soft_override = int(SoftEdge::Off);
  r->set_render_settings(s);
  r->render(v, 32, 32);
  EXPECT_FALSE(r->last_stats().reads_depth()) << "the global override turns soft edges off";
}

// Particles no opaque surface comes within reach of skip the depth read, and must look exactly
// as with soft edges off; those that do reach one must still be soft. The reach test is
// conservative: a tilted axis-locked segment whose far end pierces the wall, a particle beside a
// wall that covers only half the screen, and one in front of it.
TEST(Renderer, SoftEdgesSkipParticlesNoSurfaceCanReach) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  r->set_sprites({scenes::soft_sprite(64)});
  const ModelId wall = r->add_model(scenes::wall_model(6, 20, {0.3f, 0.4f, 0.5f, 1}, glm::vec3(0)));
  RenderView v = base_view();
  v.meshes.push_back({wall, {-3.2, 0, -10}});  // the left half of the view, at depth 10
  auto render = [&](SoftEdge m) {
    RenderSettings s = test::plain_settings();
    s.soft_override = int(m);
    r->set_render_settings(s);
    r->render(v, 96, 64);
    return r->read_pixels();
  };
  v.meshes.push_back({r->add_model(scenes::box_model({1, 1, 1}, {0.6f, 0.3f, 0.3f, 1}, glm::vec3(0))), {1.7, 0, -5}});
  // One model of two cubes 4 apart (half size 0.5), like a ship's wing tips: its bounding box
  // spans the empty gap between them, its cover boxes do not.
  ModelData dumbbell = scenes::box_model({0.5f, 0.5f, 0.5f}, {0.3f, 0.6f, 0.3f, 1}, glm::vec3(0));
  MeshPrimitive other = dumbbell.primitives[0];
  for (glm::vec3& q : dumbbell.primitives[0].positions) q.x -= 2.0f;
  for (glm::vec3& q : other.positions) q.x += 2.0f;
  dumbbell.primitives.push_back(other);
  v.meshes.push_back({r->add_model(dumbbell), {3, -2.5, -9}});
  struct Case {
    const char* what;
    ParticleInstance p;
    bool reaches;         // with linear and contrast
    bool reaches_pushed;  // with the density methods, whose quads move E/2 or E towards the camera
  };
  // An axis-locked quad lies square to the view ray through its centre, so off the view axis it
  // tilts in depth. This one's centre is 1.1 in front of the wall, more than five times its
  // size, but its far end pierces the wall: only the tilt in the reach test catches it.
  const glm::vec3 centre(-4.0f, 0.0f, -8.9f), along = glm::normalize(glm::vec3(-centre.z, 0.0f, centre.x));
  ParticleInstance segment = particle(centre, 0.3f, glm::vec3(0.4f, 0.7f, 1.0f), 0.9f, 0.0f);
  segment.billboard = uint8_t(Billboard::AxisLocked);
  segment.axis[0] = 7.0f * along.x;
  segment.axis[2] = 7.0f * along.z;
  const glm::vec3 orange(1, 0.5f, 0.2f);
  Case cases[] = {
      {"in front of the wall", particle({-2.0f, 0.0f, -6.0f}, 0.8f, orange, 0.7f, 0.0f), false, false},
      {"beside the wall at its depth", particle({3.0f, 2.0f, -10.0f}, 0.8f, orange, 0.7f, 0.0f), false, false},
      {"grazing the wall", particle({-2.0f, 0.0f, -9.8f}, 0.8f, orange, 0.7f, 0.0f), true, true},
      {"just in front of the wall", particle({-2.0f, 0.0f, -9.5f}, 0.8f, orange, 0.7f, 0.0f), true, true},
      {"axis-locked segment piercing the wall", segment, true, true},
      // Behind the wall by 0.3: hidden unless pushed forward, which both density methods do.
      {"just behind the wall", particle({-2.0f, 0.0f, -10.3f}, 0.8f, orange, 0.7f, 0.0f), false, true},
      // The box at depth 4..6 covers it on screen but lies wholly in front: hidden, not softened.
      {"behind a nearer box", particle({3.1f, 0.0f, -9.0f}, 0.8f, orange, 0.7f, 0.0f), false, false},
      {"in the gap between two parts of one model", particle({3.0f, -2.5f, -9.0f}, 0.4f, orange, 0.7f, 0.0f), false, false},
      {"just in front of one part of that model", particle({5.0f, -2.5f, -8.3f}, 0.4f, orange, 0.7f, 0.0f), true, true},
  };
  for (const Case& c : cases) {
    v.particles = {c.p};
    Image off = render(SoftEdge::Off);
    test::dump_if_asked(std::string("reach_off_") + c.what, off);
    for (SoftEdge m : {SoftEdge::Linear, SoftEdge::Contrast, SoftEdge::AverageDensity, SoftEdge::DensityExtent}) {
      Image soft = render(m);
      test::dump_if_asked(std::string("reach_") + std::to_string(int(m)) + "_" + c.what, soft);
      bool pushed = m == SoftEdge::AverageDensity || m == SoftEdge::DensityExtent;
      bool reaches = pushed ? c.reaches_pushed : c.reaches;
      EXPECT_EQ(r->last_stats().soft_shaded, reaches ? 1 : 0) << c.what << ", method " << int(m);
      EXPECT_EQ(r->last_stats().reads_depth(), reaches) << c.what << ", method " << int(m);
      if (!reaches) {
        EXPECT_EQ(compare_images(off, soft).max_diff, 0) << c.what << ", method " << int(m);
      } else if (m == SoftEdge::Linear || (m == SoftEdge::DensityExtent && !c.reaches)) {
        EXPECT_GT(compare_images(off, soft).max_diff, 4) << c.what << ": soft edges must show";
      }
    }
  }
}

// Particles wholly outside the frustum's sides are not uploaded; one whose centre is off screen
// but whose quad (or axis-locked segment) reaches in is kept and shows at the edge.
TEST(Renderer, CullsOnlyParticlesWhollyOffScreen) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  RenderView v = base_view();
  const float tan_x = std::tan(0.45f) * 1.0f;  // square 32×32 view: horizontal half-angle = vertical
  const float edge = 10.0f * tan_x;              // the right edge at depth 10
  v.particles.push_back(particle({edge + 3.0f, 0, -10}, 1.0f, glm::vec3(1), 1.0f, 0.0f));   // off by 2 quad sizes
  v.particles.push_back(particle({0, -edge - 3.0f, -10}, 1.0f, glm::vec3(1), 1.0f, 0.0f));  // below
  v.particles.push_back(particle({edge + 0.5f, 0, -10}, 1.0f, glm::vec3(1, 0, 0), 1.0f, 0.0f));  // reaches in
  ParticleInstance beam = particle({-edge - 2.0f, 5.0f, -10}, 0.3f, glm::vec3(0, 1, 0), 1.0f, 1.0f);
  beam.billboard = uint8_t(Billboard::AxisLocked);
  beam.axis[0] = 6.0f;  // centre off the left edge, the segment runs 1 unit into the view
  v.particles.push_back(beam);
  r->render(v, 32, 32);
  EXPECT_EQ(r->last_stats().culled_offscreen, 2);
  EXPECT_EQ(r->last_stats().particles_drawn, 2);
  Image img = r->read_pixels();
  EXPECT_GT(channel(img, 31, 16, 0), 0.3f) << "the red particle reaching in from the right";
  float green = 0;
  for (int y = 0; y < 32; ++y) green = std::max(green, channel(img, 0, y, 1));
  EXPECT_GT(green, 0.3f) << "the beam reaching in from the left";
}

// Past the particles one draw can pull, the farthest are left out and counted.
TEST(Renderer, KeepsTheNearestParticlesPastTheDrawLimit) {
  REQUIRE_CONTEXT();
  RendererDesc d;
  d.offscreen = true;
  d.max_particles_per_draw = 2;
  Renderer r(d);
  r.set_render_settings(test::plain_settings());
  RenderView v = base_view();
  v.particles.push_back(particle({-1.2f, 0, -8}, 0.5f, glm::vec3(1, 0, 0), 1.0f, 0.0f));   // far: left out
  v.particles.push_back(particle({0, 0, -5}, 0.5f, glm::vec3(0, 1, 0), 1.0f, 0.0f));
  v.particles.push_back(particle({0.8f, 0, -4}, 0.5f, glm::vec3(0, 0, 1), 1.0f, 0.0f));
  r.render(v, 64, 64);
  EXPECT_EQ(r.last_stats().over_draw_limit, 1);
  Image img = r.read_pixels();
  // Pixels of one pure primary each (the stars behind are whitish).
  int pure[3] = {};
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < 3; ++c)
        pure[c] += channel(img, x, y, c) > 0.5f && channel(img, x, y, (c + 1) % 3) < 0.1f &&
                   channel(img, x, y, (c + 2) % 3) < 0.1f;
  EXPECT_EQ(pure[0], 0) << "the farthest particle is the one left out";
  EXPECT_GT(pure[1], 10);
  EXPECT_GT(pure[2], 10);
  // The one left out is the only soft particle, right in front of a wall: with it gone nothing
  // drawn needs the depth copy or the soft program.
  v.particles[0].soft_edge = uint8_t(SoftEdge::Linear);
  v.meshes.push_back({r.add_model(scenes::wall_model(40, 40, {0.5f, 0.5f, 0.5f, 1}, glm::vec3(0))), {0, 0, -8.2}});
  r.render(v, 64, 64);
  EXPECT_EQ(r.last_stats().over_draw_limit, 1);
  EXPECT_EQ(r.last_stats().soft_shaded, 0);
  EXPECT_FALSE(r.last_stats().reads_depth());
  v.particles[1].soft_edge = uint8_t(SoftEdge::Linear);
  v.particles[1].pos[2] = -7.9f;  // now the middle one, kept, is soft next to the wall
  r.render(v, 64, 64);
  EXPECT_EQ(r.last_stats().soft_shaded, 1);
  EXPECT_TRUE(r.last_stats().reads_depth());
}

// The benchmark's instruments: the occlusion query counts the samples the particle draw
// blends (the whole quad that passes the depth test, transparent corners included), and the
// pass timer reports a time only when asked.
TEST(Renderer, CountsBlendedFragmentsAndTimesThePassOnRequest) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  RenderView v = base_view();
  v.particles.push_back(particle({0, 0, -5}, 1.0f, glm::vec3(1), 0.5f, 0.0f));
  r->render(v, 64, 64);
  EXPECT_EQ(r->last_stats().particle_fragments, -1);
  EXPECT_EQ(r->last_stats().particle_pass_gpu_ms, -1);
  r->count_particle_fragments(true);
  r->time_gpu_passes(true);
  r->render(v, 64, 64);
  const double half = 1.0 / (5.0 * std::tan(0.45)) * 32.0;  // quad half-size in pixels
  EXPECT_NEAR(double(r->last_stats().particle_fragments), 4.0 * half * half, 0.1 * 4.0 * half * half);
  EXPECT_GE(r->last_stats().particle_pass_gpu_ms, 0.0);
  v.meshes.push_back({r->add_model(scenes::wall_model(40, 40, {0.5f, 0.5f, 0.5f, 1}, glm::vec3(0))), {0, 0, -4}});
  r->render(v, 64, 64);
  EXPECT_EQ(r->last_stats().particle_fragments, 0) << "behind the wall nothing is blended";
  r->count_particle_fragments(false);
  r->time_gpu_passes(false);
  r->render(v, 64, 64);
  EXPECT_EQ(r->last_stats().particle_pass_gpu_ms, -1);
}

TEST(Renderer, SortingPutsTheNearParticleOnTop) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  RenderView v = base_view();
  // Input order: near red first, far green second; unsorted, green ends up over red.
  v.particles.push_back(particle({0, 0, -5}, 1.0f, glm::vec3(1, 0, 0), 1.0f, 0.0f));
  v.particles.push_back(particle({0, 0, -8}, 2.0f, glm::vec3(0, 1, 0), 1.0f, 0.0f));
  r->render(v, 32, 32);
  Image sorted = r->read_pixels();
  EXPECT_GT(channel(sorted, 16, 16, 0), 0.9f);
  EXPECT_EQ(r->last_stats().sorted, 2);
  RenderSettings s = test::plain_settings();
  s.sorting = RenderSettings::Sorting::Off;
  r->set_render_settings(s);
  r->render(v, 32, 32);
  Image unsorted = r->read_pixels();
  EXPECT_GT(channel(unsorted, 16, 16, 1), 0.9f);
  EXPECT_EQ(r->last_stats().sorted, 0);
}

TEST(Renderer, ClusterSortingOrdersWholeClusters) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  RenderView v = base_view();
  // Cluster 1 = {red at 5, blue at 9}, mean 7; cluster 0 = {green at 8}. Per cluster: green,
  // then cluster 1 in its own order (red, blue), so blue ends on top. Per particle: blue,
  // green, red, so red ends on top.
  auto red = particle({0, 0, -5}, 1.0f, glm::vec3(1, 0, 0), 1.0f, 0.0f);
  auto blue = particle({0, 0, -9}, 3.0f, glm::vec3(0, 0, 1), 1.0f, 0.0f);
  auto green = particle({0, 0, -8}, 2.0f, glm::vec3(0, 1, 0), 1.0f, 0.0f);
  red.cluster = blue.cluster = 1;
  green.cluster = 0;
  v.particles = {red, blue, green};
  RenderSettings s = test::plain_settings();
  s.sorting = RenderSettings::Sorting::Cluster;
  r->set_render_settings(s);
  r->render(v, 32, 32);
  Image by_cluster = r->read_pixels();
  EXPECT_GT(channel(by_cluster, 16, 16, 2), 0.9f);
  EXPECT_EQ(r->last_stats().sorted, 3);
  s.sorting = RenderSettings::Sorting::Full;
  r->set_render_settings(s);
  r->render(v, 32, 32);
  Image full = r->read_pixels();
  EXPECT_GT(channel(full, 16, 16, 0), 0.9f);
}

TEST(Renderer, AxisLockedBillboardStretchesAlongItsAxis) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  RenderView v = base_view();
  auto beam = particle({0, 0, -10}, 0.2f, glm::vec3(0.3f, 0.6f, 1.0f), 1.0f, 1.0f);
  beam.billboard = uint8_t(Billboard::AxisLocked);
  beam.axis[0] = 8.0f;  // a horizontal segment 8 units long
  v.particles = {beam};
  r->render(v, 128, 64);
  Image img = r->read_pixels();
  test::dump_if_asked("axis_locked", img);
  EXPECT_GT(channel(img, 64 + 20, 32, 2), 0.9f) << "lit far along the axis";
  EXPECT_GT(channel(img, 64 - 20, 32, 2), 0.9f);
  EXPECT_LT(channel(img, 64, 32 + 12, 2), 0.2f) << "thin across it";
}

TEST(Renderer, PureAdditiveParticlesAreNotSorted) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  RenderView v = base_view();
  v.particles.push_back(particle({0, 0, -5}, 1.0f, glm::vec3(0.3f, 0, 0), 1.0f, 1.0f));
  v.particles.push_back(particle({0, 0, -8}, 2.0f, glm::vec3(0, 0.3f, 0), 1.0f, 1.0f));
  r->render(v, 32, 32);
  EXPECT_EQ(r->last_stats().sorted, 0);
  EXPECT_EQ(r->last_stats().particles_drawn, 2);
}

TEST(Renderer, RenderScaleKeepsTheOutputSize) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  RenderSettings s = test::plain_settings();
  s.scale = 0.5;
  r->set_render_settings(s);
  RenderView v = base_view();
  v.particles.push_back(particle({0, 0, -5}, 1.0f, glm::vec3(1), 1.0f, 0.0f));
  r->render(v, 80, 60);
  Image img = r->read_pixels();
  EXPECT_EQ(img.width, 80);
  EXPECT_EQ(img.height, 60);
  EXPECT_GT(channel(img, 40, 30, 0), 0.9f);
}

TEST(Renderer, HudDrawsQuadsLinesAndText) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  RenderView v = base_view();
  v.hud.quads.push_back({4, 4, 10, 10, glm::vec4(1, 0, 0, 1)});
  v.hud.lines.push_back({0, 40, 63, 40, 3, glm::vec4(0, 1, 0, 1)});
  v.hud.texts.push_back({20, 4, 2.0f, glm::vec4(1, 1, 1, 1), "HI"});
  r->render(v, 64, 64);
  Image img = r->read_pixels();
  test::dump_if_asked("hud", img);
  EXPECT_GT(channel(img, 8, 8, 0), 0.99f);
  EXPECT_LT(channel(img, 8, 8, 1), 0.01f);
  EXPECT_GT(channel(img, 30, 40, 1), 0.99f);
  int lit = 0;
  for (int y = 4; y < 34; ++y)
    for (int x = 20; x < 50; ++x) lit += channel(img, x, y, 0) > 0.9f && channel(img, x, y, 2) > 0.9f;
  EXPECT_GT(lit, 20) << "text pixels";
}

TEST(Renderer, ShaderReloadKeepsOldProgramsOnError) {
  REQUIRE_CONTEXT();
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("arcfire_shaders_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::copy(arc::data_root() + "/shaders", dir);
  RendererDesc d;
  d.offscreen = true;
  d.shader_dir = dir.string();
  Renderer r(d);
  r.set_render_settings(test::plain_settings());
  EXPECT_EQ(r.reload(), "");
  { std::ofstream(dir / "particle.frag") << "#version 330 core\nvoid main() { this is not glsl; }\n"; }
  std::string err = r.reload();
  EXPECT_NE(err.find("particle.frag"), std::string::npos) << err;
  RenderView v = base_view();
  v.particles.push_back(particle({0, 0, -5}, 1.0f, glm::vec3(1, 0, 0), 1.0f, 0.0f));
  r.render(v, 32, 32);
  Image img = r.read_pixels();
  EXPECT_GT(channel(img, 16, 16, 0), 0.9f) << "the old particle program still draws";
  fs::remove_all(dir);
}

TEST(Renderer, AppliesQualitySettings) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  Settings s = all_settings();
  s.apply_preset_file(arc::data_root() + "/assets/settings/quality.json", "low");
  s.set_from_text("render.depth_mode=standard", "--set");
  r->apply_settings(s);
  EXPECT_EQ(r->render_settings().soft_override, int(SoftEdge::Off));
  EXPECT_EQ(r->render_settings().sorting, RenderSettings::Sorting::Off);
  EXPECT_FALSE(r->render_settings().reversed_z);
  EXPECT_DOUBLE_EQ(r->render_settings().scale, 0.5);
  EXPECT_FALSE(r->render_settings().sky_exact);
  EXPECT_EQ(r->render_settings().sky_resolution, 128);
  s.apply_preset_file(arc::data_root() + "/assets/settings/quality.json", "high");
  r->apply_settings(s);
  EXPECT_EQ(r->render_settings().soft_override, -1);
  s.apply_preset_file(arc::data_root() + "/assets/settings/quality.json", "reference");
  r->apply_settings(s);
  EXPECT_TRUE(r->render_settings().sky_exact);
}

TEST(Renderer, StarfieldIsSeededAndVaried) {
  REQUIRE_CONTEXT();
  auto r = make_renderer();
  RenderView v = base_view();
  v.camera.orientation = glm::angleAxis(0.4, glm::normalize(glm::dvec3(0.3, 1, 0.1)));
  r->render(v, 480, 270);
  Image a = r->read_pixels();
  r->render(v, 480, 270);
  Image again = r->read_pixels();
  v.starfield_seed = 8;
  r->render(v, 480, 270);
  Image other = r->read_pixels();
  test::dump_if_asked("starfield", a);
  EXPECT_EQ(compare_images(a, again).max_diff, 0);
  EXPECT_FALSE(compare_images(a, other).passed);
  int faint = 0, bright = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      float l = channel(a, x, y, 0) + channel(a, x, y, 1) + channel(a, x, y, 2);
      faint += l > 0.15f && l < 0.8f;
      bright += l >= 0.8f;
    }
  EXPECT_GT(faint, 20);
  EXPECT_GT(bright, 3);
}

// render.sky = baked looks the nebula up in a cube map rendered once by the exact shader; the
// views look at the eight cube corners with a wide lens, so every face, edge and corner of the
// map is on screen. Compared in the float scene buffer (the stars are the same in both).
TEST(Renderer, BakedSkyMatchesTheExactNebula) {
  REQUIRE_CONTEXT();
  auto r = make_renderer(true);
  auto worst_error = [&](bool exact, int resolution, float* lowest) {
    RenderSettings s = test::plain_settings();
    s.sky_exact = exact;
    s.sky_resolution = resolution;
    r->set_render_settings(s);
    float err = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
      glm::dvec3 dir(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
      RenderView v = base_view();
      v.camera.fov_y_radians = 1.6;
      v.camera.orientation = glm::quatLookAt(glm::normalize(dir), glm::dvec3(0.3, 1, 0.2));
      RenderSettings e = s;
      e.sky_exact = true;
      r->set_render_settings(e);
      r->render(v, 160, 90);
      std::vector<float> want = r->read_pixels_float();
      r->set_render_settings(s);
      r->render(v, 160, 90);
      std::vector<float> got = r->read_pixels_float();
      for (size_t i = 0; i < want.size(); ++i) {
        if (i % 4 == 3) continue;
        err = std::max(err, std::abs(got[i] - want[i]));
        *lowest = std::min(*lowest, want[i]);
      }
    }
    return err;
  };
  float lowest = 1.0f;
  EXPECT_EQ(worst_error(true, 256, &lowest), 0.0f) << "exact against itself";
  ASSERT_GT(lowest, 0.005f) << "the nebula (at least its base tint) covers every pixel";
  float fine = worst_error(false, 256, &lowest), coarse = worst_error(false, 16, &lowest);
  // Three eighths of a step of an 8-bit output at the default resolution (measured 0.25: the
  // half-float texels); a wrong face orientation would be off by the nebula's own size, and
  // faces looked up without the edge alignment (sky.frag's u_edge_scale at 1) by 0.5 at the seams.
  EXPECT_LT(fine, 0.375f / 255.0f);
  EXPECT_GT(coarse, 2.0f * fine) << "a coarser cube map is measurably less exact";
}

// The sky alone, looking toward corner 0..7 of a cube around the camera (each view holds parts of
// three cube-map faces and their seams).
RenderView sky_corner_view(int corner) {
  const glm::dvec3 dir(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
  RenderView v = base_view();
  v.starfield_seed = 0;
  v.camera.fov_y_radians = 0.9;
  v.camera.orientation = glm::quatLookAt(glm::normalize(dir), glm::dvec3(0.3, 1, 0.2));
  return v;
}

// render.sky_grid = N looks the baked map up at the corners of N-pixel cells and interpolates:
// at 16 (the default) within 4/255 of the per-pixel lookup everywhere on screen (measured 3.3,
// where linear interpolation flattens the brightest crests of the nebula; the level views
// give 58–75 dB PSNR), no pixel left out (a hole would be black, off by the nebula's whole
// value), and a coarser grid is measurably further off.
TEST(Renderer, GridSkyMatchesThePerPixelLookup) {
  REQUIRE_CONTEXT();
  auto r = make_renderer(true);
  auto worst_error = [&](int grid) {
    float err = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
      const RenderView v = sky_corner_view(corner);
      RenderSettings s = test::plain_settings();
      s.sky_exact = false;
      r->set_render_settings(s);
      r->render(v, 650, 362);  // the last row and column of cells cut short
      const std::vector<float> want = r->read_pixels_float();
      s.sky_grid = grid;
      r->set_render_settings(s);
      r->render(v, 650, 362);  // the last row and column of cells cut short
      const std::vector<float> got = r->read_pixels_float();
      for (size_t i = 0; i < want.size(); ++i)
        if (i % 4 != 3) err = std::max(err, std::abs(got[i] - want[i]));
    }
    return err;
  };
  const float fine = worst_error(16), coarse = worst_error(64);
  EXPECT_LT(fine, 4.0f / 255.0f);
  EXPECT_GT(coarse, 2.0f * fine) << "a coarser grid is measurably less exact";
}

// An 8-bit scene draws the grid through a texture of its corners, read with bilinear filtering
// by llvmpipe's linear rasteriser (gfx/sky_pass.h). Against the per-pixel lookup, over eight
// views: within 7/255 (measured 6; the Gouraud grid 4) and 52 dB PSNR (measured 53.2, the
// Gouraud grid 59.9: the linear rasteriser's interpolation rounds down, so the nebula comes out
// 0.3/255 darker on average), stored bottom-up or top-down alike. Corners read half a texel off
// across gave 8/255 and 51.2 dB; mirrored rows or a wrong scale would be off by much more, and
// a hole would be black.
TEST(Renderer, CornerTextureSkyMatchesThePerPixelLookup) {
  REQUIRE_CONTEXT();
  Renderer bottom_up(RendererDesc{.offscreen = true, .top_down_scene = RendererDesc::TopDownScene::Off});
  Renderer top_down(RendererDesc{.offscreen = true, .top_down_scene = RendererDesc::TopDownScene::On});
  int worst[2][2] = {};          // [renderer][grid 16, 64]
  double squared[2][2] = {};     // summed squared error of the RGB channels, in 1/255
  double values = 0;
  int top_vs_bottom = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const RenderView v = sky_corner_view(corner);
    Image fine[2];
    for (int k = 0; k < 2; ++k) {
      Renderer& r = k ? top_down : bottom_up;
      RenderSettings s = test::plain_settings();
      r.set_render_settings(s);
      r.render(v, 650, 362);  // the last row and column of cells cut short
      const Image want = r.read_pixels();
      for (int g = 0; g < 2; ++g) {
        s.sky_grid = g ? 64 : 16;
        r.set_render_settings(s);
        r.render(v, 650, 362);
        const Image got = r.read_pixels();
        worst[k][g] = std::max(worst[k][g], compare_images(want, got).max_diff);
        for (size_t i = 0; i < want.rgba.size(); ++i)
          if (i % 4 != 3) squared[k][g] += std::pow(double(got.rgba[i]) - double(want.rgba[i]), 2.0);
        if (g == 0) fine[k] = got;
      }
      if (k == 0) values += double(want.rgba.size()) * 0.75;
    }
    test::dump_if_asked("corner_sky_" + std::to_string(corner), fine[1]);
    top_vs_bottom = std::max(top_vs_bottom, compare_images(fine[0], fine[1]).max_diff);
  }
  for (int k = 0; k < 2; ++k) {
    const double psnr = 10.0 * std::log10(255.0 * 255.0 * values / std::max(squared[k][0], 1e-9));
    std::printf("  %s: worst %d/255 and %.1f dB at 16-pixel cells, worst %d/255 at 64\n", k ? "top-down" : "bottom-up",
                worst[k][0], psnr, worst[k][1]);
    EXPECT_LE(worst[k][0], 7);
    EXPECT_GE(psnr, 52.0);
    EXPECT_GT(worst[k][1], 2 * worst[k][0]) << "a coarser grid is measurably less exact";
  }
  EXPECT_LE(top_vs_bottom, 1) << "the same picture stored either way";
}

// The scene's colour is not cleared (the sky writes every pixel), so nothing of one frame may
// show in the next: a frame after a screen-filling white one equals the same frame drawn by a
// fresh renderer, for every sky mode, odd sizes (cells cut at the edges), MSAA and HDR.
TEST(Renderer, NoPixelOfTheLastFrameShowsThroughTheSky) {
  REQUIRE_CONTEXT();
  RenderView white = test::dark_view();
  for (int i = 0; i < 6; ++i) {
    ParticleInstance p = scenes::particle({0.0f, 0.0f, -1.0f - 0.1f * float(i)}, 3.0f, glm::vec3(1.0f), 1.0f, 1.0f, SoftEdge::Off);
    white.particles.push_back(p);
  }
  const RenderView calm = test::dark_view();
  for (int mode = 0; mode < 5; ++mode) {
    RenderSettings s = test::plain_settings();
    s.size_clamp = 4.0f;
    s.sky_exact = mode == 1;
    s.sky_grid = mode == 2 ? 32 : mode == 3 ? 7 : 0;
    if (mode == 4) s.hdr = true, s.antialias = RenderSettings::Antialias::Msaa4;
    Renderer used(RendererDesc{.offscreen = true}), fresh(RendererDesc{.offscreen = true});
    used.set_render_settings(s);
    fresh.set_render_settings(s);
    used.render(white, 333, 197);
    const Image lit = used.read_pixels();
    EXPECT_GT(test::channel(lit, 166, 98, 0), 0.9f) << "mode " << mode << ": the white frame";
    used.render(calm, 333, 197);
    fresh.render(calm, 333, 197);
    const ImageDiff d = compare_images(fresh.read_pixels(), used.read_pixels());
    EXPECT_EQ(d.max_diff, 0) << "mode " << mode;
  }
}

}  // namespace
}  // namespace arc
