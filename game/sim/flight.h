// game/sim/flight.h — ships in flight (game/sim/flight.cpp).
#pragma once
#include "game/sim/world.h"

namespace arc {

// Flight for one ship and one step of h seconds from its `controls` (exposed for the flight tests).
void integrate_flight(Ship& s, double h);
// One tick of a ship's flight: the afterburner's energy, then integrate_flight in the world's sub-steps.
void fly_ship(World& w, Ship& s);
// The exhausts' brightness follows the throttle (full only with the afterburner).
void update_exhausts(World& w);

}  // namespace arc
