// particles/particle_settings.h — the particles.* settings keys, registered by the particle engine.
#pragma once

namespace arc {

class Settings;

// Defines particles.budget, particles.lightning_interval and particles.cull_distance at their
// defaults; the app turns them into GameOptions (game/app/app_options.h).
void register_particle_settings(Settings& s);

}  // namespace arc
