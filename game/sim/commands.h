// game/sim/commands.h — a tick's discrete commands (game/sim/commands.cpp).
#pragma once
#include <vector>

#include "game/sim/input.h"

namespace arc {

class World;

// Pause and resume; while running, the camera toggle and the player's target and weapon choice.
void apply_commands(World& w, const std::vector<Command>& commands);

}  // namespace arc
