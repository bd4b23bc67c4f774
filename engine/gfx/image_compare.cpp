// gfx/image_compare.cpp — golden-image tolerance rule, summary and failure images (no GL).
#include "gfx/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace arc {

std::string ImageDiff::summary() const {
  std::ostringstream s;
  if (size_mismatch) return "image sizes differ";
  s << (passed ? "match" : "MISMATCH") << ": " << fraction_within * 100.0 << "% of pixels within tolerance, max channel diff "
    << max_diff;
  return s.str();
}

ImageDiff compare_images(const Image& expected, const Image& actual, const ImageCompareRule& rule) {
  ImageDiff d;
  if (expected.width != actual.width || expected.height != actual.height ||
      expected.rgba.size() != actual.rgba.size() || expected.rgba.empty()) {
    d.size_mismatch = true;
    return d;
  }
  size_t pixels = expected.rgba.size() / 4, within = 0;
  for (size_t p = 0; p < pixels; ++p) {
    int m = 0;
    for (int c = 0; c < 4; ++c) m = std::max(m, std::abs(int(expected.rgba[p * 4 + c]) - int(actual.rgba[p * 4 + c])));
    d.max_diff = std::max(d.max_diff, m);
    if (m <= rule.tolerance) ++within;
  }
  d.fraction_within = double(within) / double(pixels);
  d.passed = d.fraction_within >= rule.min_fraction;
  return d;
}

Image difference_image(const Image& expected, const Image& actual) {
  Image out;
  out.width = actual.width;
  out.height = actual.height;
  out.rgba.resize(actual.rgba.size());
  for (size_t i = 0; i < actual.rgba.size(); ++i)
    out.rgba[i] = (i % 4 == 3) ? 255 : uint8_t(std::min(255, 8 * std::abs(int(expected.rgba[i]) - int(actual.rgba[i]))));
  return out;
}

void write_failure_images(const std::string& prefix, const Image& actual, const Image& expected) {
  save_image(prefix + "_actual.png", actual);
  if (expected.width == actual.width && expected.height == actual.height && expected.rgba.size() == actual.rgba.size())
    save_image(prefix + "_diff.png", difference_image(expected, actual));
}

double psnr_db(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.rgba.size() != b.rgba.size()) return std::nan("");
  double sum = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4)
    for (size_t c = 0; c < 3; ++c) {
      const double d = double(a.rgba[i + c]) - double(b.rgba[i + c]);
      sum += d * d;
    }
  const double mse = sum / std::max<double>(1.0, double(a.rgba.size() / 4 * 3));
  return mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
}

}  // namespace arc
