// The effect gallery as a grid of cells, checked on the laid-out HUD and the
// particle world without GL: its labels neither overlap nor leave a 1280x720 screen, and each
// hangs below its own effect; a level's lightning channel aimed with "to" stays between its two
// points; an effect with a "velocity" travels from its position and starts there again.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "game/render/hud_layout.h"
#include "game/render/render_view_builder.h"
#include "game/render/screen_projection.h"
#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

bool overlap(const HudBox& a, const HudBox& b) { return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1; }

// The frame as the game builds it (its camera and HUD), at 1280x720.
RenderView gallery_view(const Game& g) {
  RenderView v;
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, HudState{}, kWidth, kHeight, v);
  return v;
}

TEST(GalleryCells, LabelsNeitherOverlapNorLeaveTheScreen) {
  Game g = Game::load_level(test::repo("levels/gallery.json"), test::options());
  for (int tick = 1; tick <= 240; ++tick) {
    g.step(InputFrame{});
    if (tick != 1 && tick != 120 && tick != 240) continue;
    const HudLayer h = gallery_view(g).hud;
    ASSERT_GE(h.texts.size(), 14u);  // the objective and thirteen cell labels
    for (size_t i = 0; i < h.texts.size(); ++i) {
      const HudBox a = text_box(h.texts[i]);
      SCOPED_TRACE(h.texts[i].text);
      EXPECT_GE(a.x0, 0.0);
      EXPECT_GE(a.y0, 0.0);
      EXPECT_LE(a.x1, double(kWidth));
      EXPECT_LE(a.y1, double(kHeight));
      for (size_t j = i + 1; j < h.texts.size(); ++j)
        EXPECT_FALSE(overlap(a, text_box(h.texts[j]))) << "overlaps \"" << h.texts[j].text << "\"";
    }
  }
}

// Every labelled effect has its label below it and within its cell's width: labels are laid out
// by cell, not left to fall wherever the effect is.
TEST(GalleryCells, EachLabelHangsBelowItsEffect) {
  Game g = Game::load_level(test::repo("levels/gallery.json"), test::options());
  g.step(InputFrame{});
  const RenderView v = gallery_view(g);
  const HudLayer& h = v.hud;
  const Projector pr = Projector::of(v.camera, kWidth, kHeight);
  int labelled = 0;
  for (const EffectSpawnDef& e : g.world().level.effects) {
    if (e.label.empty()) continue;
    ++labelled;
    SCOPED_TRACE(e.label);
    auto it = std::find_if(h.texts.begin(), h.texts.end(), [&](const HudText& t) { return t.text == e.label; });
    ASSERT_NE(it, h.texts.end());
    const HudBox box = text_box(*it);
    glm::dvec2 at;
    ASSERT_TRUE(pr.project(e.position, at));
    EXPECT_GT(box.y0, at.y + 40.0);                              // below the effect
    EXPECT_LT(box.y0, at.y + 0.5 * kHeight / 3.0 + 40.0);        // and not in the next row
    EXPECT_LT(std::abs(0.5 * (box.x0 + box.x1) - at.x), kWidth / 8.0);  // in its column
  }
  EXPECT_EQ(labelled, 13);
}

// Visible particles of `g`, seen from `eye` looking down −Z, with their world positions.
std::vector<ParticleInstance> visible(const Game& g, const glm::dvec3& eye) {
  ParticleCamera cam;
  cam.position = eye;
  cam.fov_y_radians = 1.2;
  std::vector<ParticleInstance> out;
  g.world().particles->collect(cam, out);
  for (ParticleInstance& p : out)
    for (int k = 0; k < 3; ++k) p.pos[k] += float(eye[k]);
  return out;
}

std::string one_effect_level(const std::string& effect_json) {
  // The ship is required by the format; it waits far outside the view.
  return test::write_level("level_effect.json", test::level_text(
      R"({ "name": "Idle", "class": "viper", "team": "blue", "ai": "none", "position": [0, 0, 5000] })",
      "\n  \"effects\": [" + effect_json + "],"));
}

TEST(LevelEffects, LightningAimedWithToStaysBetweenItsPoints) {
  Game g = Game::load_level(one_effect_level(R"({ "effect": "lightning_beam", "position": [0, 0, 0],
      "to": [40, 0, 0], "repeat_ticks": 150 })"), test::options());
  for (int i = 0; i < 30; ++i) g.step(InputFrame{});
  float reach = 0.0f;
  int segments = 0;
  for (const ParticleInstance& p : visible(g, {20, 0, 120})) {
    if (p.billboard != uint8_t(Billboard::AxisLocked)) continue;
    ++segments;
    for (float end : {-0.5f, 0.5f}) {
      const float x = p.pos[0] + end * p.axis[0], y = p.pos[1] + end * p.axis[1], z = p.pos[2] + end * p.axis[2];
      EXPECT_GE(x, -0.5f);
      EXPECT_LE(x, 40.5f);
      EXPECT_LE(std::max(std::abs(y), std::abs(z)), 15.0f);  // guided to the line between the points
      reach = std::max(reach, x);
    }
  }
  EXPECT_GT(segments, 3);
  EXPECT_GT(reach, 32.0f);  // the cut is along the zigzag, so it ends a little short of 40 m
}

// The flame of a missile trail (pure burn, short-lived) marks where the moving emitter is.
float flame_extent(const Game& g, bool farthest) {
  float x = farthest ? -1e9f : 1e9f;
  for (const ParticleInstance& p : visible(g, {15, 0, 80}))
    if (p.burn > 0.99f) x = farthest ? std::max(x, p.pos[0]) : std::min(x, p.pos[0]);
  return x;
}

TEST(LevelEffects, MovingEffectTravelsAndStartsAgainWithEachSpawn) {
  Game g = Game::load_level(one_effect_level(R"({ "effect": "missile_trail", "position": [0, 0, 0],
      "orientation": [-90, 0, 0], "velocity": [30, 0, 0], "repeat_ticks": 60 })"), test::options());
  for (int i = 0; i < 50; ++i) g.step(InputFrame{});
  EXPECT_GT(flame_extent(g, true), 20.0f);  // 49 ticks at 30 m/s: 24.5 m
  for (int i = 0; i < 20; ++i) g.step(InputFrame{});
  // Tick 70: the second spawn (tick 61) is 4.5 m along; the first one's flame went with its owner.
  EXPECT_LT(flame_extent(g, true), 6.0f);
  EXPECT_GT(flame_extent(g, false), -6.0f);
}

}  // namespace
}  // namespace arc
