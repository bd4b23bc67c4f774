// game/app/window_loop.h — the live game in a window: fixed-step simulation, interpolated
// rendering, devices to InputFrames, the menus and the pause screen, screenshots, hot reload,
// optional recording.
//
// run_window() drives a WindowSession (window_session.h) the way raylib's examples are laid
// out: setup() once, then update(frame seconds) and draw() every frame until the window closes.
#pragma once
#include "game/app/app_options.h"

namespace arc {

// Exit code 2 without a display or with a bad bindings or level file; 0 when the window closes;
// 130 or 143 when SIGINT or SIGTERM closes it, with the close button's files all written.
int run_window(const AppOptions& options);

}  // namespace arc
