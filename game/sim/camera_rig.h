// game/sim/camera_rig.h — the simulated camera (game/sim/camera_rig.cpp).
#pragma once
#include "particles/particle_world.h"

namespace arc {

class World;

// Follows the focus ship (chase with a short lag, or cockpit) or holds the level's fixed view.
void update_camera(World& w);
// The camera rig as the particle world's culling view.
ParticleCamera particle_camera(const World& w);

}  // namespace arc
