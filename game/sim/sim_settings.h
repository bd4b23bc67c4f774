// game/sim/sim_settings.h — the sim.* settings keys, registered by the simulation.
#pragma once

namespace arc {

class Settings;

// Defines sim.substeps at its default; the app turns it into GameOptions::substeps.
void register_sim_settings(Settings& s);

}  // namespace arc
