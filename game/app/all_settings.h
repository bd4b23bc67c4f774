// game/app/all_settings.h — every setting the game knows, from the modules that own them.
//
// Each module registers its own keys (gfx/render_settings.h, particles/particle_settings.h,
// game/sim/sim_settings.h, audio/audio_settings.h); core/settings.h is only the mechanism.
// The order here is the order of `arcfire --list-settings` (tests/cli/list_settings.txt).
//
// Example, compiled as AllSettings.PresetOverDefaults in tests/unit/app/test_all_settings.cpp:
//   Settings s = all_settings();
//   s.apply_preset_file(arc::data_root() + "/assets/settings/quality.json", "high");
//   s.set_from_text("render.sorting=full", "--set");
//   std::string m = s.choice("render.soft_edges");
#pragma once
#include "core/settings.h"

namespace arc {

// Render, particle, simulation and audio settings, in that order, at their defaults.
Settings all_settings();

}  // namespace arc
