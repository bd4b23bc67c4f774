// game/sim/outcome.h — the level's result (game/sim/outcome.cpp).
#pragma once
namespace arc {

class World;

// Decides victory, defeat or the winning team once, by the level's win and lose rules.
void update_outcome(World& w);

}  // namespace arc
