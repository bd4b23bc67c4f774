// game/workbench/workbench_window.h — `arcfire --workbench [EFFECT]`: the effect workbench.
//
// A window with one effect on a stage (game/workbench/workbench_stage.h) seen through an orbit
// camera (drag to orbit, wheel to zoom, double-click to frame the effect), the panel beside it
// (effect list, backdrop, time controls, every field of the effect file) and the stats
// overlay. Keys, when no text field has the keyboard: Space plays or pauses, Left/Right step
// one tick, Home goes to tick 0, F frames the effect, F12 saves a screenshot (panel included) to
// out/screenshots/, Ctrl+S saves, Ctrl+Z / Ctrl+Y undo and redo, Esc quits (asking first when
// there are unsaved edits).
#pragma once
#include <string>

#include "core/data_root.h"
#include "core/settings.h"
#include "game/app/all_settings.h"

namespace arc {

struct WorkbenchOptions {
  std::string root_dir = data_root();  // assets/, shaders/
  std::string effect_path;                    // "" = the first effect of assets/effects
  Settings settings = all_settings();   // render.* and particles.budget
  int width = 1280, height = 720;
  bool vsync = true;
};

// Runs until the window closes or Esc; returns the exit code (0; 130 or 143 when SIGINT or
// SIGTERM closes it as the close button does, without saving edits). Bad input (the effect
// file, assets) throws InputError before the window opens; no display throws PlatformError.
int run_workbench(const WorkbenchOptions& options);

}  // namespace arc
