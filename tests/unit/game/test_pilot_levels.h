// tests/unit/game/test_pilot_levels.h — the test pilot (test_pilot.h) flying a whole level:
// the skirmish or the arena, with the wing and the waves, and how long each ship lasted.
//
//   LevelRun r = fly_level(arc::data_root(), "levels/skirmish.json", /*difficulty=*/1, /*seed=*/3);
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "test_pilot.h"

namespace arc {

// One ship's time in the fight: from its arrival (0, or its wave's tick) to its death or the end.
struct ShipLife {
  std::string name, ship_class;
  bool wing = false, hostile = false, died = false, arrived = true;
  double seconds = 0;
};

struct LevelRun {
  bool won = false, lost = false;
  double seconds = 0;  // when it was decided, or the time limit
  int player_kills = 0;
  std::string player_killer;  // the last ship to hit the player, when it died
  std::vector<ShipLife> lives;
};

// `level` relative to `root_dir`, or an absolute path (the assets still come from `root_dir`).
LevelRun fly_level(const std::string& root_dir, const std::string& level, int difficulty, uint64_t seed,
                   PilotKind pilot = PilotKind::Person, double max_seconds = 300.0);

struct LevelRates {
  int fights = 0, wins = 0, losses = 0;
  double win_rate = 0;
  // Mean seconds in the fight of the wingmen, and of hostiles of the wingmen's classes.
  double wing_life_s = 0, enemy_life_s = 0;
};
// Over seeds 1..seeds at one difficulty.
LevelRates level_rates(const std::string& root_dir, const std::string& level, int difficulty, int seeds,
                       PilotKind pilot = PilotKind::Person);

}  // namespace arc
