// game/sim/ai_strike.h — how a fighter pilot attacks a capital ship: the subsystem it goes for
// and when it launches torpedoes (ai_strike.cpp); fighters and other targets take no part.
#pragma once
#include <glm/vec3.hpp>

#include "game/sim/input.h"

namespace arc {

class World;
struct Ship;

// The part of capital ship `t` a pilot goes for: its shield generator while one stands (a
// torpedo reaches it through the shield, and the hull is open after it), then its engines (a
// ship that cannot run cannot jump out), then its nearest turret; −1 (the hull) when none is left.
int pick_strike_part(const World& w, const Ship& s, const Ship& t);
// At each decision: `s` aims at the part pick_strike_part names while its target is a capital
// ship, at nothing otherwise (Ship::target_part).
void choose_strike_part(const World& w, Ship& s);
// Where `s` aims on its target: the part it goes for, else the ship itself.
glm::dvec3 strike_aim_point(const World& w, const Ship& s, const Ship& t);
// A pilot that carries torpedoes takes them against a capital ship: the torpedo in the
// secondary bank, launched when ready, within range and near the nose, the line clear of its
// own side; against anything else it turns back to its missile or plasma.
void use_torpedoes(const World& w, Ship& s, const Ship& t, bool line_clear, InputFrame& c);

}  // namespace arc
