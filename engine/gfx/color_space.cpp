// gfx/color_space.cpp — sRGB encode/decode and premultiplication in linear light.
#include "gfx/color_space.h"

#include <algorithm>
#include <cmath>

namespace arc {

float srgb_to_linear(float c) {
  if (c <= 0.04045f) return c / 12.92f;
  return std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float linear_to_srgb(float c) {
  if (c <= 0.0031308f) return c * 12.92f;
  return 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

glm::vec3 srgb_to_linear(glm::vec3 c) { return {srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)}; }

glm::vec4 srgb_to_linear(glm::vec4 c) { return {srgb_to_linear(glm::vec3(c)), c.a}; }

Image premultiply_linear_srgb(const Image& image) {
  float decode[256];
  for (int i = 0; i < 256; ++i) decode[i] = srgb_to_linear(float(i) / 255.0f);
  Image out = image;
  out.premultiplied = true;
  for (size_t i = 0; i + 3 < out.rgba.size(); i += 4) {
    const float a = float(image.rgba[i + 3]) / 255.0f;
    for (size_t c = 0; c < 3; ++c) {
      float straight = decode[image.rgba[i + c]];
      if (image.premultiplied) {
        // Undo the sRGB-space premultiplication: straight colour = stored / alpha (0 where alpha is).
        float s = a > 0.0f ? std::min(1.0f, float(image.rgba[i + c]) / 255.0f / a) : 0.0f;
        straight = srgb_to_linear(s);
      }
      out.rgba[i + c] = uint8_t(std::lround(std::clamp(linear_to_srgb(straight * a), 0.0f, 1.0f) * 255.0f));
    }
  }
  return out;
}

}  // namespace arc
