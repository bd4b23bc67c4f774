// game/sim/damage.h — damage and deaths (game/sim/damage.cpp).
#pragma once
#include <glm/vec3.hpp>

#include "game/sim/ids.h"

namespace arc {

class World;
struct Ship;

// Applies damage at a world point: shield first, then hull; records the attacker. What reaches a
// capital ship's hull hurts the parts at the point too, unless `parts` is false.
void apply_damage(World& w, Ship& target, double amount, const glm::dvec3& point, ShipId attacker, bool parts = true);
// Ships without hull explode (splash damage may take others with them); stale targets and old
// explosions are cleared.
void resolve_deaths(World& w);

}  // namespace arc
