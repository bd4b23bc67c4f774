// HDR, tone mapping, bloom and anti-aliasing, headless through EGL (Mesa llvmpipe). They skip,
// with the reason, when no EGL context can be made.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "game/app/all_settings.h"
#include "gfx/color_space.h"
#include "gfx_test_util.h"
#include "core/data_root.h"

namespace arc {
namespace {

using scenes::particle;
using test::channel;

using test::dark_view;

std::unique_ptr<Renderer> make_renderer(bool float_scene, HdrFormat format = HdrFormat::Rgba16f) {
  RendererDesc d;
  d.offscreen = true;
  d.float_scene = float_scene;
  d.hdr_format = format;
  return std::make_unique<Renderer>(d);
}

RenderSettings hdr_settings(float bloom = 0.0f, RenderSettings::Antialias aa = RenderSettings::Antialias::Off) {
  RenderSettings s = test::plain_settings();
  s.hdr = true;
  s.bloom = bloom;
  s.antialias = aa;
  return s;
}

// Ilmonen eq. 3 in linear light, unclamped: result = fgc·alpha + (1 − alpha·(1 − burn))·background,
// with the sRGB-picked colours decoded first. The scene buffer is read as floats before the
// tone map; where the sum passes 1 it must stay above 1. `rel` is the buffer's precision.
void expect_equation3_in_float(Renderer& r, float rel) {
  const glm::vec3 bg_picked(0.9f, 0.8f, 0.95f), fg_picked(1.0f, 0.9f, 0.6f);
  const glm::vec3 bg = srgb_to_linear(bg_picked), fg = srgb_to_linear(fg_picked);
  const float alpha = 0.8f;
  ModelId wall = r.add_model(scenes::wall_model(100, 100, {0, 0, 0, 1}, bg_picked));
  float highest = 0.0f;
  for (float burn : {0.0f, 0.25f, 0.5f, 1.0f}) {
    RenderView v = dark_view();
    v.meshes.push_back({wall, {0, 0, -20}});
    v.particles.push_back(particle({0, 0, -10}, 2.0f, fg_picked, alpha, burn));
    r.render(v, 64, 64);
    const std::vector<float> px = r.read_pixels_float();
    const size_t centre = (32u * 64u + 32u) * 4u;
    for (int c = 0; c < 3; ++c) {
      const float expect = fg[c] * alpha + (1 - alpha * (1 - burn)) * bg[c];
      highest = std::max(highest, px[centre + size_t(c)]);
      EXPECT_NEAR(px[centre + size_t(c)], expect, expect * rel + 1e-4f) << "burn " << burn << " channel " << c;
    }
  }
  EXPECT_GT(highest, 1.3f) << "additive light goes past 1 instead of clipping";
}

TEST(Hdr, BurnBlendMatchesEquation3InFloatWithoutClamping) {
  REQUIRE_CONTEXT();
  auto r = make_renderer(true);  // RGBA16F: 11-bit mantissa
  r->set_render_settings(hdr_settings());
  expect_equation3_in_float(*r, 2e-3f);
}

TEST(Hdr, BurnBlendHoldsInBothSceneFormats) {
  REQUIRE_CONTEXT();
  auto r = make_renderer(false);  // the renderer's default, RGBA16F
  r->set_render_settings(hdr_settings());
  expect_equation3_in_float(*r, 2e-3f);
  r = make_renderer(false, HdrFormat::R11fG11fB10f);  // 6- and 5-bit mantissas: 1/32 relative
  r->set_render_settings(hdr_settings());
  expect_equation3_in_float(*r, 1.0f / 32.0f);
}

float aces_fit(float x) { return std::clamp(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f); }

// The resolve: sRGB(ACES(scene × exposure)) in the output, for an emissive wall of known colour.
TEST(Hdr, ToneMapAppliesExposureAndTheAcesFit) {
  REQUIRE_CONTEXT();
  auto r = make_renderer(false);
  const glm::vec3 picked(0.2f, 0.5f, 0.9f);
  ModelId wall = r->add_model(scenes::wall_model(100, 100, {0, 0, 0, 1}, picked));
  RenderView v = dark_view();
  v.meshes.push_back({wall, {0, 0, -20}});
  for (float exposure : {0.5f, 1.0f, 3.0f}) {
    RenderSettings s = hdr_settings();
    s.exposure = exposure;
    r->set_render_settings(s);
    r->render(v, 32, 32);
    Image img = r->read_pixels();
    for (int c = 0; c < 3; ++c) {
      const float expect = linear_to_srgb(aces_fit(srgb_to_linear(picked[c]) * exposure));
      EXPECT_NEAR(channel(img, 16, 16, c), expect, 1.5f / 255) << "exposure " << exposure << " channel " << c;
    }
  }
}

// A tiny particle far brighter than white glows around itself with bloom on; one below the
// threshold does not, and nothing glows with bloom off.
TEST(Hdr, BloomSpreadsOnlyLightAboveTheThreshold) {
  REQUIRE_CONTEXT();
  auto r = make_renderer(false);
  auto glow_at = [&](float intensity, float bloom) {
    RenderView v = dark_view();
    v.starfield_seed = 0;
    ParticleInstance p = particle({0, 0, -10}, 0.15f, glm::vec3(1), 1.0f, 1.0f);
    for (int c = 0; c < 3; ++c) p.color[c] = intensity;
    v.particles.push_back(p);
    r->set_render_settings(hdr_settings(bloom));
    r->render(v, 256, 256);
    Image img = r->read_pixels();
    float ring = 0;  // 12 to 20 pixels from the particle's centre, well outside its quad
    for (int dy = -20; dy <= 20; ++dy)
      for (int dx = -20; dx <= 20; ++dx) {
        const float d = std::sqrt(float(dx * dx + dy * dy));
        if (d >= 12 && d <= 20) ring = std::max(ring, channel(img, 128 + dx, 128 + dy, 0));
      }
    return ring;
  };
  const float dark = glow_at(0.0f, 0.0f);
  EXPECT_GT(glow_at(40.0f, RenderSettings::kBloomHigh), dark + 10.0f / 255) << "bright light blooms";
  EXPECT_LE(glow_at(40.0f, 0.0f), dark + 1.0f / 255) << "no bloom when it is off";
  EXPECT_LE(glow_at(0.5f, RenderSettings::kBloomHigh), dark + 1.0f / 255) << "light below the threshold does not";
}

// A lit ship's outline against black space: per column, the largest step between vertically
// neighbouring pixels; averaged over the columns an edge crosses. Aliased edges step by the
// full contrast in one pixel, anti-aliased ones spread it over two or more.
float mean_edge_step(const Image& img) {
  double sum = 0;
  int columns = 0;
  for (int x = 0; x < img.width; ++x) {
    float worst = 0;
    for (int y = 1; y < img.height; ++y) {
      float step = 0;
      for (int c = 0; c < 3; ++c) step += std::abs(channel(img, x, y, c) - channel(img, x, y - 1, c)) / 3.0f;
      worst = std::max(worst, step);
    }
    if (worst > 0.1f) {
      sum += worst;
      ++columns;
    }
  }
  return columns ? float(sum / columns) : 0.0f;
}

RenderView ship_view(Renderer& r) {
  RenderView v = dark_view();
  v.starfield_seed = 0;
  v.light_color = glm::vec3(1.4f);
  v.ambient = glm::vec3(0.3f);
  v.light_direction = glm::vec3(1.0f, -0.3f, -0.3f);  // from the side: no highlight on the wall
  ModelId ship = r.add_model(load_model(arc::data_root() + "/assets/models/viper.glb"));
  // A black wall behind it hides the stars, whose single-pixel points would dominate the measure.
  v.meshes.push_back({r.add_model(scenes::wall_model(400, 400, {0, 0, 0, 1}, glm::vec3(0))), {0, 0, -80}});
  v.meshes.push_back({ship, {0, 0, -14}, glm::angleAxis(glm::radians(7.0), glm::dvec3(0, 0, 1)) *
                                             glm::angleAxis(glm::radians(80.0), glm::dvec3(0, 1, 0))});
  return v;
}

TEST(Antialias, SmoothsTheStairStepsOfAShipEdge) {
  REQUIRE_CONTEXT();
  auto r = make_renderer(false);
  const RenderView v = ship_view(*r);
  auto step = [&](bool hdr, RenderSettings::Antialias aa) {
    RenderSettings s = hdr_settings(0.0f, aa);
    s.hdr = hdr;
    r->set_render_settings(s);
    r->render(v, 320, 180);
    Image img = r->read_pixels();
    test::dump_if_asked(std::string("ship_edge_") + (hdr ? "hdr_" : "ldr_") + std::to_string(int(aa)), img);
    return mean_edge_step(img);
  };
  for (bool hdr : {true, false}) {
    const float off = step(hdr, RenderSettings::Antialias::Off);
    ASSERT_GT(off, 0.2f) << "the ship's outline is in the picture";
    EXPECT_LT(step(hdr, RenderSettings::Antialias::Fxaa), 0.85f * off) << "hdr " << hdr;
    EXPECT_LT(step(hdr, RenderSettings::Antialias::Msaa4), 0.85f * off) << "hdr " << hdr;
    EXPECT_LT(step(hdr, RenderSettings::Antialias::Msaa2), 0.9f * off) << "hdr " << hdr;
  }
}

// The HUD draws after the filter: every HUD pixel is the same with FXAA or MSAA as without,
// while the ship's edge under it does change.
TEST(Antialias, LeavesHudPixelsUnchanged) {
  REQUIRE_CONTEXT();
  auto r = make_renderer(false);
  RenderView v = ship_view(*r);
  v.hud.texts.push_back({40, 60, 2.0f, glm::vec4(1, 1, 0.2f, 1), "TARGET 300 M"});
  v.hud.lines.push_back({20, 20, 300, 150, 1.5f, glm::vec4(0.2f, 1, 0.4f, 1)});
  v.hud.quads.push_back({150, 80, 30, 12, glm::vec4(1, 0.3f, 0.3f, 1)});
  RenderView bare = v;
  bare.hud = HudLayer{};
  auto frame = [&](const RenderView& view, RenderSettings::Antialias aa) {
    r->set_render_settings(hdr_settings(0.0f, aa));
    r->render(view, 320, 180);
    return r->read_pixels();
  };
  const Image plain = frame(v, RenderSettings::Antialias::Off), scene = frame(bare, RenderSettings::Antialias::Off);
  for (auto aa : {RenderSettings::Antialias::Fxaa, RenderSettings::Antialias::Msaa4}) {
    const Image filtered = frame(v, aa);
    int hud_pixels = 0, scene_changed = 0;
    for (size_t i = 0; i < plain.rgba.size(); i += 4) {
      const bool hud = !std::equal(&plain.rgba[i], &plain.rgba[i] + 3, &scene.rgba[i]);
      const bool same = std::equal(&plain.rgba[i], &plain.rgba[i] + 3, &filtered.rgba[i]);
      // Opaque HUD pixels (the colour is the HUD's whatever lies under it) must not change.
      if (hud && plain.rgba[i] > 200 && plain.rgba[i + 1] > 200 && plain.rgba[i + 2] < 80) {
        ++hud_pixels;
        EXPECT_TRUE(same) << "text pixel " << i / 4 << " changed under anti-aliasing " << int(aa);
      }
      scene_changed += !hud && !same;
    }
    EXPECT_GT(hud_pixels, 40) << "the text is on screen";
    EXPECT_GT(scene_changed, 20) << "the filter did change the scene";
  }
}

// With MSAA the particles test against, and soften by, a single-sample copy of the resolved
// depth: a soft particle cutting a wall shows no hard line, as without MSAA.
TEST(Antialias, MsaaKeepsSoftEdges) {
  REQUIRE_CONTEXT();
  auto r = make_renderer(false);
  r->set_sprites({scenes::soft_sprite(64)});
  RenderView v = dark_view();
  v.starfield_seed = 0;
  ModelId wall = r->add_model(scenes::wall_model(60, 60, {0, 0, 0, 1}, glm::vec3(0.05f, 0.05f, 0.1f)));
  v.meshes.push_back({wall, {0, 0, -12}, glm::angleAxis(glm::radians(60.0), glm::dvec3(0, 1, 0))});
  auto largest_step = [&](SoftEdge soft) {
    v.particles = {particle({0, 0, -12}, 3.0f, glm::vec3(1.0f, 0.8f, 0.5f), 0.9f, 0.0f, soft)};
    r->set_render_settings(hdr_settings(0.0f, RenderSettings::Antialias::Msaa4));
    r->render(v, 200, 100);
    EXPECT_EQ(r->last_stats().reads_depth(), soft != SoftEdge::Off);
    Image img = r->read_pixels();
    float worst = 0;
    for (int x = 61; x < 138; ++x)
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(channel(img, x, 50, c) - channel(img, x - 1, 50, c)));
    return worst;
  };
  const float hard = largest_step(SoftEdge::Off), soft = largest_step(SoftEdge::Linear);
  EXPECT_GT(hard, 0.25f) << "the wall cuts the hard particle";
  EXPECT_LT(soft, 0.5f * hard);
}

TEST(Hdr, QualityPresetsSetTheLook) {
  REQUIRE_CONTEXT();
  auto r = make_renderer(false);
  const std::string quality = arc::data_root() + "/assets/settings/quality.json";
  Settings s = all_settings();
  r->apply_settings(s);
  EXPECT_FALSE(r->render_settings().hdr) << "the default keeps the 8-bit scene";
  EXPECT_EQ(r->render_settings().antialias, RenderSettings::Antialias::Off);
  s.apply_preset_file(quality, "high");
  r->apply_settings(s);
  EXPECT_TRUE(r->render_settings().hdr);
  EXPECT_EQ(r->render_settings().antialias, RenderSettings::Antialias::Msaa2)
      << "high multisamples (chosen by the tradeoffs bench)";
  EXPECT_FLOAT_EQ(r->render_settings().bloom, RenderSettings::kBloomHigh);
  s.apply_preset_file(quality, "low");
  r->apply_settings(s);
  EXPECT_FALSE(r->render_settings().hdr);
  EXPECT_EQ(r->render_settings().bloom, 0.0f);
  s.apply_preset_file(quality, "reference");
  s.set_from_text("render.exposure=2.5", "--set");
  r->apply_settings(s);
  EXPECT_TRUE(r->render_settings().hdr);
  EXPECT_EQ(r->render_settings().antialias, RenderSettings::Antialias::Msaa4);
  EXPECT_FLOAT_EQ(r->render_settings().bloom, RenderSettings::kBloomHigh);
  EXPECT_FLOAT_EQ(r->render_settings().exposure, 2.5f);
}

TEST(ColorSpace, SrgbRoundTripsAndPremultipliesInLinearLight) {
  for (int i = 0; i <= 255; ++i) EXPECT_NEAR(linear_to_srgb(srgb_to_linear(i / 255.0f)), i / 255.0f, 1e-5f);
  EXPECT_NEAR(srgb_to_linear(0.5f), 0.21404f, 1e-4f);
  Image straight;
  straight.width = 2;
  straight.height = 1;
  straight.rgba = {255, 128, 0, 128, 10, 200, 255, 0};
  Image texels = premultiply_linear_srgb(straight);
  EXPECT_TRUE(texels.premultiplied);
  // Decoding what is stored gives linear(c)·a: 0.5·1 for the red, not linear(0.5·1).
  EXPECT_NEAR(srgb_to_linear(texels.rgba[0] / 255.0f), 128 / 255.0f, 2.5e-3f);
  EXPECT_NEAR(srgb_to_linear(texels.rgba[1] / 255.0f), srgb_to_linear(128 / 255.0f) * 128 / 255.0f, 1.5e-3f);
  EXPECT_EQ(texels.rgba[3], 128);
  EXPECT_EQ(texels.rgba[4], 0);  // zero alpha, zero colour
  // A premultiplied white sprite gives the same texels as its straight form.
  Image white_pm = straight, white = straight;
  white.rgba = {255, 255, 255, 90, 255, 255, 255, 255};
  white_pm.rgba = {90, 90, 90, 90, 255, 255, 255, 255};
  white_pm.premultiplied = true;
  EXPECT_EQ(premultiply_linear_srgb(white_pm).rgba, premultiply_linear_srgb(white).rgba);
}

}  // namespace
}  // namespace arc
