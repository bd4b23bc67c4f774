// game/sim/commands.cpp — a tick's discrete commands: pause and resume, the camera keys, the
// player's target (next, nearest hostile, next hostile), secondary weapon, flares and wing orders.
#include "game/sim/commands.h"

#include "game/sim/capital.h"
#include "game/sim/seekers.h"
#include "game/sim/wing.h"
#include "game/sim/world.h"

namespace arc {
namespace {

ShipId next_target(const World& w, ShipId self, ShipId current, bool hostile_only) {
  const size_t n = w.ships.size();
  const size_t from = (current ? current : self).index();
  for (size_t k = 1; k <= n; ++k) {
    const Ship& s = w.ships[(from + k) % n];
    if (s.id == self || !s.alive) continue;
    if (hostile_only && !w.hostile(w.ship(self), s)) continue;
    return s.id;
  }
  return {};
}

}  // namespace

// A wingman is never what a pilot reaching for the nearest target wants: hostiles only.
ShipId nearest_hostile(const World& w, ShipId self) {
  ShipId best;
  double best_d = 0;
  const Ship& me = w.ship(self);
  for (const Ship& s : w.ships) {
    if (s.id == self || !s.alive || !w.hostile(me, s)) continue;
    double d = glm::dot(s.position - me.position, s.position - me.position);
    if (!best || d < best_d) best = s.id, best_d = d;
  }
  return best;
}

void apply_commands(World& w, const std::vector<Command>& commands) {
  for (Command c : commands) {
    if (c == Command::Pause) w.paused = true;
    if (c == Command::Resume) w.paused = false;
    if (w.paused) continue;
    // The camera key swaps chase and cockpit (padlock leaves for the cockpit); the padlock key
    // turns the padlock view on and off, back to chase.
    if (c == Command::CameraToggle && w.camera_mode != CameraMode::Fixed)
      w.camera_mode = w.camera_mode == CameraMode::Cockpit ? CameraMode::Chase : CameraMode::Cockpit;
    if (c == Command::CameraPadlock && w.camera_mode != CameraMode::Fixed)
      w.camera_mode = w.camera_mode == CameraMode::Padlock ? CameraMode::Chase : CameraMode::Padlock;
    if (!w.player || !w.ship(w.player).alive) continue;
    apply_ship_command(w, w.ship(w.player), c);
  }
}

void apply_ship_command(World& w, Ship& p, Command c) {
  const ShipId before = p.target;
  switch (c) {
    case Command::TargetNext: p.target = next_target(w, p.id, p.target, false); break;
    case Command::TargetNearest: p.target = nearest_hostile(w, p.id); break;
    case Command::Countermeasure: drop_flare(w, p); break;
    case Command::TargetNextHostile: p.target = next_target(w, p.id, p.target, true); break;
    case Command::SwitchWeapon:
      if (p.cls->missile.present && p.cls->plasma.present && !p.cls->primary_plasma)
        p.secondary = p.secondary == SecondaryWeapon::Missile ? SecondaryWeapon::Plasma : SecondaryWeapon::Missile;
      break;
    case Command::OrderAttack:
    case Command::OrderCover:
    case Command::OrderFormUp:
    case Command::OrderEngage:
      if (p.id == w.player) order_wing(w, c);  // the wing follows the level's player only
      break;
    case Command::TargetSubsystem: cycle_target_part(w, p); break;
    default: break;
  }
  if (p.target != before) p.target_part.clear();
}

// Pause and the camera stay local to each peer: a slot's commands steer its own ship only.
void apply_slot_commands(World& w, const std::vector<SlotInput>& slots) {
  for (size_t i = 0; i < slots.size() && i < w.pilots.size(); ++i) {
    if (!w.pilots[i].piloted) continue;
    Ship& s = w.ship(w.pilots[i].ship);
    for (Command c : slots[i].commands)
      if (s.alive) apply_ship_command(w, s, c);
  }
}

}  // namespace arc
