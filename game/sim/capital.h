// game/sim/capital.h — capital ships: turrets, subsystems and the staged break-up (capital.cpp).
//
// A capital ship's class lists turrets and subsystems (defs.h); Ship::parts holds each one's
// hull, turrets first. Turrets pick the nearest hostile inside their arc and range and fire on
// their own: a beam turret strikes along a bolt traced like the player's beam, a flak turret
// bursts a shell near its target. Hits that reach the hull also hurt every part whose sphere
// they land in; a destroyed part bursts into flame, a turret stops firing, the last engine stops
// the ship and the last shield generator drops its shield for good. A capital ship that dies
// breaks up: blasts along its hull over seconds while its wreck drifts, then the final one.
// Ships without parts take none of these paths, so their hashes stay as they were.
#pragma once
#include <cstdint>
#include <vector>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "game/sim/ids.h"

namespace arc {

class World;
struct Ship;
struct ShipClassDef;
struct TurretDef;

// Whether a turret on a ship turned by `ship_q`, mounted at world point `mount`, can aim at `at`:
// within its arc of its facing.
bool turret_can_aim(const TurretDef& t, const glm::dquat& ship_q, const glm::dvec3& mount, const glm::dvec3& at);

// Every turret and subsystem at full hull (none for a class without them).
void init_parts(Ship& s);
// Where part `i` is, in the world, and its hit sphere's radius.
glm::dvec3 part_position(const Ship& s, size_t i);
double part_radius(const ShipClassDef& c, size_t i);
const char* part_name(const ShipClassDef& c, size_t i);
bool part_alive(const Ship& s, size_t i);
// Every engine destroyed (false for a ship without engines listed).
bool engines_down(const Ship& s);
// Every shield generator destroyed (false for a ship without one listed).
bool shield_generators_down(const Ship& s);

// The capital AI: ahead at half throttle while its engines work.
void drive_capital(World& w, Ship& s);
// After flight: a ship whose engines are gone loses its speed and turn.
void stall_dead_engines(World& w, Ship& s);
// Every live turret of `s` aims and fires when ready.
void fire_turrets(World& w, Ship& s);
// A hit of `amount` at `point` on `t`'s hull: each live part whose sphere holds the point takes
// it too (part `only` alone when >= 0: a torpedo on the part it homed on).
void damage_parts(World& w, Ship& t, const glm::dvec3& point, double amount, ShipId attacker, int only = -1);
// The first live part sphere the segment a→b crosses (t in [0, 1], −1 for none).
double segment_parts(const Ship& s, const glm::dvec3& a, const glm::dvec3& b, int* part = nullptr);
// The player's subsystem key: the next live part of its target, then back to the whole ship.
void cycle_target_part(World& w, Ship& s);
// The part `s` aims at on its target (−1: the whole ship).
int target_part(const World& w, const Ship& s);

// A capital ship has died: its break-up starts (one explosion instead for a ship with no stages).
bool start_breakup(World& w, Ship& s);
// Blasts along breaking hulls, their wrecks drifting; the final blast ends each.
void update_breakups(World& w);

}  // namespace arc
