// game/sim/capital.cpp — capital ships: parts (turrets and subsystems) and their damage, turret
// fire, dead engines and shield generators, subsystem targeting and the staged break-up.
#include "game/sim/capital.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"
#include "game/sim/beams.h"
#include "game/sim/damage.h"
#include "game/sim/effects.h"
#include "game/sim/geometry.h"
#include "game/sim/wing.h"
#include "game/sim/world.h"

namespace arc {
namespace {

// Keyed random streams (core/rng.h): one per ship and turret for aim scatter, one per wreck.
constexpr uint64_t kTurretStream = 0x7475727265740000ull;
constexpr uint64_t kBreakupStream = 0x627265616B000000ull;
constexpr double kFlakShellSpeed = 700.0;  // m/s: how far ahead a flak turret leads its target
constexpr double kStallRate = 0.35;        // 1/s: how fast a ship with dead engines loses speed
constexpr int8_t kCruiseThrottle = 64;     // about half
constexpr int64_t kBoltTicks = 15;         // how long a beam turret's bolt shows
constexpr double kFlakBurstScale = 2.5;    // of the hull sparks effect

bool is_turret(const ShipClassDef& c, size_t i) { return i < c.turrets.size(); }

glm::dvec3 part_local(const ShipClassDef& c, size_t i) {
  return is_turret(c, i) ? c.turrets[i].position : c.subsystems[i - c.turrets.size()].position;
}

bool kind_down(const Ship& s, SubsystemKind kind) {
  const ShipClassDef& c = *s.cls;
  bool any = false;
  for (size_t k = 0; k < c.subsystems.size(); ++k) {
    if (c.subsystems[k].kind != kind) continue;
    any = true;
    if (s.parts[c.turrets.size() + k].hull > 0) return false;
  }
  return any;
}

void destroy_part(World& w, Ship& t, size_t i) {
  t.parts[i].hull = 0;
  t.parts[i].aim = {};
  const ShipClassDef& c = *t.cls;
  SpawnParams p;
  p.position = part_position(t, i);
  p.velocity = t.velocity;
  p.scale = std::max(0.5, part_radius(c, i) / 6.0);
  p.priority = 2;
  spawn_fx(w, w.fx.ship_explosion, p);
  if (!is_turret(c, i) && c.subsystems[i - c.turrets.size()].kind == SubsystemKind::ShieldGenerator &&
      shield_generators_down(t))
    t.shield = 0;
  post_message(w, w.hostile(t, w.ship(w.focus_ship())) ? MessageKind::Friendly : MessageKind::Hostile,
               t.name + ": " + part_name(c, i) + " destroyed");
}

// The nearest live hostile inside the turret's arc and range, from its mount.
ShipId pick_target(const World& w, const Ship& s, const TurretDef& t, const glm::dvec3& mount) {
  ShipId best;
  double best_d = 0;
  for (const Ship& o : w.ships) {
    if (!o.alive || o.id == s.id || !w.hostile(s, o)) continue;
    const glm::dvec3 to = o.position - mount;
    const double d = safe_len(to);
    if (d > t.range || d < 1e-6) continue;
    if (!turret_can_aim(t, s.orientation, mount, o.position)) continue;
    if (!best || d < best_d) best = o.id, best_d = d;
  }
  return best;
}

void fire_beam_turret(World& w, Ship& s, PartState& ps, const TurretDef& t, const glm::dvec3& mount,
                      const glm::dvec3& dir) {
  const glm::dvec3 end = mount + dir * t.range;
  const BeamHit hit = trace_beam(w, s.id, {mount, end});
  const double reach = hit.ship ? hit.distance : t.range;
  SpawnParams p;
  p.position = mount;
  p.orientation = glm::quatLookAt(dir, glm::dvec3(0, 1, 0.001));
  ps.bolt = spawn_fx(w, w.fx.lightning_beam, p);
  for (ClusterHandle ch : ps.bolt.clusters) w.particles->cut_lightning(ch, reach);
  if (!hit.ship) return;
  Ship& target = w.ship(hit.ship);
  SpawnParams sp;
  sp.position = hit.point;
  sp.velocity = target.velocity;
  sp.priority = 0;
  spawn_fx(w, hit.on_shield ? w.fx.shield_hit : w.fx.hull_sparks, sp);
  if (w.hostile(s, target)) apply_damage(w, target, t.damage, hit.point, s.id);
}

void fire_flak_turret(World& w, Ship& s, const TurretDef& t, const glm::dvec3& mount, const glm::dvec3& dir,
                      double distance, const Rng& r) {
  const double along = std::clamp(distance + r.range(7, -0.5, 0.5) * t.burst_radius, 1.0, t.range);
  const glm::dvec3 burst = mount + dir * along;
  SpawnParams p;
  p.position = burst;
  p.scale = kFlakBurstScale;
  p.priority = 0;
  spawn_fx(w, w.fx.hull_sparks, p);
  for (Ship& o : w.ships) {
    if (!o.alive || !w.hostile(s, o)) continue;
    const double d = safe_len(o.position - burst) - o.cls->collision_radius;
    if (d >= t.burst_radius) continue;
    apply_damage(w, o, t.damage * std::min(1.0, 1.0 - d / t.burst_radius), o.position, s.id);
  }
}

}  // namespace

bool turret_can_aim(const TurretDef& t, const glm::dquat& ship_q, const glm::dvec3& mount, const glm::dvec3& at) {
  const glm::dvec3 to = at - mount;
  const double d = safe_len(to);
  if (d < 1e-9) return false;
  return glm::dot(ship_q * t.facing, to / d) >= std::cos(t.arc * kDeg) - 1e-12;
}

void init_parts(Ship& s) {
  s.parts.clear();
  for (const TurretDef& t : s.cls->turrets) s.parts.push_back({t.hull, 0, {}, -1});
  for (const SubsystemDef& d : s.cls->subsystems) s.parts.push_back({d.hull, 0, {}, -1});
  if (s.cls->primary_plasma) s.primary_cooldown = {0.0};
}

glm::dvec3 part_position(const Ship& s, size_t i) { return s.position + s.orientation * part_local(*s.cls, i); }

double part_radius(const ShipClassDef& c, size_t i) {
  return is_turret(c, i) ? c.turrets[i].radius : c.subsystems[i - c.turrets.size()].radius;
}

const char* part_name(const ShipClassDef& c, size_t i) {
  return (is_turret(c, i) ? c.turrets[i].name : c.subsystems[i - c.turrets.size()].name).c_str();
}

bool part_alive(const Ship& s, size_t i) { return i < s.parts.size() && s.parts[i].hull > 0; }
bool engines_down(const Ship& s) { return !s.parts.empty() && kind_down(s, SubsystemKind::Engine); }
bool shield_generators_down(const Ship& s) { return !s.parts.empty() && kind_down(s, SubsystemKind::ShieldGenerator); }

void drive_capital(World&, Ship& s) {
  s.controls = InputFrame{};
  if (!engines_down(s)) s.controls.throttle = kCruiseThrottle;
  else s.controls.buttons = kFlightAssist;  // assist off: no thrust at all
}

void stall_dead_engines(World& w, Ship& s) {
  if (!engines_down(s)) return;
  const double keep = std::exp(-kStallRate * w.dt);
  s.velocity *= keep;
  s.angular_velocity *= keep;
}

void fire_turrets(World& w, Ship& s) {
  const ShipClassDef& c = *s.cls;
  for (size_t i = 0; i < c.turrets.size(); ++i) {
    PartState& ps = s.parts[i];
    // A bolt shows for a moment, then goes (its turret destroyed, at once).
    if (!ps.bolt.clusters.empty() && (ps.hull <= 0 || w.tick - ps.fired_tick >= kBoltTicks)) {
      w.particles->destroy(ps.bolt);
      ps.bolt = {};
    }
    if (ps.hull <= 0 || w.tick < ps.ready_tick) continue;
    const TurretDef& t = c.turrets[i];
    const glm::dvec3 mount = part_position(s, i);
    ps.aim = pick_target(w, s, t, mount);
    if (!ps.aim) continue;
    const Ship& target = w.ship(ps.aim);
    const double distance = safe_len(target.position - mount);
    glm::dvec3 at = target.position;
    if (t.kind == TurretKind::Flak) at += (target.velocity - s.velocity) * (distance / kFlakShellSpeed);
    const Rng r{w.seed, kTurretStream + (uint64_t(s.id.index()) << 8) + i, uint64_t(w.tick)};
    const glm::dvec3 dir = safe_norm(safe_norm(at - mount, forward_of(s.orientation)) + r.unit_vector(0) * t.spread,
                                     forward_of(s.orientation));
    if (t.kind == TurretKind::Beam) fire_beam_turret(w, s, ps, t, mount, dir);
    else fire_flak_turret(w, s, t, mount, dir, distance, r);
    ps.fired_tick = w.tick;
    ps.ready_tick = w.tick + std::max<int64_t>(1, seconds_to_ticks(w, t.cooldown));
  }
}

void damage_parts(World& w, Ship& t, const glm::dvec3& point, double amount, ShipId, int only) {
  if (amount <= 0) return;
  for (size_t i = 0; i < t.parts.size(); ++i) {
    if (!part_alive(t, i)) continue;
    if (only >= 0 ? int(i) != only : safe_len(point - part_position(t, i)) > part_radius(*t.cls, i) * 1.25) continue;
    t.parts[i].hull -= amount;
    if (t.parts[i].hull <= 0) destroy_part(w, t, i);
  }
}

double segment_parts(const Ship& s, const glm::dvec3& a, const glm::dvec3& b, int* part) {
  double best = -1;
  for (size_t i = 0; i < s.parts.size(); ++i) {
    if (!part_alive(s, i)) continue;
    const double t = segment_sphere(a, b, part_position(s, i), part_radius(*s.cls, i));
    if (t >= 0 && (best < 0 || t < best)) {
      best = t;
      if (part) *part = int(i);
    }
  }
  return best;
}

int target_part(const World& w, const Ship& s) {
  if (s.target_part.empty() || !s.target) return -1;
  const int i = s.target_part[0];
  return part_alive(w.ship(s.target), size_t(i)) ? i : -1;
}

void cycle_target_part(World& w, Ship& s) {
  const int current = target_part(w, s);
  s.target_part.clear();
  if (!s.target) return;
  const Ship& t = w.ship(s.target);
  for (size_t i = size_t(current + 1); i < t.parts.size(); ++i)
    if (part_alive(t, i)) {
      s.target_part.push_back(int32_t(i));
      return;
    }
}

bool start_breakup(World& w, Ship& s) {
  for (PartState& p : s.parts)
    if (!p.bolt.clusters.empty()) w.particles->destroy(p.bolt), p.bolt = {};
  if (s.cls->breakup.stages <= 0) return false;
  BreakUp b;
  b.ship = s.id;
  b.start_tick = w.tick;
  b.position = b.prev_position = s.position;
  b.velocity = s.velocity * 0.5;
  b.orientation = b.prev_orientation = s.orientation;
  w.breakups.push_back(b);
  return true;
}

// Each wreck drifts and turns; its stages and final blast are spawned here, so the break-up's
// timing reads top to bottom.
void update_breakups(World& w) {
  for (BreakUp& b : w.breakups) {
    const Ship& s = w.ship(b.ship);
    const BreakupDef& d = s.cls->breakup;
    const Rng r{w.seed, kBreakupStream + b.ship.index(), 0};
    b.prev_position = b.position;
    b.prev_orientation = b.orientation;
    b.position += b.velocity * w.dt;
    const glm::dvec3 axis = safe_norm(r.unit_vector(0), glm::dvec3(0, 0, 1));
    b.orientation = glm::normalize(b.orientation * glm::angleAxis(d.spin * kDeg * w.dt, axis));
    const int64_t total = std::max<int64_t>(1, seconds_to_ticks(w, d.seconds));
    const int64_t age = w.tick - b.start_tick;
    const int64_t due = std::min<int64_t>(d.stages, age * (d.stages + 1) / total);
    while (b.stage < due) {
      ++b.stage;
      const Rng rs{w.seed, kBreakupStream + b.ship.index(), uint64_t(b.stage)};
      // A blast at one of its parts or along its keel, scattered across the hull.
      glm::dvec3 local(0.0);
      const size_t n = s.cls->part_count();
      if (n > 0 && rs.uniform(1) < 0.6) local = part_local(*s.cls, size_t(rs.uniform(2) * double(n)) % n);
      else local = glm::dvec3(0, 0, rs.range(3, -1.0, 1.0) * s.cls->collision_radius * 1.5);
      local += rs.unit_vector(4) * (s.cls->collision_radius * 0.15);
      SpawnParams p;
      p.position = b.position + b.orientation * local;
      p.velocity = b.velocity + rs.unit_vector(5) * 4.0;
      p.scale = s.cls->collision_radius / 14.0 * rs.range(6, 0.7, 1.2);
      p.priority = 2;
      spawn_fx(w, w.fx.ship_explosion, p);
      w.explosions.push_back({p.position, w.tick, s.cls->collision_radius * 2.0});
    }
    if (age >= total) {
      SpawnParams p;
      p.position = b.position;
      p.velocity = b.velocity;
      p.scale = d.final_scale;
      p.priority = 2;
      spawn_fx(w, w.fx.ship_explosion, p);
      w.explosions.push_back({b.position, w.tick, s.cls->collision_radius * 6.0});
      b.stage = -1;  // done
    }
  }
  std::erase_if(w.breakups, [](const BreakUp& b) { return b.stage < 0; });
}

}  // namespace arc
