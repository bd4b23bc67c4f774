// tests/unit/game/mission_flight.h — the human-like test pilot (human_pilot.h) flies a mission to
// its end, and its figures over seeds per mission and difficulty (no GL).
//
// A fight ends in a win (the mission's victory), a loss (defeat, or the player's ship destroyed)
// or a timeout (max_seconds of game time). Its figures:
//   kill time         for each hostile the player destroys, seconds from the player's first hit
//                     on it to its death
//   beam accuracy     the game's own count (CombatStats): ticks the beam stayed on a hostile
//                     over ticks it fired; missile accuracy: missiles that struck a hostile
//                     over missiles fired
//   on-screen share   of the ticks a target is selected, those its brackets are drawn
//   hidden share      of the ticks the target is within 20° of the nose, those it is behind
//                     the own hull in the view (game/render/own_cover.h)
//   damage            dealt and taken (CombatStats), per fight
// `arcfire-bench --scene test_pilot` prints figures_table() for every mission, and the game
// tests check a few seeds with wide bounds (test_human_pilot.cpp).
//
//   const MissionFigures f = mission_figures(root, root + "/levels/duel.json", 1, 4);
//   std::fputs(figures_table({f}).c_str(), stdout);
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "human_pilot.h"

namespace arc {

enum class FightEnd { Won, Lost, Timeout };

struct MissionRun {
  FightEnd end = FightEnd::Timeout;
  double seconds = 0;         // game time when it ended
  double reaction_s = 0;      // the pilot's reaction time (drawn per seed)
  double tick_s = 0;          // the level's tick
  int hostiles = 0, kills = 0;
  std::vector<double> kill_s; // one per hostile the player destroyed
  int64_t beam_ticks = 0, beam_hit_ticks = 0, missiles_fired = 0, missiles_hit = 0;
  double damage_dealt = 0, damage_taken = 0;
  int64_t target_ticks = 0, on_screen_ticks = 0, near_nose_ticks = 0, hidden_ticks = 0;
};

// One fight of `level_path` at `difficulty` (0 easy, 1 normal, 2 hard) with `seed`.
MissionRun fly_mission(const std::string& root_dir, const std::string& level_path, int difficulty, uint64_t seed,
                       const HumanSkill& skill = {}, double max_seconds = 240.0);

struct MissionFigures {
  std::string mission;  // the level file's name without ".json"
  int difficulty = 1;
  int fights = 0, wins = 0, losses = 0, timeouts = 0;
  double win_rate = 0;
  double mean_kill_s = 0;        // over every kill; 0 without one
  double kills_per_fight = 0;
  double beam_accuracy = 0, missile_accuracy = 0;
  double beam_s_per_fight = 0, missiles_per_fight = 0;  // seconds the beam fired, missiles fired
  double on_screen_share = 0, hidden_share = 0;
  double damage_dealt = 0, damage_taken = 0;  // means per fight
  double mean_fight_s = 0;
  double reaction_s = 0;         // the pilot's mean reaction time over the seeds
};

// Seeds 1..seeds.
MissionFigures mission_figures(const std::string& root_dir, const std::string& level_path, int difficulty, int seeds,
                               const HumanSkill& skill = {}, double max_seconds = 240.0);

// The levels the menu lists as missions (a "mission" block of category mission), in the menu's
// order, as paths.
std::vector<std::string> mission_levels(const std::string& root_dir);

// A Markdown table, one row per entry; and the same as CSV with a header line.
std::string figures_table(const std::vector<MissionFigures>& rows);
std::string figures_csv(const std::vector<MissionFigures>& rows);

}  // namespace arc
