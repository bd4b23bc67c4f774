// The followed ship's own effects, edited in the frame's particle list (see own_view.h).
#include "game/render/own_view.h"

#include <algorithm>
#include <cmath>

#include "game/render/screen_projection.h"
#include "game/sim/world.h"

namespace arc {
namespace {

enum class ViewKind { Other, OwnShield, OwnExhaust, OwnBeam, OtherBeam };

// The clusters the rules touch, by ClusterHandle::index (as ParticleInstance::cluster).
struct ViewClusters {
  std::vector<uint32_t> shield, exhaust, beam, other_beams;

  static ViewClusters of(const World& w, const Ship& me) {
    ViewClusters o;
    for (ClusterHandle h : me.shield_fx.clusters) o.shield.push_back(h.index);
    for (const EffectHandle& e : me.exhaust_fx)
      for (ClusterHandle h : e.clusters) o.exhaust.push_back(h.index);
    for (ClusterHandle h : me.beam_channels) o.beam.push_back(h.index);
    for (const Ship& s : w.ships)
      if (s.id != me.id)
        for (ClusterHandle h : s.beam_channels) o.other_beams.push_back(h.index);
    return o;
  }
  ViewKind kind(uint32_t cluster) const {
    auto has = [cluster](const std::vector<uint32_t>& v) { return std::find(v.begin(), v.end(), cluster) != v.end(); };
    if (has(shield)) return ViewKind::OwnShield;
    if (has(exhaust)) return ViewKind::OwnExhaust;
    if (has(beam)) return ViewKind::OwnBeam;
    if (has(other_beams)) return ViewKind::OtherBeam;
    return ViewKind::Other;
  }
};

double smoothstep01(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

void scale_color(ParticleInstance& p, double k) {
  for (float& c : p.color) c *= float(k);
}

// The particle in view space (camera at the origin looking along −Z): its offset is already
// camera-relative, so only the rotation remains.
glm::dvec3 view_space(const ParticleInstance& p, const glm::dquat& inverse) {
  return inverse * glm::dvec3(p.pos[0], p.pos[1], p.pos[2]);
}

// Chase camera: how much of a shield particle stays, by how far its quad lies from the crosshair.
double shield_visibility(const ParticleInstance& p, const Projector& pr, glm::dvec2 crosshair, double height,
                         const OwnViewRules& rules) {
  const glm::dvec3 v = view_space(p, pr.inverse);
  if (v.z > -pr.near_plane) return 0.0;
  const glm::dvec2 px(pr.cx + v.x / -v.z * pr.focal, pr.cy - v.y / -v.z * pr.focal);
  const double reach = std::max(double(p.size), 0.0) / -v.z * pr.focal * std::sqrt(2.0);
  const glm::dvec2 d = px - crosshair;
  const double gap = std::sqrt(d.x * d.x + d.y * d.y) - reach - rules.clear_radius * height;
  return smoothstep01(gap / std::max(rules.clear_fade * height, 1e-9));
}

// Chase camera: how much of a shield particle stays by how edge-on the sphere is seen there, so
// the sphere reads as a thin rim. `centre` is the ship's centre, camera-relative like p.pos.
double rim_visibility(const ParticleInstance& p, const glm::dvec3& centre, const OwnViewRules& rules) {
  const glm::dvec3 at(p.pos[0], p.pos[1], p.pos[2]);
  const glm::dvec3 normal = at - centre;
  const double ln = std::sqrt(glm::dot(normal, normal)), la = std::sqrt(glm::dot(at, at));
  if (ln < 1e-9 || la < 1e-9) return 0.0;
  const double facing = std::fabs(glm::dot(normal, at)) / (ln * la);
  return 1.0 - smoothstep01((facing - rules.rim_facing) / std::max(rules.rim_fade, 1e-9));
}

// Either camera: a beam is at most `half_width` (share of the screen height) wide on screen and
// fades out over `near_fade` metres toward the eye (0: no fade). False when nothing is left.
bool tame_beam(ParticleInstance& p, const Projector& pr, double height, double half_width, double near_fade) {
  const glm::dvec3 v = view_space(p, pr.inverse);
  const double depth = -v.z;
  if (depth <= pr.near_plane) return false;
  const double widest = half_width * height * depth / pr.focal;
  p.size = float(std::min(double(p.size), widest));
  const double dist = std::sqrt(glm::dot(v, v));
  const double fade = near_fade > 0 ? smoothstep01(dist / near_fade) : 1.0;
  scale_color(p, fade);
  return fade > 0.0;
}

}  // namespace

void keep_own_effects_out_of_view(const World& w, ShipId ship, bool cockpit, const CameraView& camera, double alpha,
                                  int width, int height, const OwnViewRules& rules,
                                  std::vector<ParticleInstance>& particles) {
  if (!ship || ship.index() >= w.ships.size()) return;
  const Ship& me = w.ship(ship);
  const ViewClusters clusters = ViewClusters::of(w, me);
  const Projector pr = Projector::of(camera, width, height);
  glm::dvec2 crosshair(pr.cx, pr.cy);
  pr.project(crosshair_point(w, me, alpha), crosshair);
  const glm::dvec3 centre = lerp_pos(me.prev_position, me.position, alpha) - camera.position;
  const double near_own = rules.near_own_radius * me.cls->shield_radius;
  // A ship blowing up is news, not clutter: its fire and smoke (seconds long) stay whole, even
  // near the eye, wherever they drift.
  std::vector<glm::dvec3> wrecks;
  for (const Ship& s : w.ships)
    if (!s.alive && s.death_tick >= 0 && double(w.tick - s.death_tick) * w.dt < 4.0) wrecks.push_back(s.position - camera.position);
  auto in_explosion = [&](const glm::dvec3& at) {
    for (const glm::dvec3& c : wrecks)
      if (glm::dot(at - c, at - c) < 150.0 * 150.0) return true;
    return false;
  };
  // The player's own flares are news too: they drift away beside the ship and must be seen burning
  // there; only one within 15 m of the eye is still tamed, so it never glows across the screen.
  std::vector<glm::dvec3> own_flares;
  for (const Flare& f : w.flares)
    if (f.owner == ship) own_flares.push_back(lerp_pos(f.prev_position, f.position, alpha) - camera.position);
  auto at_own_flare = [&](const glm::dvec3& at) {
    for (const glm::dvec3& c : own_flares)
      if (glm::dot(at - c, at - c) < 8.0 * 8.0 && glm::dot(c, c) > 15.0 * 15.0) return true;
    return false;
  };
  // Chase: an impact around the own ship or near the eye stays a small flash on screen.
  auto tame_near = [&](ParticleInstance& p) {
    const glm::dvec3 at(p.pos[0], p.pos[1], p.pos[2]);
    const glm::dvec3 from_ship = at - centre;
    const double eye = std::sqrt(glm::dot(at, at));
    if (eye > rules.near_eye_m && glm::dot(from_ship, from_ship) > near_own * near_own) return true;
    if (in_explosion(at) || at_own_flare(at)) return true;
    if (p.billboard == uint8_t(Billboard::AxisLocked)) {  // a streak: its length kept short too
      const double depth = std::max(-view_space(p, pr.inverse).z, pr.near_plane);
      const double len = std::sqrt(double(p.axis[0]) * p.axis[0] + double(p.axis[1]) * p.axis[1] + double(p.axis[2]) * p.axis[2]);
      const double longest = 3.0 * rules.near_half_width * height * depth / pr.focal;
      if (len > longest)
        for (float& a : p.axis) a *= float(longest / len);
    }
    return tame_beam(p, pr, height, rules.near_half_width, rules.near_eye_fade);
  };
  std::erase_if(particles, [&](ParticleInstance& p) {
    switch (clusters.kind(p.cluster)) {
      case ViewKind::Other: return !cockpit && !tame_near(p);
      case ViewKind::OwnExhaust: return cockpit;
      case ViewKind::OwnBeam: return !tame_beam(p, pr, height, rules.beam_half_width, rules.beam_near_fade);
      case ViewKind::OtherBeam: return !tame_beam(p, pr, height, rules.other_beam_half_width, 0.0);
      case ViewKind::OwnShield: {
        if (cockpit) return true;
        const double keep = shield_visibility(p, pr, crosshair, height, rules) * rim_visibility(p, centre, rules);
        scale_color(p, keep);
        return keep <= 0.0;
      }
    }
    return false;
  });
}

}  // namespace arc
