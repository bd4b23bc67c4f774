// tools/assetgen/hull_textures.cpp — plate rows, panel lines, fasteners and hatches, tiling.
#include "hull_textures.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "assets/image.h"
#include "core/input_file.h"
#include "core/input_limits.h"
#include "core/rng.h"

namespace arc::assetgen {
namespace {

constexpr int kTexels = 256;

// Streams of the pattern's keyed random numbers.
enum Stream : uint64_t { kRowOffset = 1, kCut = 2, kTone = 3, kHatch = 4, kGrain = 5 };

double gaussian_line(double distance, double half_width) {
  const double t = distance / half_width;
  return std::exp(-t * t);
}

// One row of plates: where each plate starts along the row (the first at 0, the row's end at
// kTexels) before the row's offset is applied, so the row wraps around the tile seamlessly.
std::vector<double> plate_starts(const HullPattern& p, int row) {
  const Rng cut{p.seed, kCut, uint64_t(row)};
  const double mean = double(kTexels) / p.plates_per_row;
  std::vector<double> starts{0.0};
  for (int i = 1; i < p.plates_per_row; ++i) starts.push_back(i * mean + cut.range(uint64_t(i), -0.3, 0.3) * mean);
  starts.push_back(double(kTexels));
  return starts;
}

// The detail value (1 = the material's own colour) of the texel whose centre is (x, y).
double hull_texel(const HullPattern& p, const std::vector<std::vector<double>>& rows, double x, double y) {
  const double row_height = double(kTexels) / p.rows;
  const int row = std::min(int(y / row_height), p.rows - 1);
  const double in_row = y - row * row_height;
  const double offset = Rng{p.seed, kRowOffset, 0}.uniform(uint64_t(row)) * kTexels;
  const double u = std::fmod(x - offset + 2.0 * kTexels, double(kTexels));
  const std::vector<double>& starts = rows[size_t(row)];
  size_t plate = 0;
  while (plate + 2 < starts.size() && u >= starts[plate + 1]) ++plate;
  const double left = u - starts[plate], right = starts[plate + 1] - u;
  const double seam = std::min({left, right, in_row, row_height - in_row});
  const uint64_t key = uint64_t(row) * 64u + plate;
  double v = 1.0 - p.tone_spread * Rng{p.seed, kTone, 0}.uniform(key);
  // Panel lines: a dark groove about two texels wide with a lit lip below and right of it.
  v *= 1.0 - 0.62 * gaussian_line(seam, 1.1);
  v *= 1.0 + 0.08 * gaussian_line(std::min(left, in_row) - 2.2, 0.8);
  // Fasteners: a dotted row just under each row's upper seam.
  const double along = std::fmod(u, 8.0) - 4.0, below = in_row - 3.5;
  v *= 1.0 - 0.35 * gaussian_line(std::sqrt(along * along + below * below), 1.0);
  // Some plates carry an inset hatch: a thin outline 6 texels inside the plate's edges.
  if (Rng{p.seed, kHatch, 0}.uniform(key) < p.hatch_share) {
    const double inset = std::min({left, right, in_row, row_height - in_row}) - 6.0;
    v *= 1.0 - 0.3 * gaussian_line(inset, 0.7);
  }
  // A faint grain, so large plates do not look like flat paint.
  v *= 0.975 + 0.025 * Rng{p.seed, kGrain, 0}.uniform(uint64_t(y) * kTexels + uint64_t(x));
  return std::clamp(v, 0.0, 1.0);
}

std::string read_bytes(const std::string& path) { return read_input_file(path, kMaxImageFileBytes, "a texture"); }

}  // namespace

std::string write_hull_texture(const std::string& path, const HullPattern& pattern) {
  std::vector<std::vector<double>> rows;
  for (int r = 0; r < pattern.rows; ++r) rows.push_back(plate_starts(pattern, r));
  Image img;
  img.width = kTexels;
  img.height = kTexels;
  img.rgba.resize(size_t(kTexels) * kTexels * 4);
  for (int y = 0; y < kTexels; ++y)
    for (int x = 0; x < kTexels; ++x) {
      // The value is the sRGB-encoded colour itself (detail around white), not linear light.
      const double v = hull_texel(pattern, rows, x + 0.5, y + 0.5);
      const uint8_t q = uint8_t(std::clamp(std::floor(v * 255.0 + 0.5), 0.0, 255.0));
      uint8_t* d = &img.rgba[(size_t(y) * kTexels + size_t(x)) * 4];
      d[0] = d[1] = d[2] = q;
      d[3] = 255;
    }
  save_image(path, img);
  return read_bytes(path);
}

}  // namespace arc::assetgen
