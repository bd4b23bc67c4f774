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

namespace {

// An orthonormal pair perpendicular to a unit direction; the helper axis avoids the parallel case.
void basis_around(const glm::dvec3& dir, glm::dvec3& b1, glm::dvec3& b2) {
  const glm::dvec3 helper = std::fabs(dir.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  b1 = glm::dvec3(helper.y * dir.z - helper.z * dir.y, helper.z * dir.x - helper.x * dir.z, helper.x * dir.y - helper.y * dir.x);
  b1 /= std::sqrt(b1.x * b1.x + b1.y * b1.y + b1.z * b1.z);
  b2 = glm::dvec3(dir.y * b1.z - dir.z * b1.y, dir.z * b1.x - dir.x * b1.z, dir.x * b1.y - dir.y * b1.x);
}

// A guided segment's axis: from its start toward the seed line's point `guide` ahead of it.
glm::dvec3 guide_axis(const LightningChannel& ch, const glm::dvec3& from, double guide) {
  const glm::dvec3 rel = from - ch.origin;
  const double along = rel.x * ch.direction.x + rel.y * ch.direction.y + rel.z * ch.direction.z;
  const glm::dvec3 to = ch.origin + ch.direction * (along + guide) - from;
  return to / std::sqrt(to.x * to.x + to.y * to.y + to.z * to.z);
}

}  // namespace

void build_lightning(const LightningDef& def, double scale, const Rng& rng, LightningChannel& ch) {
  const glm::dvec3 dir = ch.direction;
  glm::dvec3 b1, b2;
  basis_around(dir, b1, b2);

  const double seed = def.seed_length * scale;
  const double max_length = def.max_length * scale;
  const double guide = def.guide_distance * scale;
  ch.points.clear();
  ch.points.push_back(ch.origin);
  ch.points.push_back(ch.origin + dir * seed);
  double total = seed;
  for (uint64_t i = 1;; ++i) {
    const double len = seed * (1.0 + def.length_jitter * (2.0 * rng.uniform(i * 4 + 2) - 1.0));
    if (total + len > max_length) break;
    const glm::dvec3 local = cone_direction(def.max_angle, rng.uniform(i * 4), rng.uniform(i * 4 + 1));
    glm::dvec3 axis = dir, a1 = b1, a2 = b2;
    if (guide > 0.0) {
      axis = guide_axis(ch, ch.points.back(), guide);
      basis_around(axis, a1, a2);
    }
    // cone_direction opens around −Z; map −Z to the segment's axis.
    const glm::dvec3 d = a1 * local.x + a2 * local.y + axis * (-local.z);
    ch.points.push_back(ch.points.back() + d * len);
    total += len;
  }
}

}  // namespace arc
