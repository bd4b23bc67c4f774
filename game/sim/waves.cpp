// game/sim/waves.cpp — reinforcement waves arriving: a timed wave at its second, a losses wave
// when its team has fewer ships alive than its count (an event's trigger and spawn, in short).
#include "game/sim/waves.h"

#include <vector>

#include "game/sim/mission_events.h"

namespace arc {
namespace {

void arrive(World& w, size_t first, const WaveDef& d) {
  std::vector<size_t> ships;
  for (size_t i = first; i < first + d.ships.size(); ++i) ships.push_back(i);
  spawn_ships(w, ships);
  announce_reinforcements(w, ships);
}

}  // namespace

void update_waves(World& w) {
  if (w.outcome != Outcome::Undecided) return;
  size_t first = w.level.ships.size();
  for (size_t i = 0; i < w.waves.size(); ++i) {
    const WaveDef& d = w.level.waves[i];
    if (w.waves[i].arrived_tick < 0 && trigger_holds(w, d.when)) {
      w.waves[i].arrived_tick = w.tick;
      arrive(w, first, d);
    }
    first += d.ships.size();
  }
}

}  // namespace arc
