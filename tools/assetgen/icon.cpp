// tools/assetgen/icon.cpp — the application icon: a round night-sky badge with a rim, keyed stars,
// a fire trail sweeping around the bottom and a pale arrowhead fighter at its head. Each pixel
// averages 4×4 samples (soft edges at icon sizes); the result is straight alpha, transparent
// outside the disc.
#include "icon.h"
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include "assets/image.h"
#include "core/rng.h"

namespace arc::assetgen {
namespace {

constexpr int kSize = 256;
constexpr int kSamples = 4;  // per axis
constexpr double kPi = 3.14159265358979323846;
constexpr double kTrailRadius = 0.58;
constexpr double kTrailSweep = 200.0 * kPi / 180.0;  // the trail reaches this far behind the ship
constexpr int kStars = 40;

struct Sample {
  glm::dvec3 color{0.0};
  double alpha = 0.0;
};

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

bool in_triangle(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  const double d1 = cross(b - a, p - a), d2 = cross(c - b, p - b), d3 = cross(a - c, p - c);
  return (d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0);
}

// Trail glow at p: the ship sits at angle 0 on the trail circle flying +Y; the trail runs back
// clockwise through the bottom, thinning and cooling from white-yellow to red.
glm::dvec3 trail(glm::dvec2 p) {
  const double r = glm::length(p);
  double behind = -std::atan2(p.y, p.x);  // 0 at the ship, growing clockwise; a little ahead < 0
  if (behind < -0.5) behind += 2.0 * kPi;
  if (behind > kTrailSweep) return glm::dvec3(0.0);
  const double s = std::max(behind, 0.0) / kTrailSweep;  // 0 at the ship, 1 at the tail's end
  const double width = 0.015 + 0.06 * (1.0 - s);
  const double d = (r - kTrailRadius) / width;
  const double core = std::exp(-d * d * 2.0), glow = 0.3 * std::exp(-d * d * 0.5);
  // The fire starts under the ship's tail and ends in a point, with no hard edge ahead of it.
  const double head = behind < 0.0 ? std::exp(-std::pow(behind / 0.05, 2.0)) : 1.0;
  const double fade = std::pow(1.0 - s, 1.3) * head;
  const glm::dvec3 hot(1.0, 0.95, 0.7), warm(1.0, 0.55, 0.1), cool(0.8, 0.15, 0.05);
  const glm::dvec3 tint = s < 0.4 ? glm::mix(hot, warm, s / 0.4) : glm::mix(warm, cool, (s - 0.4) / 0.6);
  return tint * (core + glow) * fade;
}

Sample shade(glm::dvec2 p, const Rng& stars) {
  Sample out;
  const double r = glm::length(p);
  if (r > 0.95) return out;
  out.alpha = 1.0;
  // Night sky, lighter at the centre, with a blue rim.
  out.color = glm::mix(glm::dvec3(0.07, 0.11, 0.26), glm::dvec3(0.02, 0.03, 0.09), r / 0.95);
  const double rim = std::exp(-std::pow((r - 0.925) / 0.018, 2.0));
  out.color = glm::mix(out.color, glm::dvec3(0.3, 0.5, 0.9), rim);
  for (uint64_t i = 0; i < kStars; ++i) {
    const glm::dvec2 at(stars.range(i * 3, -0.75, 0.75), stars.range(i * 3 + 1, -0.75, 0.75));
    const double size = 0.004 + 0.006 * stars.uniform(i * 3 + 2);
    const double d2 = glm::dot(p - at, p - at);
    out.color += glm::dvec3(0.85, 0.9, 1.0) * std::exp(-d2 / (2.0 * size * size)) * 0.8;
  }
  out.color += trail(p);
  // The fighter: an arrowhead with a notched tail, nose along +Y, and its canopy.
  const glm::dvec2 ship(kTrailRadius, 0.0), h(0.0, 1.0), n(1.0, 0.0);
  const glm::dvec2 nose = ship + h * 0.2, right = ship - h * 0.1 + n * 0.11, left = ship - h * 0.1 - n * 0.11,
                   notch = ship - h * 0.04;
  if (in_triangle(p, nose, right, notch) || in_triangle(p, nose, notch, left)) {
    const double lit = 0.8 + 0.2 * glm::dot(glm::normalize(p - ship + glm::dvec2(1e-9)), glm::dvec2(-0.6, 0.8));
    out.color = glm::dvec3(0.86, 0.89, 0.93) * lit;
    const glm::dvec2 canopy = ship + h * 0.05;
    if (glm::length(p - canopy) < 0.028) out.color = glm::dvec3(0.3, 0.8, 1.0);
  }
  return out;
}

uint8_t quantise(double v) { return uint8_t(std::clamp(std::floor(v * 255.0 + 0.5), 0.0, 255.0)); }

}  // namespace

void write_icon(const std::string& path) {
  const Rng stars{0x1C0Au, 1, 0};
  Image img;
  img.width = kSize;
  img.height = kSize;
  img.rgba.resize(size_t(kSize) * kSize * 4);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      glm::dvec3 premultiplied(0.0);
      double alpha = 0.0;
      for (int sy = 0; sy < kSamples; ++sy)
        for (int sx = 0; sx < kSamples; ++sx) {
          // Image rows run top to bottom; +Y in icon space is up.
          const double u = (x + (sx + 0.5) / kSamples) / (kSize * 0.5) - 1.0;
          const double v = 1.0 - (y + (sy + 0.5) / kSamples) / (kSize * 0.5);
          const Sample s = shade({u, v}, stars);
          premultiplied += glm::clamp(s.color, 0.0, 1.0) * s.alpha;
          alpha += s.alpha;
        }
      uint8_t* d = &img.rgba[(size_t(y) * kSize + size_t(x)) * 4];
      const glm::dvec3 c = alpha > 0.0 ? premultiplied / alpha : glm::dvec3(0.0);
      d[0] = quantise(c.r);
      d[1] = quantise(c.g);
      d[2] = quantise(c.b);
      d[3] = quantise(alpha / (kSamples * kSamples));
      if (d[3] == 0) d[0] = d[1] = d[2] = 0;
    }
  save_image(path, img);
}

}  // namespace arc::assetgen
