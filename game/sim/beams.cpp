// game/sim/beams.cpp — the lightning beam: the trigger spends energy and opens one channel per
// mount, each tick the channels are traced against ships, cut at the first hit and deal damage.
#include "game/sim/beams.h"

#include <algorithm>

#include "game/sim/capital.h"
#include "game/sim/damage.h"
#include "game/sim/effects.h"
#include "game/sim/geometry.h"
#include "game/sim/projectiles.h"
#include "game/sim/world.h"

namespace arc {
namespace {

// The beam's path: the lightning channel's polyline up to where it reaches the class's range
// ahead of its mount (measured along the aim line, so a zigzag does not shorten it), or a
// straight seed line while the channel has no points yet (the tick it was spawned).
struct BeamPath {
  std::vector<glm::dvec3> points;
  double length = 0;  // along the polyline: where the channel is cut when nothing is hit
};

BeamPath beam_path(const World& w, const Ship& s, size_t mount) {
  const double range = s.cls->beam.range;
  const glm::dvec3 aim = forward_of(s.orientation);
  BeamPath path;
  path.points = w.particles->lightning_points(s.beam_channels[mount]);
  std::vector<glm::dvec3>& pts = path.points;
  if (pts.size() < 2) {
    glm::dvec3 origin = s.position + s.orientation * s.cls->beam.mounts[mount];
    pts = {origin, origin + aim * range};
    path.length = range;
    return path;
  }
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    const double reach0 = glm::dot(pts[i] - pts[0], aim), reach1 = glm::dot(pts[i + 1] - pts[0], aim);
    const double seg = safe_len(pts[i + 1] - pts[i]);
    if (reach1 > range && reach1 > reach0) {
      const double f = (range - reach0) / (reach1 - reach0);
      pts[i + 1] = pts[i] + (pts[i + 1] - pts[i]) * f;
      pts.resize(i + 2);
      path.length += seg * f;
      return path;
    }
    path.length += seg;
  }
  return path;
}

}  // namespace

BeamHit trace_beam(const World& w, ShipId shooter, const std::vector<glm::dvec3>& line) {
  BeamHit best;
  double along = 0;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const glm::dvec3 a = line[i], b = line[i + 1];
    const double seg = safe_len(b - a);
    double best_t = 2.0;
    for (const Ship& s : w.ships) {
      if (!s.alive || s.id == shooter) continue;
      // Bounding sphere first (the larger of the two), then the sphere that actually stops it.
      const double outer = std::max(s.cls->shield_radius, s.cls->collision_radius);
      if (segment_sphere(a, b, s.position, outer) < 0) continue;
      const bool shield_up = s.shield > 0;
      double t = segment_sphere(a, b, s.position, shield_up ? s.cls->shield_radius : s.cls->collision_radius);
      // A capital ship's turrets and subsystems stand off its hull sphere: they stop beams too.
      if (!shield_up && !s.parts.empty()) {
        const double tp = segment_parts(s, a, b);
        if (tp >= 0 && (t < 0 || tp < t)) t = tp;
      }
      if (t >= 0 && t < best_t) {
        best_t = t;
        best.ship = s.id;
        best.on_shield = shield_up;
      }
    }
    if (best.ship) {
      best.point = a + (b - a) * best_t;
      best.distance = along + seg * best_t;
      return best;
    }
    along += seg;
  }
  return best;
}

void stop_beam(World& w, Ship& s) {
  for (ClusterHandle ch : s.beam_channels) w.particles->destroy(ch);
  s.beam_channels.clear();
  s.beam_hit_distance.clear();
  s.beam_firing = false;
  s.beam_target = {};
}

void update_beam_trigger(World& w, Ship& s) {
  if (s.cls->primary_plasma) return fire_primary_plasma(w, s);
  const BeamDef& b = s.cls->beam;
  const bool want = (s.controls.buttons & kFirePrimary) && s.energy >= b.energy_per_second * w.dt;
  if (!want) {
    if (s.beam_firing) stop_beam(w, s);
    return;
  }
  s.energy -= b.energy_per_second * w.dt;
  if (s.beam_firing) return;
  s.beam_firing = true;
  for (const glm::dvec3& m : b.mounts)
    s.beam_channels.push_back(w.particles->spawn_lightning(w.fx.lightning_beam, s.particle_owner, m, {0, 0, -1}));
  s.beam_hit_distance.assign(s.beam_channels.size(), -1.0);
}

void resolve_beams(World& w) {
  for (Ship& s : w.ships) {
    if (!s.alive || !s.beam_firing) continue;
    s.beam_target = {};
    s.stats.beam_ticks++;
    bool on_hostile = false;
    const size_t n = s.beam_channels.size();
    for (size_t m = 0; m < n; ++m) {
      ClusterHandle ch = s.beam_channels[m];
      const BeamPath path = beam_path(w, s, m);
      BeamHit hit = trace_beam(w, s.id, path.points);
      s.beam_hit_distance[m] = hit.distance;
      w.particles->cut_lightning(ch, hit.ship ? hit.distance : path.length);
      if (!hit.ship) continue;
      Ship& t = w.ship(hit.ship);
      s.beam_target = hit.ship;
      if (w.hostile(s, t)) {
        on_hostile = true;
        apply_damage(w, t, s.cls->beam.damage_per_second * w.dt / double(n), hit.point, s.id);
      }
      if ((w.tick + static_cast<int64_t>(m)) % 4 == 0) {
        SpawnParams p;
        p.position = hit.point;
        p.velocity = t.velocity;
        p.orientation = glm::quatLookAt(safe_norm(hit.point - t.position, glm::dvec3(0, 1, 0)), glm::dvec3(0, 1, 0.001));
        p.priority = 0;
        spawn_fx(w, hit.on_shield ? w.fx.shield_hit : w.fx.hull_sparks, p);
      }
    }
    if (on_hostile) s.stats.beam_hit_ticks++;
  }
}

}  // namespace arc
