// tests/unit/game/test_pilot_levels.cpp — the test pilot through a whole level (test_pilot_levels.h).
#include "test_pilot_levels.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "game/sim/game.h"
#include "game/sim/world.h"

namespace arc {

LevelRun fly_level(const std::string& root_dir, const std::string& level, int difficulty, uint64_t seed, PilotKind pilot,
                   double max_seconds) {
  Game g = load_flight(root_dir, level, difficulty, seed);
  fly_to_outcome(g, seed, pilot, max_seconds);
  const World& w = g.world();
  LevelRun r;
  r.won = w.outcome == Outcome::Victory;
  r.lost = w.outcome == Outcome::Defeat;
  const int64_t end = w.outcome == Outcome::Undecided ? w.tick : w.outcome_tick;
  r.seconds = double(end) * w.dt;
  // A wave's ships arrive at its tick; the level's own at 0.
  std::vector<int64_t> arrival(w.ships.size(), 0);
  size_t next = w.level.ships.size();
  for (size_t i = 0; i < w.level.waves.size(); ++i)
    for (size_t k = 0; k < w.level.waves[i].ships.size(); ++k) arrival[next++] = w.waves[i].arrived_tick;
  const Ship& p = w.ship(w.player);
  r.player_kills = p.kills;
  if (!p.alive && p.last_attacker) r.player_killer = w.ship(p.last_attacker).name;
  for (const Ship& s : w.ships) {
    if (s.player) continue;
    ShipLife l;
    l.name = s.name;
    l.ship_class = s.cls->name;
    l.hostile = w.hostile(p, s);
    for (const Wingman& m : w.wing) l.wing = l.wing || m.ship == s.id;
    l.arrived = arrival[s.id.index()] >= 0;
    l.died = s.death_tick >= 0;
    const int64_t gone = l.died ? s.death_tick : end;
    l.seconds = l.arrived ? double(std::max<int64_t>(0, gone - arrival[s.id.index()])) * w.dt : 0.0;
    r.lives.push_back(l);
  }
  return r;
}

LevelRates level_rates(const std::string& root_dir, const std::string& level, int difficulty, int seeds, PilotKind pilot) {
  LevelRates r;
  double wing_sum = 0, enemy_sum = 0;
  int wing_n = 0, enemy_n = 0;
  for (int s = 1; s <= seeds; ++s) {
    const LevelRun run = fly_level(root_dir, level, difficulty, static_cast<uint64_t>(s), pilot);
    if (std::getenv("WING_VERBOSE"))
      std::printf("  seed %2d %s at %5.1f s, player kills %d, killed by %s\n", s, run.won ? "won " : run.lost ? "lost" : "open",
                  run.seconds, run.player_kills, run.player_killer.c_str());
    ++r.fights;
    r.wins += run.won;
    r.losses += run.lost;
    std::vector<std::string> wing_classes;
    for (const ShipLife& l : run.lives)
      if (l.wing) wing_classes.push_back(l.ship_class), wing_sum += l.seconds, ++wing_n;
    for (const ShipLife& l : run.lives)
      if (l.hostile && l.arrived && std::count(wing_classes.begin(), wing_classes.end(), l.ship_class))
        enemy_sum += l.seconds, ++enemy_n;
  }
  r.win_rate = r.fights ? double(r.wins) / r.fights : 0.0;
  r.wing_life_s = wing_n ? wing_sum / wing_n : 0.0;
  r.enemy_life_s = enemy_n ? enemy_sum / enemy_n : 0.0;
  return r;
}

}  // namespace arc
