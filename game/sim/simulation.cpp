// game/sim/simulation.cpp — step_world: one tick of the simulation, step by step in a fixed order.
#include "game/sim/simulation.h"

#include "core/error.h"
#include "game/sim/ai.h"
#include "game/sim/beams.h"
#include "game/sim/camera_rig.h"
#include "game/sim/capital.h"
#include "game/sim/collisions.h"
#include "game/sim/commands.h"
#include "game/sim/damage.h"
#include "game/sim/effects.h"
#include "game/sim/flight.h"
#include "game/sim/mission_events.h"
#include "game/sim/outcome.h"
#include "game/sim/projectiles.h"
#include "game/sim/seekers.h"
#include "game/sim/shields.h"
#include "game/sim/training.h"
#include "game/sim/waves.h"
#include "game/sim/wing.h"
#include "game/sim/world.h"

namespace arc {

namespace {

// Slot index + 1 of every ship a pilot flies (0: none); empty outside network matches.
std::vector<uint8_t> piloted_ships(const World& w, const std::vector<SlotInput>* slots) {
  std::vector<uint8_t> out;
  if (!slots) return out;
  out.assign(w.ships.size(), 0);
  for (size_t i = 0; i < w.pilots.size() && i < slots->size(); ++i)
    if (w.pilots[i].piloted) out[w.pilots[i].ship.index()] = uint8_t(i + 1);
  return out;
}

}  // namespace

void step_world(World& w, const InputFrame& input, const std::vector<Command>& commands,
                const std::vector<SlotInput>* slots) {
  apply_commands(w, commands);
  if (slots && !w.paused) apply_slot_commands(w, *slots);
  if (w.paused) return;
  ++w.tick;
  for (Ship& s : w.ships) {
    s.prev_position = s.position;
    s.prev_orientation = s.orientation;
  }
  if (!w.waves.empty()) update_waves(w);
  if (w.mission) update_events(w);
  if (!w.wing.empty()) update_wing_orders(w);
  const std::vector<uint8_t> pilot_of = piloted_ships(w, slots);
  for (Ship& s : w.ships) {
    if (!s.alive) continue;
    const int slot = pilot_of.empty() ? 0 : pilot_of[s.id.index()];
    if (slot > 0) s.controls = (*slots)[slot - 1].input;
    else if (slots && s.ai == AiKind::None) drive_ai(w, s), defend_against_missiles(w, s);  // a slot nobody flies
    else if (s.id == w.player && s.ai == AiKind::None) s.controls = input;
    else if (w.mission && fly_order(w, s)) {}  // an event's route or hold order
    else if (s.ai == AiKind::Fighter) drive_ai(w, s), defend_against_missiles(w, s);
    else if (s.ai == AiKind::Gunner) drive_gunner(w, s);
    else if (s.ai == AiKind::Drone) drive_drone(w, s);
    else if (s.ai == AiKind::Capital) drive_capital(w, s);
    else s.controls = InputFrame{};
    fly_ship(w, s);
    if (!s.parts.empty()) stall_dead_engines(w, s);
  }
  collide_ships(w);
  update_locks(w);
  for (Ship& s : w.ships) {
    if (!s.alive) continue;
    update_beam_trigger(w, s);
    fire_secondary(w, s);
  }
  // After every fighter's trigger, in id order: turret hits land before the deaths are resolved.
  for (Ship& s : w.ships)
    if (s.alive && !s.cls->turrets.empty()) fire_turrets(w, s);
  update_flares(w);
  move_projectiles(w);
  publish_owner_transforms(w);
  if (!w.level.effects.empty()) {
    try {
      spawn_level_effects(w);
    } catch (const InputError& e) {
      throw InputError(w.level.path + ": " + e.what());
    }
  }
  w.particles->step(static_cast<uint64_t>(w.tick), particle_camera(w));
  // After the step, so a new exhaust's one-off nozzle burst is emitted at full intensity.
  update_exhausts(w);
  resolve_beams(w);
  hit_projectiles(w);
  resolve_deaths(w);
  if (!w.breakups.empty()) update_breakups(w);
  update_shields_and_energy(w);
  update_training(w, commands);
  update_outcome(w);
  update_camera(w);
}

}  // namespace arc
