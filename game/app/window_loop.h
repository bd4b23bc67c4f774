// game/app/window_loop.h — the live game in a window: fixed-step simulation, interpolated
// rendering, devices to InputFrames, pause menu, screenshots, optional recording.
#pragma once
#include "game/app/app_options.h"

namespace arc {

int run_window(const AppOptions& options);

}  // namespace arc
