// game/sim/shields.cpp — shield and energy regeneration, and the shield sphere's density and
// brightness, which follow the shield's strength and its hits.
#include "game/sim/shields.h"

#include <algorithm>
#include <cmath>

#include "game/sim/capital.h"
#include "game/sim/effects.h"
#include "game/sim/world.h"

namespace arc {

// The shield cluster's particle count is fixed by its burst, so density follows strength by
// respawning the sphere whenever strength crosses a quarter (a few times per fight at most).
void spawn_shield(World& w, Ship& s, int quarters) {
  if (!s.shield_fx.clusters.empty()) w.particles->destroy(s.shield_fx);
  SpawnParams sp;
  sp.owner = s.particle_owner;
  sp.scale = s.cls->shield_radius / 10.0;
  sp.intensity = quarters / 4.0;
  s.shield_fx = spawn_fx(w, w.fx.shield_sphere, sp);
  s.shield_density = quarters;
  s.shield_spawn_tick = w.tick;
  s.shown_shield_intensity = -1;
}

void update_shields_and_energy(World& w) {
  for (Ship& s : w.ships) {
    if (!s.alive) continue;
    const ShipClassDef& c = *s.cls;
    s.energy = std::min(c.energy, s.energy + c.energy_regen * w.dt);
    const bool regen_allowed = w.tick - s.last_hit_tick >= seconds_to_ticks(w, c.shield_regen_delay);
    // A capital ship whose shield generators are all destroyed has no shield left to raise.
    const bool generator_down = !s.parts.empty() && shield_generators_down(s);
    if (generator_down) s.shield = 0;
    const bool recharging = regen_allowed && !generator_down && s.shield < c.shield;
    if (recharging) s.shield = std::min(c.shield, s.shield + c.shield_regen * w.dt);
    if (s.shield_fx.clusters.empty()) continue;
    const int quarters = static_cast<int>(std::ceil(4.0 * s.shield / c.shield));
    if (quarters > 0 && quarters != s.shield_density) spawn_shield(w, s, quarters);
    // A new sphere keeps its spawn intensity until its burst has been emitted.
    if (s.shield_spawn_tick == w.tick) continue;
    // Brightest at a hit and fading in about half a second; a faint glow while recharging (it must
    // not hide the view from the chase camera); density and
    // brightness follow strength.
    double since_hit = double(w.tick - s.shield_flash_tick) * w.dt;
    double flash = std::max(0.0, 1.0 - since_hit / kFlashSeconds);
    double strength = c.shield > 0 ? s.shield / c.shield : 0.0;
    double visible = std::max(flash, recharging ? 0.12 : 0.0) * (0.25 + 0.75 * strength);
    double q = std::round(visible * 64.0) / 64.0;
    if (q != s.shown_shield_intensity) {
      for (ClusterHandle ch : s.shield_fx.clusters) w.particles->set_intensity(ch, q);
      s.shown_shield_intensity = q;
    }
  }
}

}  // namespace arc
