#include "game/app/music_director.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "game/sim/world.h"

namespace arc {

const char* MusicDirector::mood(const World& w) {
  if (!w.player) return "menu";
  if (w.tick < last_tick_) combat_until_ = tension_until_ = -1;  // a restart
  last_tick_ = w.tick;
  const Ship& me = w.ship(w.player);
  if (w.outcome == Outcome::Victory || w.outcome == Outcome::TeamWon) return "victory";
  if (w.outcome == Outcome::Defeat || !me.alive) return "defeat";
  const int64_t hold_combat = std::llround(kCombatHold / w.dt), hold_tension = std::llround(kTensionHold / w.dt);
  bool combat = me.last_hit_tick >= w.tick - 1 && me.last_hit_tick > 0;
  bool tension = false;
  if (me.beam_firing && me.beam_target && w.ship(me.beam_target).alive && w.hostile(me, w.ship(me.beam_target)))
    combat = true;
  for (const Ship& s : w.ships) {
    if (!s.alive || !w.hostile(me, s)) continue;
    if (glm::length(s.position - me.position) < kTensionRange) tension = true;
    if (s.seeker.lock_target == me.id) tension = true;
    if (s.beam_firing && s.beam_target == me.id) combat = true;
  }
  for (const Projectile& p : w.projectiles)
    if (p.target == me.id && !p.decoy) tension = true;
  if (combat) combat_until_ = w.tick + hold_combat;
  if (tension) tension_until_ = w.tick + hold_tension;
  if (w.tick < combat_until_) return "combat";
  if (w.tick < tension_until_) return "tension";
  return "calm";
}

}  // namespace arc
