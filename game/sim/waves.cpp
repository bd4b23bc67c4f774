// game/sim/waves.cpp — reinforcement waves arriving: a timed wave at its second, a losses wave
// when its team has fewer ships alive than its count.
#include "game/sim/waves.h"

#include <string>

#include "game/sim/effects.h"
#include "game/sim/level_start.h"
#include "game/sim/wing.h"

namespace arc {
namespace {

int alive_in_team(const World& w, const std::string& team) {
  int n = 0;
  for (const Ship& s : w.ships) n += s.alive && w.team_name(s.team) == team ? 1 : 0;
  return n;
}

bool due(const World& w, const WaveDef& d) {
  if (d.after_seconds >= 0) return w.tick >= seconds_to_ticks(w, d.after_seconds);
  return alive_in_team(w, d.team) < d.below;
}

void arrive(World& w, size_t first, const WaveDef& d) {
  for (size_t i = first; i < first + d.ships.size(); ++i) {
    Ship& s = w.ships[i];
    s.alive = true;
    set_owner(w, s.particle_owner, s.position, s.orientation, s.velocity);
    attach_ship_effects(w, s);
  }
  const Ship& lead = w.ships[first];
  const bool friendly = w.player && w.ship(w.player).team == lead.team;
  const size_t n = d.ships.size();
  post_message(w, friendly ? MessageKind::Friendly : MessageKind::Hostile,
               std::string("Reinforcements: ") + std::to_string(n) + (friendly ? " friendly" : " hostile") +
                   (n == 1 ? " ship" : " ships"));
}

}  // namespace

void update_waves(World& w) {
  if (w.outcome != Outcome::Undecided) return;
  size_t first = w.level.ships.size();
  for (size_t i = 0; i < w.waves.size(); ++i) {
    const WaveDef& d = w.level.waves[i];
    if (w.waves[i].arrived_tick < 0 && due(w, d)) {
      w.waves[i].arrived_tick = w.tick;
      arrive(w, first, d);
    }
    first += d.ships.size();
  }
}

}  // namespace arc
