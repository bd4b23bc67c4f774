// game/sim/seekers.h — missile locks, flares and the missiles they decoy, and how an AI pilot
// defends itself against a missile homing on it (game/sim/seekers.cpp).
//
// A ship's lock builds while its target stays within its missile's lock cone and range; a
// missile leaves only once the lock is complete (a trigger held early fires at that moment)
// and homes on the target.
// A flare pulls each missile homing on its ship that has it in the seeker cone, with the
// class's decoy chance drawn once per missile and flare from the keyed RNG; a pulled missile
// chases the flare and bursts on it (passing through ships on the way), or flies straight on
// once the flare burns out.
#pragma once
#include "game/sim/world.h"

namespace arc {

// Advances or resets every live ship's lock on its target, one tick.
void update_locks(World& w);
// Whether `s`'s lock on its target is complete.
bool missile_locked(const World& w, const Ship& s);
// Lock progress on the ship's target, 0..1 (0 with no missile or no lock building).
double lock_progress(const World& w, const Ship& s);
// Drops a flare when one is left and the cooldown has passed; returns whether it did.
bool drop_flare(World& w, Ship& s);
// Flares drift and burn out; a missile whose flare burnt out flies straight on.
void update_flares(World& w);
// A flare's position by serial, or null when it has burnt out.
const Flare* find_flare(const World& w, uint32_t serial);
// An AI fighter's answer to a missile homing on it: a flare when it sees the missile close
// (after its reaction time), and a hard turn across the missile's path.
void defend_against_missiles(World& w, Ship& s);

}  // namespace arc
