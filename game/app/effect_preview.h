// game/app/effect_preview.h — `arcfire --headless --preview EFFECT.json --out DIR`: a filmstrip.
//
// Renders one effect file at N evenly spaced moments of its life (the centres of N equal slices
// of EffectTimeline::life_seconds), each frame reached by the workbench's exact scrub and
// labelled with its time and particle count in the HUD font, side by side in DIR/filmstrip.png;
// DIR/stats.json has per frame the tick, the live particles (per cluster too), the particles
// drawn and the pixels the particle pass blended (the renderer's occlusion query). The camera
// frames every particle of all N moments at once, so motion reads across the strip. Backdrops:
// empty space, the wall a third of the effect's radius behind its centre (soft edges show where
// particles meet it), or a model of assets/models at the origin. An effect that lays a trail along its
// emitter's path ("spacing") is spawned on an owner flying the workbench's circle, so the trail
// shows. A bad effect file is the loader's line.
#pragma once
#include <string>

#include "core/data_root.h"
#include "core/settings.h"
#include "game/app/all_settings.h"

namespace arc {

struct PreviewOptions {
  std::string effect_path;
  std::string out_dir;
  int frame_width = 320;
  int frame_height = 240;
  int frames = 8;
  std::string backdrop = "space";  // "space", "wall" or a model name in assets/models
  Settings settings = all_settings();
  std::string root_dir = data_root();
};

struct AppOptions;
// The preview's part of the command line; frames are 320x240 unless --size says otherwise.
PreviewOptions preview_options(const AppOptions& app);

// "" when the backdrop names space, the wall or a model that exists; else the one-line error.
std::string check_preview_backdrop(const std::string& backdrop, const std::string& root_dir);

// Writes the filmstrip and stats; throws InputError (bad file, folder) or PlatformError.
// SIGINT or SIGTERM stops it after the frame being drawn, writing neither (exit 130 or 143).
int run_preview(const PreviewOptions& options);

}  // namespace arc
