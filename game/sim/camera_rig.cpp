// game/sim/camera_rig.cpp — the simulated camera (chase, cockpit or fixed) and the view the
// particle world culls against.
#include "game/sim/camera_rig.h"

#include <cmath>

#include "game/sim/geometry.h"
#include "game/sim/world.h"

namespace arc {

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
  const double R = s.cls->collision_radius;
  if (w.camera_mode == CameraMode::Cockpit) {
    w.camera.orientation = s.orientation;
    w.camera.position = s.position + s.orientation * glm::dvec3(0, 0.25 * R, -0.3 * R);
    return;
  }
  // Chase: the camera's orientation follows the ship's with a short exponential lag, so turns
  // read on screen; the position is rebuilt from it each tick, so the ship never drifts away.
  double k = 1.0 - std::exp(-6.0 * w.dt);
  w.camera.orientation = glm::normalize(glm::slerp(w.camera.orientation, s.orientation, k));
  w.camera.position = s.position + w.camera.orientation * glm::dvec3(0, 0.45 * R + 2.0, 2.6 * R + 8.0);
}

ParticleCamera particle_camera(const World& w) {
  ParticleCamera c;
  c.position = w.camera.position;
  c.orientation = w.camera.orientation;
  c.fov_y_radians = w.level.camera.fov_deg * kDeg;
  return c;
}

}  // namespace arc
