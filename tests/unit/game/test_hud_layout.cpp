// tests/unit/game/test_hud_layout.cpp — the HUD's panels at every window size from 640x360 to
// 3840x2160: none overlaps another, none leaves the screen, and none covers the own ship in the
// chase view (game/render/hud_layout.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "assets/model.h"
#include "game/render/hud_layout.h"
#include "game/render/screen_projection.h"
#include "game/render/render_view_builder.h"
#include "game/sim/level_start.h"
#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

// The firing range with every panel showing: a target, a kill in the feed, the longest
// objective of the shipped levels, a notice and a reload error.
Game busy_game() {
  const std::string level = test::write_level(
      "hud_layout.json",
      test::level_text(R"({ "name": "Player", "class": "viper", "team": "blue", "player": true },
        { "name": "Lancer-2", "class": "warden", "team": "red", "ai": "none", "position": [40, 10, -300] },
        { "name": "Drone", "class": "dart", "team": "red", "ai": "none", "position": [-200, 0, -500] })"));
  Game g = Game::load_level(level, test::options());
  g.world_mut().level.objective = "Destroy all hostile ships before they reach the relay station";
  g.step(InputFrame{}, {Command::TargetNearest});
  World& w = g.world_mut();
  w.ships[2].hull = -1;
  w.ships[2].last_attacker = ShipId::from_index(0);
  g.step(InputFrame{});
  return g;
}

HudState busy_state() {
  HudState s;
  s.notice = "Recording stopped: replays/2026-11-28_12-00-00.replay";
  s.error_banner = "assets/ships/viper.json:20:14: beam range must be positive (reload kept the old values)";
  return s;
}

std::string box_text(const HudPanelBox& p) {
  return p.name + " [" + std::to_string(int(p.box.x0)) + "," + std::to_string(int(p.box.y0)) + " - " +
         std::to_string(int(p.box.x1)) + "," + std::to_string(int(p.box.y1)) + "]";
}

// Every panel of `want` is drawn, and no panel overlaps another or leaves the screen, at each size.
void check_panels(const World& w, const HudState& state, const std::vector<const char*>& want) {
  for (auto [width, height] : {std::pair{640, 360}, {1280, 720}, {1920, 1080}, {3840, 2160}}) {
    RenderView v;
    build_render_view(w, {}, 1.0, CameraSettings{}, state, width, height, v);
    std::vector<HudPanelBox> panels;
    layout_hud(w, v.camera, state, 1.0, width, height, v.hud, &panels);
    std::vector<std::string> names;
    for (const HudPanelBox& p : panels) names.push_back(p.name);
    for (const char* name : want)
      EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name << " at " << width << "x" << height;
    for (const HudPanelBox& p : panels)
      if (p.name == "radar") EXPECT_GE(p.box.y1 - p.box.y0, 0.15 * height) << "radar at " << width << "x" << height;
    for (size_t i = 0; i < panels.size(); ++i) {
      const HudBox& a = panels[i].box;
      EXPECT_TRUE(a.x0 >= 0 && a.y0 >= 0 && a.x1 <= width && a.y1 <= height)
          << box_text(panels[i]) << " leaves the " << width << "x" << height << " screen";
      for (size_t j = i + 1; j < panels.size(); ++j) {
        const HudBox& b = panels[j].box;
        const bool overlap = a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
        EXPECT_FALSE(overlap) << box_text(panels[i]) << " overlaps " << box_text(panels[j]) << " at " << width << "x"
                              << height;
      }
    }
  }
}

TEST(HudLayout, PanelsNeitherOverlapNorLeaveTheScreenAtEverySize) {
  Game g = busy_game();
  ASSERT_TRUE(g.world().ships[0].target);
  check_panels(g.world(), busy_state(),
               {"objective", "kill feed", "own bars", "weapon", "target panel", "radar", "notice", "error banner"});
}

// The chase view draws the own ship in the lower middle of the screen; no panel lies over the
// screen box of its model's bounds, at any size.
TEST(HudLayout, NoPanelCoversTheOwnShipInTheChaseView) {
  Game g = busy_game();
  const World& w = g.world();
  ASSERT_EQ(w.camera_mode, CameraMode::Chase);
  const Ship& me = w.ship(w.player);
  const ModelData model = load_model(test::repo(w.model_paths[me.model.index()]));
  for (auto [width, height] : {std::pair{640, 360}, {1280, 720}, {1920, 1080}, {3840, 2160}}) {
    RenderView v;
    build_render_view(w, {}, 1.0, CameraSettings{}, busy_state(), width, height, v);
    std::vector<HudPanelBox> panels;
    layout_hud(w, v.camera, busy_state(), 1.0, width, height, v.hud, &panels);
    const Projector pr = Projector::of(v.camera, width, height);
    HudBox ship{1e9, 1e9, -1e9, -1e9};
    for (int c = 0; c < 8; ++c) {
      const glm::dvec3 corner(c & 1 ? model.bounds_max.x : model.bounds_min.x, c & 2 ? model.bounds_max.y : model.bounds_min.y,
                              c & 4 ? model.bounds_max.z : model.bounds_min.z);
      glm::dvec2 px;
      ASSERT_TRUE(pr.project(me.position + me.orientation * corner, px)) << "own ship behind the chase camera";
      ship = {std::min(ship.x0, px.x), std::min(ship.y0, px.y), std::max(ship.x1, px.x), std::max(ship.y1, px.y)};
    }
    EXPECT_GT(ship.y0, height * 0.5) << "the own ship in the lower half at " << width << "x" << height;
    for (const HudPanelBox& p : panels) {
      const HudBox& a = p.box;
      const bool overlap = a.x0 < ship.x1 && ship.x0 < a.x1 && a.y0 < ship.y1 && ship.y0 < a.y1;
      EXPECT_FALSE(overlap) << box_text(p) << " covers the own ship [" << int(ship.x0) << "," << int(ship.y0) << " - "
                            << int(ship.x1) << "," << int(ship.y1) << "] at " << width << "x" << height;
    }
  }
}

// The training level at its longest prompt, with a target, a kill in the feed, a notice and an
// error: the prompt takes the objective's place and overlaps nothing.
TEST(HudLayout, TheTrainingPromptOverlapsNothingAtEverySize) {
  Game g = Game::load_level(test::repo("levels/training.json"), test::options());
  World& w = g.world_mut();
  size_t longest = 0;
  for (size_t i = 0; i < w.level.training.steps.size(); ++i)
    if (w.level.training.steps[i].prompt.size() > w.level.training.steps[longest].prompt.size()) longest = i;
  for (Ship& s : w.ships) arrive_ship(w, s);
  w.training->step = int32_t(longest);
  g.step(InputFrame{}, {Command::TargetNearest});
  w.ships[2].hull = -1;
  w.ships[2].last_attacker = w.player;
  g.step(InputFrame{});
  ASSERT_TRUE(w.ship(w.player).target);
  HudState state = busy_state();
  state.key_names = {{"order_attack", "LEFT_SHIFT"}, {"order_cover", "RIGHT_CONTROL"}};
  check_panels(w, state, {"training", "kill feed", "own bars", "weapon", "target panel", "radar", "notice", "error banner"});
}

}  // namespace
}  // namespace arc
