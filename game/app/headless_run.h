// game/app/headless_run.h — `arcfire --headless`: simulate, optionally render frames to PNG.
#pragma once
#include "game/app/app_options.h"

namespace arc {

// Simulates --ticks ticks of --level; with --out writes frame_NNNNNN.png every --every ticks;
// with --summary writes the final state; with --demo runs the attract level and also writes
// a contact sheet. Returns the exit code.
int run_headless(const AppOptions& options);

}  // namespace arc
