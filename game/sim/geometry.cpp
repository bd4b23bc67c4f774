// game/sim/geometry.cpp — orientations from degrees and the segment/sphere intersection.
#include "game/sim/geometry.h"

#include <algorithm>

namespace arc {

glm::dquat orientation_from_degrees(const glm::dvec3& ypr) {
  // Yaw about +Y (positive turns the nose left), then pitch about the yawed +X (positive raises
  // the nose), then roll about the resulting −Z (positive banks right).
  glm::dquat yaw = glm::angleAxis(ypr.x * kDeg, glm::dvec3(0, 1, 0));
  glm::dquat pitch = glm::angleAxis(ypr.y * kDeg, glm::dvec3(1, 0, 0));
  glm::dquat roll = glm::angleAxis(ypr.z * kDeg, glm::dvec3(0, 0, -1));
  return glm::normalize(yaw * pitch * roll);
}

double segment_sphere(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double r) {
  glm::dvec3 d = b - a, m = a - c;
  double cc = glm::dot(m, m) - r * r;
  if (cc <= 0) return 0.0;  // starts inside
  double aa = glm::dot(d, d);
  if (aa <= 0) return -1.0;
  double bb = glm::dot(m, d);
  double disc = bb * bb - aa * cc;
  if (disc < 0 || bb > 0) return -1.0;
  double t = (-bb - std::sqrt(disc)) / aa;
  return t <= 1.0 ? std::max(t, 0.0) : -1.0;
}

}  // namespace arc
