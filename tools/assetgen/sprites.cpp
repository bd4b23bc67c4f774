// tools/assetgen/sprites.cpp — procedural particle sprites, straight (not premultiplied) alpha;
// load_sprite() premultiplies them at load time (Ilmonen 2006 eq. 10).
//
// Every sprite is a function of the pixel centre in [-1, 1]² multiplied by a border window that
// reaches exactly zero before the outermost pixel ring, so no sprite shows a hard square edge.
#include "sprites.h"
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include "assets/image.h"
#include "core/rng.h"

namespace arc::assetgen {
namespace {

constexpr int kSize = 128;
constexpr double kPi = 3.14159265358979323846;

struct Texel {
  glm::dvec3 color{1.0};
  double alpha = 0.0;
};

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// 1 inside radius 0.85, 0 from 0.97 outwards (the border pixel centres lie at 0.992).
double border_window(glm::dvec2 p) {
  return 1.0 - smoothstep(0.85, 0.97, glm::length(p));
}

uint8_t quantise(double v) { return uint8_t(std::clamp(std::floor(v * 255.0 + 0.5), 0.0, 255.0)); }

void write_sprite(const std::string& path, const std::function<Texel(glm::dvec2)>& shade) {
  Image img;
  img.width = kSize;
  img.height = kSize;
  img.rgba.resize(size_t(kSize) * kSize * 4);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      // Image rows run top to bottom; +Y in sprite space is up.
      const glm::dvec2 p((x + 0.5) / (kSize * 0.5) - 1.0, 1.0 - (y + 0.5) / (kSize * 0.5));
      Texel t = shade(p);
      const double a = std::clamp(t.alpha, 0.0, 1.0) * border_window(p);
      uint8_t* d = &img.rgba[(size_t(y) * kSize + size_t(x)) * 4];
      d[0] = quantise(t.color.r);
      d[1] = quantise(t.color.g);
      d[2] = quantise(t.color.b);
      d[3] = quantise(a);
      // Fully transparent texels carry no colour, so filtering never bleeds a stray value.
      if (d[3] == 0) d[0] = d[1] = d[2] = 0;
    }
  save_image(path, img);
}

// Value noise on an integer lattice, keyed by the lattice point, smoothly interpolated.
double value_noise(const Rng& rng, glm::dvec2 p, int period) {
  const double fx = std::floor(p.x), fy = std::floor(p.y);
  const int ix = int(fx), iy = int(fy);
  auto lattice = [&](int x, int y) {
    const int wx = ((x % period) + period) % period, wy = ((y % period) + period) % period;
    return rng.uniform(uint64_t(wy) * 1024u + uint64_t(wx));
  };
  const double tx = smoothstep(0.0, 1.0, p.x - fx), ty = smoothstep(0.0, 1.0, p.y - fy);
  const double a = lattice(ix, iy), b = lattice(ix + 1, iy), c = lattice(ix, iy + 1), d = lattice(ix + 1, iy + 1);
  return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

double fbm(uint64_t seed, glm::dvec2 p) {
  double sum = 0.0, amp = 0.5, norm = 0.0;
  int period = 4;
  for (uint64_t octave = 0; octave < 5; ++octave) {
    sum += amp * value_noise(Rng{seed, octave, 0}, p * double(period) * 0.5 + 0.5 * double(period), period);
    norm += amp;
    amp *= 0.5;
    period *= 2;
  }
  return sum / norm;
}

double segment_distance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + ab * t));
}

Texel blob(glm::dvec2 p) {
  const double r2 = glm::dot(p, p);
  return {{1.0, 1.0, 1.0}, std::exp(-r2 / (2.0 * 0.3 * 0.3))};
}

Texel glow(glm::dvec2 p) {
  // A long-tailed halo: bright centre, wide faint skirt.
  const double r = glm::length(p);
  const double halo = 0.35 / (1.0 + (r / 0.12) * (r / 0.12)) + 0.65 * std::exp(-r * r / 0.18);
  return {{1.0, 1.0, 1.0}, halo * (1.0 - smoothstep(0.5, 0.9, r) * 0.6)};
}

Texel spark(glm::dvec2 p) {
  // Long axis along +Y: thin across X, tapering towards both ends.
  const double across = std::exp(-(p.x * p.x) / (2.0 * 0.045 * 0.045));
  const double along = std::pow(std::max(0.0, 1.0 - p.y * p.y / 0.72), 1.5);
  const double core = std::exp(-(p.x * p.x) / (2.0 * 0.015 * 0.015));
  return {{1.0, 0.92 + 0.08 * core, 0.7 + 0.3 * core}, across * along};
}

// The Parsec lightning flare: a hot core with jagged rays that split and thin out.
struct Flare {
  std::vector<std::pair<glm::dvec2, glm::dvec2>> segments;
  std::vector<double> widths;

  Flare() {
    const Rng rng{0xF1A2E5u, 7, 0};
    const int rays = 11;
    for (int k = 0; k < rays; ++k) {
      double angle = 2.0 * kPi * (k + rng.range(uint64_t(k), -0.3, 0.3)) / rays;
      const double length = rng.range(100u + uint64_t(k), 0.5, 0.82);
      grow(rng, uint64_t(k) * 64u, {0.0, 0.0}, angle, length, 0.035, 0);
    }
  }

  // Lightning zig-zags around a straight heading instead of drifting, which keeps rays jagged.
  void grow(const Rng& rng, uint64_t key, glm::dvec2 from, double heading, double length, double width, int depth) {
    const int steps = 7;
    glm::dvec2 at = from;
    for (int s = 0; s < steps; ++s) {
      const double kink = heading + rng.range(key * 16u + uint64_t(s) + 1000u, -0.8, 0.8);
      const glm::dvec2 next = at + glm::dvec2(std::cos(kink), std::sin(kink)) * (length / steps);
      segments.push_back({at, next});
      widths.push_back(width * (1.0 - 0.7 * double(s) / steps));
      if (depth == 0 && (s == 2 || s == 4) && rng.uniform(key * 16u + uint64_t(s) + 5000u) < 0.6)
        grow(rng, key * 16u + uint64_t(s) + 9u, next, heading + rng.range(key * 16u + uint64_t(s) + 7000u, -1.0, 1.0),
             length * 0.35, width * 0.55, 1);
      at = next;
    }
  }

  Texel operator()(glm::dvec2 p) const {
    double rays = 0.0;
    for (size_t i = 0; i < segments.size(); ++i) {
      const double d = segment_distance(p, segments[i].first, segments[i].second) / widths[i];
      rays = std::max(rays, std::exp(-d * d));
    }
    const double r2 = glm::dot(p, p);
    const double core = std::exp(-r2 / (2.0 * 0.09 * 0.09));
    const double halo = 0.35 * std::exp(-r2 / (2.0 * 0.25 * 0.25));
    const double a = std::min(1.0, core + rays * 0.9 + halo);
    // Bluish white, whiter where the core dominates.
    const double white = std::min(1.0, core + 0.3 * rays);
    return {glm::mix(glm::dvec3(0.55, 0.75, 1.0), glm::dvec3(1.0), white), a};
  }
};

Texel smoke(glm::dvec2 p) {
  const double n = fbm(0x5E0CEu, p * 1.4);
  const double r = glm::length(p);
  // Noise erodes the edge of the puff, so the outline is ragged rather than a circle.
  const double shape = smoothstep(0.0, 0.55, 0.85 - r - (n - 0.5) * 0.6);
  const double density = shape * (0.45 + 0.55 * n);
  const double shade = 0.62 + 0.33 * fbm(0x5E0CF, p * 2.0 + 3.1);
  return {{shade, shade, shade * 1.02}, density};
}

Texel shield(glm::dvec2 p) {
  // Hexagonal cells: distance from p to the nearest cell centre of a hex lattice, measured in
  // the hexagon metric, gives 1 on cell edges and 0 at cell centres.
  const double scale = 5.0;
  const glm::dvec2 q = p * scale;
  const glm::dvec2 r(1.0, std::sqrt(3.0));
  const glm::dvec2 h = r * 0.5;
  auto mod = [](glm::dvec2 a, glm::dvec2 m) { return a - m * glm::floor(a / m); };
  const glm::dvec2 a = mod(q, r) - h;
  const glm::dvec2 b = mod(q - h, r) - h;
  const glm::dvec2 g = glm::dot(a, a) < glm::dot(b, b) ? a : b;
  const glm::dvec2 ag = glm::abs(g);
  const double hex = std::max(ag.x, glm::dot(ag, glm::dvec2(0.5, std::sqrt(3.0) * 0.5))) * 2.0;
  const double edge = std::exp(-std::pow((1.0 - hex) / 0.12, 2.0));
  const double radius = glm::length(p);
  const double falloff = 1.0 - smoothstep(0.3, 0.9, radius);
  const double a_total = falloff * (0.15 + 0.85 * edge);
  return {glm::mix(glm::dvec3(0.25, 0.85, 1.0), glm::dvec3(0.85, 1.0, 1.0), edge * falloff), a_total};
}

}  // namespace

int write_sprites(const std::string& dir) {
  write_sprite(dir + "/sprite_blob.png", blob);
  write_sprite(dir + "/sprite_glow.png", glow);
  write_sprite(dir + "/sprite_spark.png", spark);
  write_sprite(dir + "/sprite_flare.png", Flare());
  write_sprite(dir + "/sprite_smoke.png", smoke);
  write_sprite(dir + "/sprite_shield.png", shield);
  return 6;
}

}  // namespace arc::assetgen
