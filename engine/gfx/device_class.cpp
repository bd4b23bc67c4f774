// gfx/device_class.cpp — software rasteriser or hardware GPU, by GL_RENDERER.
#include "gfx/device_class.h"

#include <cctype>
#include <string>

namespace arc {

bool is_software_rasteriser(std::string_view gl_renderer) {
  std::string lower(gl_renderer);
  for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
  for (const char* name : {"llvmpipe", "softpipe", "swrast", "software rasterizer", "swiftshader", "gdi generic"})
    if (lower.find(name) != std::string::npos) return true;
  return false;
}

}  // namespace arc
