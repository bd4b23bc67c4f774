// game/render/screen_projection.h — the frame camera's projection to pixels (origin top-left),
// shared by the HUD layout and the own-view rules (no GL).
//
// Projector::of(camera, width, height) matches the renderer's perspective (vertical field of
// view, square pixels); project() refuses points behind the near plane. crosshair_point() is
// where the HUD draws the crosshair: on the nose line at the target's range, or half the beam's
// range ahead of the nose without a target ahead.
#pragma once
#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "game/sim/world.h"
#include "gfx/render_view.h"

namespace arc {

struct Projector {
  glm::dvec3 position;
  glm::dquat inverse;
  double focal, cx, cy, near_plane;

  static Projector of(const CameraView& cam, int width, int height) {
    return {cam.position, glm::conjugate(cam.orientation), (height * 0.5) / std::tan(cam.fov_y_radians * 0.5),
            width * 0.5, height * 0.5, cam.near_plane};
  }
  glm::dvec3 to_view(const glm::dvec3& p) const { return inverse * (p - position); }
  bool project(const glm::dvec3& world, glm::dvec2& px, double* depth = nullptr) const {
    glm::dvec3 v = to_view(world);
    if (v.z > -near_plane) return false;
    px = {cx + v.x / -v.z * focal, cy - v.y / -v.z * focal};
    if (depth) *depth = -v.z;
    return true;
  }
};

inline glm::dvec3 lerp_pos(const glm::dvec3& a, const glm::dvec3& b, double t) { return a + (b - a) * t; }

// Half the beam's range ahead of the nose, with the ship's transform interpolated by alpha.
inline glm::dvec3 crosshair_point(const Ship& s, double alpha) {
  const glm::dvec3 pos = lerp_pos(s.prev_position, s.position, alpha);
  const glm::dquat q = glm::slerp(s.prev_orientation, s.orientation, alpha);
  return pos + forward_of(q) * s.cls->beam.range * 0.5;
}

// Where the crosshair stands for `s` in `w`: the nose line at its target's range when a live
// target lies ahead (within the beam's range), so the crosshair on the brackets means the nose
// on the target however far the chase eye sits above the nose line; else crosshair_point(s, alpha).
inline glm::dvec3 crosshair_point(const World& w, const Ship& s, double alpha) {
  const glm::dvec3 pos = lerp_pos(s.prev_position, s.position, alpha);
  const glm::dquat q = glm::slerp(s.prev_orientation, s.orientation, alpha);
  const glm::dvec3 nose = forward_of(q);
  double range = s.cls->beam.range * 0.5;
  if (s.target && w.ship(s.target).alive) {
    const Ship& t = w.ship(s.target);
    const double ahead = glm::dot(lerp_pos(t.prev_position, t.position, alpha) - pos, nose);
    if (ahead > 0.0) range = std::clamp(ahead, s.cls->beam.range * 0.1, s.cls->beam.range);
  }
  return pos + nose * range;
}

}  // namespace arc
