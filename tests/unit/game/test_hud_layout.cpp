// tests/unit/game/test_hud_layout.cpp — the HUD's panels at every window size from 640x360 to
// 3840x2160 (hud_panel_check.h), with the F3 frame figures on: none overlaps another, none leaves
// the screen, and none covers the own ship in the chase view (game/render/hud_layout.h).
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
#include "hud_panel_check.h"
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
  s.show_fps = true;  // F3, with the renderer's longest particle figures
  s.fps = 144;
  s.frame_stats = "particles 123456, 12345 reduced | 1234 draws | 12.5 screens blended (48.0 before the budget)";
  return s;
}

TEST(HudLayout, PanelsNeitherOverlapNorLeaveTheScreenAtEverySize) {
  Game g = busy_game();
  ASSERT_TRUE(g.world().ships[0].target);
  test::check_hud_panels(g.world(), busy_state(),
                         {"frame stats", "objective", "kill feed", "own bars", "weapon", "target panel", "radar",
                          "notice", "error banner"});
}

// A campaign mission with its objective rows under the objective line, F3 on: the frame
// figures stay clear of the objective, its rows and the kill feed at the top left.
TEST(HudLayout, TheFrameFiguresClearTheObjectivesAtEverySize) {
  Game g = Game::load_level(test::repo("levels/campaign/03_escort.json"), test::options());
  g.step(InputFrame{}, {Command::TargetNearest});
  ASSERT_TRUE(g.world().mission);
  test::check_hud_panels(g.world(), busy_state(), {"frame stats", "objective", "objectives", "own bars", "radar"});
}

// The chase view draws the own ship in the lower middle of the screen; no panel lies over the
// screen box of its model's bounds, at any size.
TEST(HudLayout, NoPanelCoversTheOwnShipInTheChaseView) {
  Game g = busy_game();
  const World& w = g.world();
  ASSERT_EQ(w.camera_mode, CameraMode::Chase);
  const Ship& me = w.ship(w.player);
  const ModelData model = load_model(test::repo(w.model_paths[me.model.index()]));
  for (auto [width, height] : test::kHudSizes) {
    RenderView v;
    const std::vector<HudPanelBox> panels = test::hud_panels(w, busy_state(), width, height, &v);
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
      EXPECT_FALSE(overlap) << test::box_text(p) << " covers the own ship [" << int(ship.x0) << "," << int(ship.y0) << " - "
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
  test::check_hud_panels(w, state, {"training", "kill feed", "own bars", "weapon", "target panel", "radar", "notice", "error banner"});
}

}  // namespace
}  // namespace arc
