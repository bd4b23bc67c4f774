// game/sim/geometry.h — the simulation's vector helpers and angle conventions (internal to
// game/sim and its tests; game/render keeps its own constants).
//
// Lengths and normalisations are guarded (a zero vector normalises to a given fallback);
// orientations in data files are degrees of yaw, pitch and roll; beams, projectiles and their
// tests share one segment/sphere intersection.
#pragma once
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace arc {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDeg = kPi / 180.0;

inline double safe_len(const glm::dvec3& v) { return std::sqrt(glm::dot(v, v)); }
inline glm::dvec3 safe_norm(const glm::dvec3& v, const glm::dvec3& fallback) {
  double l = safe_len(v);
  return l > 1e-12 ? v / l : fallback;
}

// Yaw about +Y (positive turns the nose left), then pitch, then roll (positive banks right).
glm::dquat orientation_from_degrees(const glm::dvec3& yaw_pitch_roll);
// Ray/segment against a sphere: smallest t in [0, 1] of a + t(b − a) on the sphere, or −1.
double segment_sphere(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& centre, double radius);

}  // namespace arc
