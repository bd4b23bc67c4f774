// game/app/device_look.cpp — the first start's preset by device.
#include "game/app/device_look.h"

#include "game/app/user_settings.h"
#include "gfx/device_class.h"

namespace arc {

QualityChoice device_default_quality(const std::string& gl_renderer) {
  const std::string name = gl_renderer.substr(0, gl_renderer.find(" ("));
  if (gl_renderer.empty()) return {kDefaultQuality, std::string(kDefaultQuality) + ": the device is not known"};
  if (is_software_rasteriser(gl_renderer))
    return {kDefaultQuality, std::string(kDefaultQuality) + ": chosen for a software rasteriser (" + name + ")"};
  return {"high", "high: chosen for a GPU (" + name + ")"};
}

}  // namespace arc
