// game/sim/training.h — a training level's steps as the simulation runs them (game/sim/training.cpp).
//
// The level's "training" block (defs.h, TrainingDef) lists steps; World::training holds the one
// under way. A step begins by spawning its ships and having its drone fire at the player, and
// ends on the tick its condition is met; the next begins on the same tick. After the last step
// World::training->step equals the steps' count and a "training_complete" win is decided.
#pragma once
#include <vector>

#include "game/sim/input.h"

namespace arc {

class World;

// Sets World::training at level start (only in levels with steps) and begins the first step.
void start_training(World& w);

// After a tick's ships, weapons and deaths: checks the step's condition against this tick's
// state and `commands`, advancing as far as conditions already hold (one step per tick).
void update_training(World& w, const std::vector<Command>& commands);

// Whether every step is done (false in levels without training).
bool training_complete(const World& w);

}  // namespace arc
