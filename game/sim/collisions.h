// game/sim/collisions.h — contacts between ships and with props (game/sim/collisions.cpp).
#pragma once
namespace arc {

class World;

// Separates overlapping ships (by mass) and ships from props, bounces them and applies the
// impact damage.
void collide_ships(World& w);

}  // namespace arc
