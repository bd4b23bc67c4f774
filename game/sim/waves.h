// game/sim/waves.h — reinforcement waves (LevelDef::waves): their ships wait out of play from the
// start (not alive, death_tick −1) and enter together when the wave's trigger holds.
#pragma once
#include "game/sim/world.h"

namespace arc {

// Brings in every wave whose time has come or whose team has fallen below its count: the ships
// come alive where the level placed them, with shields and exhausts, and "Reinforcements" is posted.
void update_waves(World& w);

}  // namespace arc
