// game/app/headless_run.h — `arcfire --headless`: simulate, optionally render frames to PNG.
#pragma once
#include "game/app/app_options.h"

namespace arc {

// Simulates --ticks ticks of --level; with --out writes frame_NNNNNN.png every --every ticks;
// with --summary writes the final state; with --demo runs the attract level and also writes
// a contact sheet. Returns the exit code. SIGINT or SIGTERM stops it at the end of the tick:
// the summary, sound and contact sheet of the ticks so far are written, one line says where it
// stopped, and the code is 130 or 143.
int run_headless(const AppOptions& options);

}  // namespace arc
