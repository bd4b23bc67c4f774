#include "replay/image_diff.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace arc::replay {

std::string ImageDiff::describe() const {
  char buf[160];
  double pct = pixels ? 100.0 * double(failing_pixels) / double(pixels) : 0.0;
  std::snprintf(buf, sizeof buf, "%llu of %llu pixels (%.3f%%) differ by more than the tolerance, max difference %d/255",
                static_cast<unsigned long long>(failing_pixels), static_cast<unsigned long long>(pixels), pct, max_diff);
  return buf;
}

ImageDiff compare_rgba8(const std::vector<uint8_t>& actual, const std::vector<uint8_t>& golden, int width,
                        int height, const ImageTolerance& tol) {
  const size_t n = size_t(std::max(width, 0)) * size_t(std::max(height, 0));
  if (actual.size() != n * 4 || golden.size() != n * 4)
    throw std::invalid_argument("compare_rgba8: buffers are not width*height*4 bytes");
  ImageDiff d;
  d.pixels = n;
  d.diff_rgba.resize(n * 4);
  for (size_t i = 0; i < n; ++i) {
    int worst = 0;
    for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(int(actual[i * 4 + c]) - int(golden[i * 4 + c])));
    d.max_diff = std::max(d.max_diff, worst);
    uint8_t* o = &d.diff_rgba[i * 4];
    const uint8_t* g = &golden[i * 4];
    if (worst > tol.max_channel_diff) {
      ++d.failing_pixels;
      o[0] = 255;
      o[1] = o[2] = 0;
    } else {
      // A dim grey copy of the golden gives context around the red failing pixels.
      uint8_t lum = static_cast<uint8_t>((int(g[0]) * 3 + int(g[1]) * 6 + int(g[2])) / 40);
      o[0] = o[1] = o[2] = lum;
    }
    o[3] = 255;
  }
  d.passed = n > 0 && double(n - d.failing_pixels) >= tol.min_fraction * double(n);
  return d;
}

}  // namespace arc::replay
