#include "particles/lightning_channel.h"

#include <algorithm>
#include <cmath>

#include "particles/emitter.h"

namespace arc {

double LightningChannel::length() const {
  double total = 0.0;
  for (size_t i = 1; i < points.size(); ++i) {
    const glm::dvec3 d = points[i] - points[i - 1];
    total += std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  }
  return total;
}

glm::dvec3 LightningChannel::point_at(double distance) const {
  if (points.empty()) return origin;
  double along = 0.0;
  for (size_t i = 1; i < points.size(); ++i) {
    const glm::dvec3 d = points[i] - points[i - 1];
    const double seg = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (along + seg >= distance) {
      if (seg <= 0.0) return points[i - 1];
      return points[i - 1] + d * (std::max(0.0, distance - along) / seg);
    }
    along += seg;
  }
  return points.back();
}

uint64_t lightning_epoch(uint64_t tick, uint64_t spawn_tick, int interval) {
  if (tick <= spawn_tick || interval <= 1) return std::max(tick, spawn_tick);
  return tick - (tick - spawn_tick) % uint64_t(interval);
}

void build_lightning(const LightningDef& def, double scale, const Rng& rng, LightningChannel& ch) {
  const glm::dvec3 dir = ch.direction;
  // An orthonormal basis around the seed direction; the helper axis avoids the parallel case.
  const glm::dvec3 helper = std::fabs(dir.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  glm::dvec3 b1(helper.y * dir.z - helper.z * dir.y, helper.z * dir.x - helper.x * dir.z, helper.x * dir.y - helper.y * dir.x);
  b1 /= std::sqrt(b1.x * b1.x + b1.y * b1.y + b1.z * b1.z);
  const glm::dvec3 b2(dir.y * b1.z - dir.z * b1.y, dir.z * b1.x - dir.x * b1.z, dir.x * b1.y - dir.y * b1.x);

  const double seed = def.seed_length * scale;
  const double max_length = def.max_length * scale;
  ch.points.clear();
  ch.points.push_back(ch.origin);
  ch.points.push_back(ch.origin + dir * seed);
  double total = seed;
  for (uint64_t i = 1;; ++i) {
    const double len = seed * (1.0 + def.length_jitter * (2.0 * rng.uniform(i * 4 + 2) - 1.0));
    if (total + len > max_length) break;
    const glm::dvec3 local = cone_direction(def.max_angle, rng.uniform(i * 4), rng.uniform(i * 4 + 1));
    // cone_direction opens around −Z; map −Z to the seed direction.
    const glm::dvec3 d = b1 * local.x + b2 * local.y + dir * (-local.z);
    ch.points.push_back(ch.points.back() + d * len);
    total += len;
  }
}

}  // namespace arc
