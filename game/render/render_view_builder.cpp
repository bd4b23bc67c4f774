// World → RenderView: the frame's camera, meshes and particles, interpolated by alpha; the HUD
// comes from hud_layout.cpp.
#include "game/render/render_view_builder.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "game/render/chase_framing.h"
#include "game/render/own_view.h"
#include "game/render/screen_projection.h"
#include "game/render/team_colors.h"
#include "game/sim/world.h"

namespace arc {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Ships as the mesh pass draws them at `alpha`; collect() places their attached clusters
// (shield, exhausts, beams) in the same pose, so they sit on the mesh between ticks. Ships get
// their particle owners in ship order at level start, so the list is sorted by owner as
// collect() needs. Projectiles have no mesh and keep their tick pose.
std::vector<DrawnOwner> drawn_ships(const World& w, double alpha) {
  std::vector<DrawnOwner> out;
  for (const Ship& s : w.ships)
    if (s.alive)
      out.push_back({s.particle_owner, lerp_pos(s.prev_position, s.position, alpha),
                     glm::normalize(glm::slerp(s.prev_orientation, s.orientation, alpha))});
  return out;
}

ModelId model_of(std::span<const ModelId> models, ModelSlot slot) {
  return slot && slot.index() < models.size() ? models[slot.index()] : ModelId{};
}

}  // namespace

const std::vector<std::string>& required_models(const World& world) { return world.model_paths; }

// Camera: the World's smoothed rig (deterministic), interpolated like everything else.
CameraView frame_camera(const World& w, double alpha, const CameraSettings& cs) {
  alpha = std::clamp(alpha, 0.0, 1.0);
  const CameraMode mode = cs.mode.value_or(w.camera_mode);
  CameraView cam;
  cam.fov_y_radians = (cs.fov_deg > 0 ? cs.fov_deg : w.level.camera.fov_deg) * kPi / 180.0;
  if (mode == CameraMode::Fixed || !w.focus_ship()) {
    cam.position = w.level.camera.position;
    glm::dvec3 d = w.level.camera.look_at - w.level.camera.position;
    double l = std::sqrt(glm::dot(d, d));
    d = l > 1e-9 ? d / l : glm::dvec3(0, 0, -1);
    cam.orientation = glm::quatLookAt(d, std::fabs(d.y) > 0.999 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0));
  } else {
    cam.position = lerp_pos(w.prev_camera.position, w.camera.position, alpha);
    cam.orientation = glm::normalize(glm::slerp(w.prev_camera.orientation, w.camera.orientation, alpha));
    if (mode == CameraMode::Chase) {
      // The view lifts over the own hull when it would hide a hostile ahead (chase_framing.h).
      lift_chase_view(w, alpha, cam.position, cam.orientation);
    }
  }
  return cam;
}

void build_render_view(const World& w, std::span<const ModelId> models, double alpha, const CameraSettings& cs, const HudState& hud, int width,
                       int height, RenderView& out) {
  alpha = std::clamp(alpha, 0.0, 1.0);
  width = std::max(width, 1);
  height = std::max(height, 1);
  out.meshes.clear();
  out.particles.clear();
  out.starfield_seed = w.seed;
  // Game time between the previous tick and this one (a paused game stands still).
  out.time_seconds = (double(w.tick) - 1.0 + alpha) * w.dt;

  const CameraMode mode = cs.mode.value_or(w.camera_mode);
  const CameraView& cam = out.camera = frame_camera(w, alpha, cs);
  const ShipId focus = w.focus_ship();
  const bool cockpit = mode == CameraMode::Cockpit;

  const double flash_s = 0.5;
  for (const Ship& s : w.ships) {
    if (!s.alive || (cockpit && s.id == focus)) continue;
    MeshInstance m;
    m.model = model_of(models, s.model);
    m.position = lerp_pos(s.prev_position, s.position, alpha);
    m.orientation = glm::normalize(glm::slerp(s.prev_orientation, s.orientation, alpha));
    // The afterburner is full boost whatever the set throttle, so it glows the brightest.
    m.emissive_boost = s.afterburner_on ? 3.0f : 1.0f + float(std::max(0.0, axis_value(s.controls.throttle)));
    m.team_color = ship_team_color(w, s);
    for (const ExplosionEvent& e : w.explosions) {
      double age = double(w.tick - e.tick) * w.dt;
      double d = std::sqrt(glm::dot(m.position - e.position, m.position - e.position));
      double k = std::max(0.0, 1.0 - age / flash_s) * std::max(0.0, 1.0 - d / (e.radius * 4.0));
      m.flash += glm::vec3(1.0f, 0.6f, 0.25f) * float(2.0 * k);
    }
    out.meshes.push_back(m);
  }
  // A capital ship breaking up: its wreck drifts and turns, darkened and lit by its blasts.
  for (const BreakUp& b : w.breakups) {
    const Ship& s = w.ship(b.ship);
    MeshInstance m;
    m.model = model_of(models, s.model);
    m.position = lerp_pos(b.prev_position, b.position, alpha);
    m.orientation = glm::normalize(glm::slerp(b.prev_orientation, b.orientation, alpha));
    m.emissive_boost = 0.0f;
    m.team_color = ship_team_color(w, s);
    for (const ExplosionEvent& e : w.explosions) {
      const double age = double(w.tick - e.tick) * w.dt;
      m.flash += glm::vec3(1.0f, 0.55f, 0.2f) * float(1.5 * std::max(0.0, 1.0 - age / flash_s));
    }
    out.meshes.push_back(m);
  }
  for (const Prop& p : w.props) {
    MeshInstance m;
    m.model = model_of(models, p.model);
    m.position = p.position;
    m.orientation = p.orientation;
    m.scale = p.scale;
    out.meshes.push_back(m);
  }

  ParticleCamera pc;
  pc.position = cam.position;
  pc.orientation = cam.orientation;
  pc.fov_y_radians = cam.fov_y_radians;
  pc.aspect = double(width) / double(height);
  pc.near_plane = cam.near_plane;
  if (mode != CameraMode::Fixed && w.focus_ship())
    pc.velocity = (w.camera.position - w.prev_camera.position) / w.dt;  // sparks streak relative to the eye
  w.particles->collect(pc, out.particles, drawn_ships(w, alpha));
  tint_exhausts(w, out.particles);
  if (mode != CameraMode::Fixed)
    keep_own_effects_out_of_view(w, focus, cockpit, cam, alpha, width, height, hud.rules.own_view, out.particles);

  layout_hud(w, cam, hud, alpha, width, height, out.hud);
}

}  // namespace arc
