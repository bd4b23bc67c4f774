// tests/unit/game/test_hud_net.cpp — a network match's HUD (game/render/hud_net.h) at every
// window size from 640x360 to 3840x2160: the F3 net figures beside the other panels, and the
// held scoreboard with eight pilots (the notice stays with it), overlap nothing and stay on screen; the names over ships
// and in the kill feed are the pilots'.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "game/render/hud_layout.h"
#include "game/render/render_view_builder.h"
#include "game/sim/world.h"
#include "hud_panel_check.h"
#include "test_helpers.h"

namespace arc {
namespace {

Game net_game() {
  const std::string level = test::write_level(
      "hud_net.json",
      test::level_text(R"({ "name": "Player", "class": "viper", "team": "blue", "player": true },
        { "name": "Lancer-2", "class": "warden", "team": "red", "ai": "none", "position": [40, 10, -300] },
        { "name": "Drone", "class": "dart", "team": "red", "ai": "none", "position": [-200, 0, -500] })"));
  Game g = Game::load_level(level, test::options());
  g.world_mut().level.objective = "Destroy all hostile ships before they reach the relay station";
  g.step(InputFrame{}, {Command::TargetNearest});
  World& w = g.world_mut();
  w.ships[2].hull = -1;
  w.ships[2].last_attacker = ShipId::from_index(1);
  g.step(InputFrame{});
  return g;
}

HudState net_state(bool scoreboard) {
  HudState s;
  s.notice = "Ann left; the AI flies their ship";
  s.error_banner = "desync at tick 1234";
  s.show_fps = true;
  s.frame_stats = "particles 123456, 12345 reduced | 1234 draws | 12.5 screens blended (48.0 before the budget)";
  s.net.on = true;
  s.net.names = {{1, "Ann"}, {2, "Bartholomew the Eighth"}};
  s.net.stats = "ping 148 ms  rollbacks 12.5/s";
  s.net.scoreboard = scoreboard;
  for (int i = 0; i < 8; ++i)
    s.net.rows.push_back({uint32_t(i % 3), i == 0 ? "Host" : "A pilot named " + std::to_string(i) + "xxxxxxxxx", 150.0 + i, i == 1});
  return s;
}

TEST(HudNet, TheNetFiguresOverlapNoPanelAtEverySize) {
  Game g = net_game();
  test::check_hud_panels(g.world(), net_state(false),
                         {"frame stats", "net stats", "objective", "kill feed", "own bars", "weapon", "target panel", "radar", "notice", "error banner"});
}

TEST(HudNet, TheHeldScoreboardOverlapsNothingAtEverySize) {
  Game g = net_game();
  test::check_hud_panels(g.world(), net_state(true), {"scoreboard", "notice"});
}

TEST(HudNet, PilotsNamesOverShipsAndInTheKillFeed) {
  Game g = net_game();
  RenderView v;
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, net_state(false), 1280, 720, v);
  bool name_over_ship = false, feed = false;
  for (const HudText& t : v.hud.texts) {
    name_over_ship = name_over_ship || t.text == "Ann";
    feed = feed || t.text == "Ann destroyed Bartholomew the Eighth";
  }
  EXPECT_TRUE(name_over_ship);
  EXPECT_TRUE(feed);
}

}  // namespace
}  // namespace arc
