// game/app/device_look.h — the quality preset a first start picks from the device that draws.
//
// With no saved settings and no --quality, a hardware GPU gets the full look ("high": HDR,
// bloom, anti-aliasing) and a software rasteriser the built-in settings made for it; the
// Graphics page says which was chosen and why. A saved preset and --quality win (the
// window session applies it; tests/unit/app/test_device_look.cpp has renderer names).
#pragma once
#include <string>

namespace arc {

struct QualityChoice {
  std::string preset;  // a preset of quality.json, or kDefaultQuality
  std::string why;     // one line for the Graphics page
};

QualityChoice device_default_quality(const std::string& gl_renderer);

}  // namespace arc
