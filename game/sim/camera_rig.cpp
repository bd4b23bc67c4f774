// game/sim/camera_rig.cpp — the simulated camera (chase, padlock, cockpit or fixed) and the view
// the particle world culls against.
#include "game/sim/camera_rig.h"

#include <algorithm>
#include <cmath>

#include "game/sim/geometry.h"
#include "game/sim/world.h"

namespace arc {
namespace {

glm::dvec3 chase_offset(const Ship& s, const ChaseFraming& f) {
  const double R = s.cls->collision_radius;
  return {0.0, f.up_per_radius * R + f.up_m, f.back_per_radius * R + f.back_m};
}

// The view's turn below the attitude it follows (the rig stores attitude * tilt).
glm::dquat tilt(const ChaseFraming& f) { return glm::angleAxis(-f.tilt_down_deg * kDeg, glm::dvec3(1, 0, 0)); }

// The angle between two attitudes, radians.
double angle_between(const glm::dquat& a, const glm::dquat& b) {
  return 2.0 * std::acos(std::min(1.0, std::fabs(glm::dot(a, b))));
}

}  // namespace

CameraRig chase_rig(const CameraRig& prev, const Ship& s, double dt, const ChaseFraming& f) {
  // The orientation follows the ship's with a short exponential lag, so turns read on screen,
  // but never more than max_lag_deg behind: the ship's centre stays put on screen (the position
  // is rebuilt from the view), and a larger lag would swing a target at the nose into the hull.
  const glm::dquat t = tilt(f);
  const double k = 1.0 - std::exp(-f.lag_rate * dt);
  glm::dquat attitude = glm::normalize(glm::slerp(prev.orientation * glm::conjugate(t), s.orientation, k));
  const double lag = angle_between(attitude, s.orientation), most = f.max_lag_deg * kDeg;
  if (lag > most) attitude = glm::normalize(glm::slerp(s.orientation, attitude, most / lag));
  CameraRig c;
  c.position = s.position + attitude * chase_offset(s, f);
  c.orientation = glm::normalize(attitude * t);
  return c;
}

CameraRig padlock_rig(const CameraRig& prev, const Ship& s, const Ship& target, double dt, const ChaseFraming& f) {
  // The view turns to the target, its up the ship's as far as the two allow; the camera keeps
  // the chase offset in that view, so the own hull stays low on screen under the target.
  const glm::dvec3 ahead = forward_of(s.orientation);
  const glm::dvec3 look = safe_norm(target.position - s.position, ahead);
  glm::dvec3 up = s.orientation * glm::dvec3(0, 1, 0);
  if (std::fabs(glm::dot(look, up)) > 0.999) up = s.orientation * glm::dvec3(0, 0, 1);
  const glm::dquat want = glm::quatLookAt(look, up);
  const glm::dquat t = tilt(f);
  const double k = 1.0 - std::exp(-2.0 * f.lag_rate * dt);
  const glm::dquat attitude = glm::normalize(glm::slerp(prev.orientation * glm::conjugate(t), want, k));
  CameraRig c;
  c.position = s.position + attitude * chase_offset(s, f);
  c.orientation = glm::normalize(attitude * t);
  return c;
}

void update_camera(World& w) {
  w.prev_camera = w.camera;
  if (w.camera_mode == CameraMode::Fixed) {
    w.camera.position = w.level.camera.position;
    glm::dvec3 dir = safe_norm(w.level.camera.look_at - w.level.camera.position, glm::dvec3(0, 0, -1));
    w.camera.orientation = glm::quatLookAt(dir, std::fabs(dir.y) > 0.999 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0));
    return;
  }
  const ShipId f = w.focus_ship();
  if (!f) return;
  const Ship& s = w.ship(f);
  if (w.camera_mode == CameraMode::Cockpit) {
    const double R = s.cls->collision_radius;
    w.camera.orientation = s.orientation;
    w.camera.position = s.position + s.orientation * glm::dvec3(0, 0.25 * R, -0.3 * R);
    return;
  }
  if (w.camera_mode == CameraMode::Padlock && s.target && w.ship(s.target).alive) {
    w.camera = padlock_rig(w.camera, s, w.ship(s.target), w.dt);
    return;
  }
  w.camera = chase_rig(w.camera, s, w.dt);
}

ParticleCamera particle_camera(const World& w) {
  ParticleCamera c;
  c.position = w.camera.position;
  c.orientation = w.camera.orientation;
  c.fov_y_radians = w.level.camera.fov_deg * kDeg;
  return c;
}

}  // namespace arc
