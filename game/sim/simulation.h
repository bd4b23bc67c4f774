// game/sim/simulation.h — one fixed tick of the rules behind Game::step (internal to game/sim).
//
// step_world() is the pipeline; each step lives in a file named for its feature:
//   commands (commands.cpp) → controls from the player, the AI or nobody (ai.cpp) and flight
//   (flight.cpp) per ship → collisions (collisions.cpp) → beam triggers (beams.cpp) and shots
//   (projectiles.cpp) → projectile flight → particle owners, level effects (effects.cpp) and the
//   particle step → exhaust glow → beam hits → projectile hits → deaths (damage.cpp) →
//   shields and energy (shields.cpp) → outcome (outcome.cpp) → camera rig (camera_rig.cpp).
// The World at tick 0 comes from init_world (level_start.h).
#pragma once
#include <vector>

#include "game/sim/input.h"

namespace arc {

class World;

// With `slots` (network matches: one per World::pilots), each piloted slot's ship takes its
// slot's input and commands, an unpiloted one flies by AI, and `input` is not used.
void step_world(World& w, const InputFrame& input, const std::vector<Command>& commands,
                const std::vector<SlotInput>* slots = nullptr);

}  // namespace arc
