// game/app/effect_preview.h — `arcfire --headless --preview EFFECT.json --out DIR`: a filmstrip.
//
// Renders one effect file at N evenly spaced moments of its life (the centres of N equal slices
// of EffectTimeline::life_seconds), each frame reached by the workbench's exact scrub and
// labelled with its time and particle count in the HUD font, side by side in DIR/filmstrip.png;
// DIR/stats.json has per frame the tick, the live particles (per cluster too), the particles
// drawn and the pixels the particle pass blended (the renderer's occlusion query). The camera
// frames every particle of all N moments at once, so motion reads across the strip. Backdrops:
// empty space, the wall cutting the effect through its centre (soft edges show where particles
// meet it), or a model of assets/models at the origin. A bad effect file is the loader's line.
#pragma once
#include <string>

#include "core/settings.h"

namespace arc {

struct PreviewOptions {
  std::string effect_path;
  std::string out_dir;
  int frame_width = 320;
  int frame_height = 240;
  int frames = 8;
  std::string backdrop = "space";  // "space", "wall" or a model name in assets/models
  Settings settings = Settings::defaults();
  std::string root_dir = ARCFIRE_SOURCE_DIR;
};

// "" when the backdrop names space, the wall or a model that exists; else the one-line error.
std::string check_preview_backdrop(const std::string& backdrop, const std::string& root_dir);

// Writes the filmstrip and stats; throws InputError (bad file, folder) or PlatformError.
int run_preview(const PreviewOptions& options);

}  // namespace arc
