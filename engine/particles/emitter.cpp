#include "particles/emitter.h"

#include <algorithm>
#include <cmath>

namespace arc {
namespace {
constexpr double kTwoPi = 6.283185307179586;

glm::dvec3 normalized_or(const glm::dvec3& v, const glm::dvec3& fallback) {
  const double l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return l > 1e-12 ? v / l : fallback;
}
}  // namespace

glm::dvec3 uniform_direction(double u1, double u2) {
  const double z = 2.0 * u1 - 1.0;
  const double a = kTwoPi * u2;
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(a), r * std::sin(a), z};
}

glm::dvec3 cone_direction(double half_angle, double u1, double u2) {
  // cos θ uniform in [cos α, 1] is uniform over the spherical cap.
  const double c = 1.0 - u1 * (1.0 - std::cos(half_angle));
  const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
  const double a = kTwoPi * u2;
  return {s * std::cos(a), s * std::sin(a), -c};
}

EmitSample sample_emitter(const EmitterDef& e, const Rng& rng, uint64_t base) {
  auto u = [&](int k) { return rng.uniform(base + uint64_t(k)); };
  EmitSample s;
  glm::dvec3 outward = uniform_direction(u(0), u(1));
  switch (e.shape) {
    case EmitterShape::Point:
      s.position = e.offset;
      break;
    case EmitterShape::Sphere:
      s.position = e.offset + outward * (e.radius * std::cbrt(u(2)));
      break;
    case EmitterShape::SphereSurface:
      s.position = e.offset + outward * e.radius;
      break;
    case EmitterShape::Cone: {
      const double r = e.radius * std::sqrt(u(2)), a = kTwoPi * u(3);
      s.position = e.offset + e.axis_rotation * glm::dvec3(r * std::cos(a), r * std::sin(a), 0.0);
      outward = cone_direction(e.angle, u(4), u(5));
      break;
    }
    case EmitterShape::Box:
      s.position = e.offset + glm::dvec3((2.0 * u(2) - 1.0) * e.half_extents.x, (2.0 * u(3) - 1.0) * e.half_extents.y,
                                         (2.0 * u(4) - 1.0) * e.half_extents.z);
      break;
    case EmitterShape::Line:
      s.position = e.offset + glm::dvec3(0.0, 0.0, -(u(2) - 0.5) * e.length);
      break;
    case EmitterShape::Mesh: {
      const double pick = u(2) * e.area_prefix.back();
      size_t tri = size_t(std::upper_bound(e.area_prefix.begin(), e.area_prefix.end(), pick) - e.area_prefix.begin());
      tri = std::min(tri, e.area_prefix.size() - 1);
      const glm::dvec3& a = e.triangles[tri * 3];
      const glm::dvec3& b = e.triangles[tri * 3 + 1];
      const glm::dvec3& c = e.triangles[tri * 3 + 2];
      // Square-root warp: uniform over the triangle's area.
      const double r1 = std::sqrt(u(3)), r2 = u(4);
      s.position = e.offset + a * (1.0 - r1) + b * (r1 * (1.0 - r2)) + c * (r1 * r2);
      const glm::dvec3 ab = b - a, ac = c - a;
      outward = normalized_or(glm::dvec3(ab.y * ac.z - ab.z * ac.y, ab.z * ac.x - ab.x * ac.z, ab.x * ac.y - ab.y * ac.x),
                              outward);
      break;
    }
  }
  switch (e.direction) {
    case EmitDirection::Shape: s.direction = outward; break;
    case EmitDirection::Random: s.direction = uniform_direction(u(6), u(7)); break;
    case EmitDirection::Forward: s.direction = {0.0, 0.0, -1.0}; break;
  }
  // Cone and forward directions are sampled around −Z, then turned onto the emitter's axis.
  if (e.shape == EmitterShape::Cone || e.direction == EmitDirection::Forward) s.direction = e.axis_rotation * s.direction;
  return s;
}

}  // namespace arc
