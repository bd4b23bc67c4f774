// The human-like test pilot (human_pilot.h, mission_flight.h): it reads the HUD as drawn, acts
// through LiveInput, and its figures on the duel, the skirmish and the arena at normal stay
// within bounds around a player's targets, while a pilot that never fires wins nothing. The bounds leave room for
// tuning the fight; the full table over more seeds is `arcfire-bench --scene test_pilot`, and per
// seed here:
//
//   PILOT_LEVEL=levels/skirmish.json PILOT_DIFF=1 PILOT_SEEDS=6 ./build/test_human_pilot
//     --gtest_also_run_disabled_tests --gtest_filter='*DISABLED_Report'
#include <algorithm>
#include <fstream>
#include <filesystem>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/data_root.h"
#include "game/render/hud_layout.h"
#include "game/render/render_view_builder.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "mission_flight.h"

namespace arc {
namespace {

Game duel() {
  GameOptions o;
  o.root_dir = data_root();
  return Game::load_level(data_root() + "/levels/duel.json", o);
}

bool has_line(const HudLayer& h, double x0, double y0, double x1, double y1) {
  for (const HudLine& l : h.lines)
    if (std::fabs(l.x0 - x0) < 0.01 && std::fabs(l.y0 - y0) < 0.01 && std::fabs(l.x1 - x1) < 0.01 &&
        std::fabs(l.y1 - y1) < 0.01)
      return true;
  return false;
}

bool has_text_near(const HudLayer& h, const std::string& s, double x, double y) {
  for (const HudText& t : h.texts)
    if (t.text == s && std::fabs(t.x - x) < 0.01 && std::fabs(t.y - y) < 0.01) return true;
  return false;
}

// What the pilot reads (hud_picture) is where layout_hud draws: the crosshair's arms, the
// brackets' corner and the missile cue's label, at 1280×720 and at 2560×1440.
TEST(HumanPilot, ReadsTheCuesWhereTheHudDrawsThem) {
  Game g = duel();
  g.step(InputFrame{}, {Command::TargetNearest});
  const World& w = g.world();
  const CameraView cam = frame_camera(w, 1.0, CameraSettings{});
  for (int height : {720, 1440}) {
    const int width = height * 16 / 9;
    const HudPicture pic = hud_picture(w, cam, HudState{}, 1.0, width, height);
    HudLayer layer;
    layout_hud(w, cam, HudState{}, 1.0, width, height, layer);
    ASSERT_TRUE(pic.flying);
    const double k = pic.scale;
    const glm::dvec2 c = pic.aim.crosshair;
    EXPECT_TRUE(has_line(layer, c.x - 14 * k, c.y, c.x - 5 * k, c.y)) << height;
    const TargetCues& t = pic.aim.target;
    ASSERT_TRUE(t.selected && t.on_screen && t.missile_cue) << height;
    const double r = t.half_size;
    EXPECT_TRUE(has_line(layer, t.centre.x - r, t.centre.y - r, t.centre.x - r + r * 0.4, t.centre.y - r)) << height;
    EXPECT_TRUE(has_text_near(layer, "MSL", t.centre.x + r + 18 * k, t.centre.y - 6 * k)) << height;
    ASSERT_FALSE(pic.radar_blips.empty());
    EXPECT_TRUE(pic.radar_blips[0].target);
  }
}

// Nothing is targeted at launch in the duel: the pilot presses the nearest-target key through
// LiveInput once its reaction time has passed, and the target is selected.
// The duel with the red Viper arriving half a second in, so nothing is targeted at launch: the
// pilot presses R one reaction time after it sees no target, and has the Viper once it is there.
TEST(HumanPilot, TargetsThroughTheKeysAfterItsReactionTime) {
  const std::string path = (std::filesystem::temp_directory_path() / "human_pilot_late_duel.json").string();
  std::ofstream(path) << R"({ "name": "Late duel", "objective": "Destroy the red Viper.",
    "win": { "type": "destroy_all_hostiles" }, "lose": { "type": "player_destroyed" },
    "ships": [ { "name": "Player", "class": "viper", "team": "blue", "player": true } ],
    "waves": [ { "after_seconds": 0.5, "ships": [
      { "name": "Red Leader", "class": "viper", "team": "red", "position": [60, 20, -1200], "orientation": [180, 0, 0] } ] } ] })";
  GameOptions o;
  o.root_dir = data_root();
  Game g = Game::load_level(path, o);
  const World& w = g.world();
  ASSERT_FALSE(w.ship(w.player).target);
  HumanPilot pilot(w, data_root(), 5);
  EXPECT_GE(pilot.reaction_s(), 0.2);
  EXPECT_LE(pilot.reaction_s(), 0.3);
  InputFrame in;
  std::vector<Command> keys;
  int64_t pressed = -1;
  for (int i = 0; i < 180 && !w.ship(w.player).target; ++i) {
    pilot.act(w, in, keys);
    if (pressed < 0 && std::find(keys.begin(), keys.end(), Command::TargetNearest) != keys.end())
      pressed = int64_t(w.tick);
    g.step(in, keys);
  }
  ASSERT_GE(pressed, 0);
  EXPECT_NEAR(double(pressed) * w.dt, pilot.reaction_s(), 2 * w.dt);
  EXPECT_TRUE(w.ship(w.player).target) << "the Viper arrived at 0.5 s";
}

void print(const MissionFigures& f) {
  std::printf("%-8s %-6s won %d lost %d timed out %d; kills %.2f per fight, %.1f s each; beam %.3f, missiles %.2f; "
              "on screen %.2f, hidden %.3f; dealt %.0f, taken %.0f\n",
              f.mission.c_str(), difficulty_name(static_cast<Difficulty>(f.difficulty)), f.wins, f.losses, f.timeouts,
              f.kills_per_fight, f.mean_kill_s, f.beam_accuracy, f.missile_accuracy, f.on_screen_share,
              f.hidden_share, f.damage_dealt, f.damage_taken);
  std::fflush(stdout);
}

// What any fair fight gives a player who sees only the screen: the target mostly on screen and
// seldom behind the own hull, damage dealt in every mission, a beam that hits when the crosshair
// is on the brackets, fights that end, and neither a sure win nor (on easy) a sure loss. A pilot that never fires deals nothing and wins nothing.
TEST(HumanPilot, FiguresOnTheDuelSkirmishAndArenaStayWithinWideBounds) {
  struct Case {
    const char* level;
    int difficulty, seeds;
    double lowest_win, highest_win;
    int most_timeouts;  // fights still undecided after 240 s
  };
  // At normal a player who sees only the screen wins the skirmish about half the time and the
  // arena a little less often (the targets are 40–70 % and 30–60 %; a few seeds are noisy), and
  // nearly every fight ends: the waves come while the fight is on, not after a straggler hunt.
  // Hard is hard but winnable: one fight in ten to one in four in every mission.
  const Case cases[] = {{"duel", 0, 3, 0.5, 1.0, 1},
                        {"duel", 1, 8, 0.15, 0.85, 1},
                        {"skirmish", 1, 10, 0.3, 0.8, 3},
                        {"arena", 1, 10, 0.2, 0.7, 3},
                        {"duel", 2, 12, 0.05, 0.5, 1},
                        {"skirmish", 2, 12, 0.05, 0.5, 4},
                        {"arena", 2, 12, 0.05, 0.5, 4}};
  for (const Case& c : cases) {
    const MissionFigures f =
        mission_figures(data_root(), data_root() + "/levels/" + c.level + ".json", c.difficulty, c.seeds);
    print(f);
    const std::string what = f.mission + " " + difficulty_name(static_cast<Difficulty>(f.difficulty));
    EXPECT_GE(f.win_rate, c.lowest_win) << what;
    EXPECT_LE(f.win_rate, c.highest_win) << what;
    EXPECT_LE(f.timeouts, c.most_timeouts) << what;
    EXPECT_GT(f.on_screen_share, 0.3) << what;
    // The chase view lifts over the own hull when it would hide a hostile ahead
    // (game/render/chase_framing.h): the target near the nose is hidden on under 2 % of ticks.
    EXPECT_LT(f.hidden_share, 0.02) << what;
    EXPECT_GT(f.damage_dealt, 150.0) << what;
    EXPECT_GT(f.beam_accuracy, 0.3) << what;  // the crosshair on the brackets puts the nose on the target
    EXPECT_GT(f.missile_accuracy, 0.1) << what;
  }
  HumanSkill holds_fire;
  holds_fire.fires = false;
  const MissionFigures idle = mission_figures(data_root(), data_root() + "/levels/duel.json", 1, 2, holds_fire);
  print(idle);
  EXPECT_EQ(idle.wins, 0);
  EXPECT_EQ(idle.missiles_per_fight, 0.0);
  EXPECT_EQ(idle.beam_s_per_fight, 0.0);
  EXPECT_LT(idle.damage_dealt, 150.0);  // what collisions deal
}

// Campaign missions as a player plays them from the HUD: the training prompts, the patrol's NAV
// marker, the strike's named corvette with torpedoes at its subsystems. At normal the pilot
// finishes each of these in 9 or 10 of seeds 1..10 (docs/pilot.md); three seeds, at least one win.
TEST(HumanPilot, FinishesCampaignMissionsAtNormal) {
  for (const char* level : {"levels/training.json", "levels/campaign/02_patrol.json", "levels/campaign/07_strike.json"}) {
    const MissionFigures f = mission_figures(data_root(), data_root() + "/" + level, 1, 3, {}, 600.0);
    print(f);
    EXPECT_GE(f.wins, 1) << level;
    EXPECT_EQ(f.timeouts, 0) << level;
  }
}

// One line per seed: PILOT_LEVEL, PILOT_DIFF, PILOT_SEEDS; the hand's PILOT_AIM_NOISE (pixels)
// and PILOT_MOVE_ERROR (share).
TEST(HumanPilot, DISABLED_Report) {
  const char* level = std::getenv("PILOT_LEVEL");
  const int d = std::getenv("PILOT_DIFF") ? std::atoi(std::getenv("PILOT_DIFF")) : 1;
  const int seeds = std::getenv("PILOT_SEEDS") ? std::atoi(std::getenv("PILOT_SEEDS")) : 6;
  const std::string path = data_root() + "/" + (level ? level : "levels/duel.json");
  HumanSkill skill;
  if (const char* v = std::getenv("PILOT_AIM_NOISE")) skill.aim_noise_px = std::atof(v);
  if (const char* v = std::getenv("PILOT_MOVE_ERROR")) skill.move_error = std::atof(v);
  for (int s = 1; s <= seeds; ++s) {
    const MissionRun r = fly_mission(data_root(), path, d, uint64_t(s), skill);
    std::printf("seed %2d %s %5.1f s kills %d/%d beam %.3f (%lld) msl %lld/%lld on %.2f hid %lld/%lld dealt %.0f taken %.0f\n",
                s, r.end == FightEnd::Won ? "won " : r.end == FightEnd::Lost ? "lost" : "time", r.seconds, r.kills,
                r.hostiles, accuracy(r.beam_hit_ticks, r.beam_ticks), (long long)r.beam_ticks,
                (long long)r.missiles_hit, (long long)r.missiles_fired, accuracy(r.on_screen_ticks, r.target_ticks),
                (long long)r.hidden_ticks, (long long)r.near_nose_ticks, r.damage_dealt, r.damage_taken);
    std::fflush(stdout);
  }
}

}  // namespace
}  // namespace arc
