// game/sim/commands.h — a tick's discrete commands (game/sim/commands.cpp).
#pragma once
#include <vector>

#include "game/sim/ids.h"
#include "game/sim/input.h"

namespace arc {

class World;
struct Ship;

// The live hostile nearest to `self` (null if none): the target key's choice, and the player's
// target at launch.
ShipId nearest_hostile(const World& w, ShipId self);

// Pause and resume; while running, the camera toggle and the player's target and weapon choice.
void apply_commands(World& w, const std::vector<Command>& commands);
// One command for one ship: its target, secondary weapon, flares; wing orders from the player's.
void apply_ship_command(World& w, Ship& ship, Command c);
// Network matches: each piloted slot's commands for its own ship (World::pilots).
void apply_slot_commands(World& w, const std::vector<SlotInput>& slots);

}  // namespace arc
