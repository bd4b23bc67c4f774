// The workbench's orbit camera (see the header).
#include "game/workbench/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>

namespace arc {
namespace {
constexpr double kRadiansPerPixel = 0.3 * 3.14159265358979 / 180.0;
constexpr double kPitchLimit = 1.55;  // a little short of ±90°
constexpr double kMinDistance = 0.2, kMaxDistance = 50000.0;
}  // namespace

void OrbitCamera::drag(double dx_pixels, double dy_pixels) {
  yaw -= dx_pixels * kRadiansPerPixel;
  pitch = std::clamp(pitch - dy_pixels * kRadiansPerPixel, -kPitchLimit, kPitchLimit);
}

void OrbitCamera::zoom(double wheel_steps) {
  distance = std::clamp(distance * std::pow(0.8, wheel_steps), kMinDistance, kMaxDistance);
}

// The distance at which the sphere just fits the vertical field of view, with a margin.
void OrbitCamera::frame(const glm::dvec3& centre, double radius) {
  target = centre;
  const double fit = std::max(radius, 0.1) / std::sin(fov_y * 0.5);
  distance = std::clamp(fit * 1.15, kMinDistance, kMaxDistance);
}

CameraView OrbitCamera::view() const {
  const glm::dquat q = glm::angleAxis(yaw, glm::dvec3(0, 1, 0)) * glm::angleAxis(pitch, glm::dvec3(1, 0, 0));
  CameraView v;
  v.orientation = q;
  v.position = target + q * glm::dvec3(0, 0, distance);  // the camera looks along its −Z at the target
  v.fov_y_radians = fov_y;
  v.near_plane = std::max(0.05, distance * 0.01);
  return v;
}

}  // namespace arc
