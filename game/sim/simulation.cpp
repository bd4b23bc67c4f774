#include "game/sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/error.h"
#include "core/rng.h"
#include "game/sim/effects.h"

namespace arc {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kFlashSeconds = 0.5;
constexpr double kExplosionMemorySeconds = 1.0;
constexpr uint64_t kAiStream = 0x41490000ull;

uint32_t ship_owner(int id) { return static_cast<uint32_t>(id) + 1; }
uint32_t projectile_owner(uint32_t serial) { return kProjectileOwnerBase + serial; }

double safe_len(const glm::dvec3& v) { return std::sqrt(glm::dot(v, v)); }
glm::dvec3 safe_norm(const glm::dvec3& v, const glm::dvec3& fallback) {
  double l = safe_len(v);
  return l > 1e-12 ? v / l : fallback;
}

int64_t seconds_to_ticks(const World& w, double s) { return static_cast<int64_t>(std::llround(s / w.dt)); }

// Spawns an effect; names come from validated data, so a failure here is a data error of the level.
EffectHandle spawn_fx(World& w, const std::string& name, const SpawnParams& p) {
  return w.particles->spawn(name, p);
}

void set_owner(World& w, uint32_t owner, const glm::dvec3& pos, const glm::dquat& q, const glm::dvec3& vel) {
  w.particles->set_owner_transform(owner, OwnerTransform{pos, q, vel});
}

// ---------------------------------------------------------------- targets and commands

int next_target(const World& w, int self, int current, bool hostile_only) {
  const int n = static_cast<int>(w.ships.size());
  for (int k = 1; k <= n; ++k) {
    int id = ((current < 0 ? self : current) + k) % n;
    const Ship& s = w.ships[id];
    if (id == self || !s.alive) continue;
    if (hostile_only && !w.hostile(w.ships[self], s)) continue;
    return id;
  }
  return -1;
}

int nearest_target(const World& w, int self, bool hostile_only) {
  int best = -1;
  double best_d = 0;
  const Ship& me = w.ships[self];
  for (const Ship& s : w.ships) {
    if (s.id == self || !s.alive) continue;
    if (hostile_only && !w.hostile(me, s)) continue;
    double d = glm::dot(s.position - me.position, s.position - me.position);
    if (best < 0 || d < best_d) best = s.id, best_d = d;
  }
  return best;
}

void apply_commands(World& w, const std::vector<Command>& commands) {
  for (Command c : commands) {
    if (c == Command::Pause) w.paused = true;
    if (c == Command::Resume) w.paused = false;
    if (w.paused) continue;
    if (c == Command::CameraToggle && w.camera_mode != CameraMode::Fixed)
      w.camera_mode = w.camera_mode == CameraMode::Chase ? CameraMode::Cockpit : CameraMode::Chase;
    if (w.player < 0 || !w.ships[w.player].alive) continue;
    Ship& p = w.ships[w.player];
    switch (c) {
      case Command::TargetNext: p.target = next_target(w, p.id, p.target, false); break;
      case Command::TargetNearest: p.target = nearest_target(w, p.id, false); break;
      case Command::TargetNextHostile: p.target = next_target(w, p.id, p.target, true); break;
      case Command::SwitchWeapon:
        if (p.cls->missile.present && p.cls->plasma.present)
          p.secondary = p.secondary == SecondaryWeapon::Missile ? SecondaryWeapon::Plasma : SecondaryWeapon::Missile;
        break;
      default: break;
    }
  }
}

// ---------------------------------------------------------------- AI

// Stick commands that turn the nose toward a world direction, damped by the current turn rate.
void steer_toward(const Ship& s, const glm::dvec3& dir, InputFrame& out) {
  glm::dvec3 local = glm::conjugate(s.orientation) * dir;
  double yaw_angle = std::atan2(local.x, -local.z);
  double pitch_angle = std::atan2(local.y, std::sqrt(local.x * local.x + local.z * local.z));
  if (local.z > 0 && std::fabs(local.x) < 1e-9 && std::fabs(local.y) < 1e-9) pitch_angle = kPi / 2;
  const double gain = 3.0, damping = 0.35;
  double yaw_rate = s.cls->turn_rate[1] * kDeg, pitch_rate = s.cls->turn_rate[0] * kDeg;
  // Yawing right is a negative rate about +Y, hence the sign of the damping term.
  double yaw_cmd = gain * yaw_angle + damping * (s.angular_velocity.y / std::max(yaw_rate, 1e-6));
  double pitch_cmd = gain * pitch_angle - damping * (s.angular_velocity.x / std::max(pitch_rate, 1e-6));
  out.yaw = quantise_axis(yaw_cmd);
  out.pitch = quantise_axis(pitch_cmd);
  // Level the wings slowly so the ship does not corkscrew.
  out.roll = quantise_axis(-0.3 * s.angular_velocity.z);
}

glm::dvec3 lead_point(const Ship& shooter, const Ship& target, double projectile_speed) {
  glm::dvec3 rel = target.position - shooter.position;
  if (projectile_speed <= 0) return target.position;
  double t = safe_len(rel) / projectile_speed;
  glm::dvec3 rel_v = target.velocity - shooter.velocity;
  for (int i = 0; i < 2; ++i) t = safe_len(rel + rel_v * t) / projectile_speed;
  return target.position + rel_v * t;
}

// The nearest hostile, but a damaged one counts as nearer: pilots go for the kill, so fights end
// in explosions instead of spreading damage over everyone.
int pick_target(const World& w, int self) {
  int best = -1;
  double best_score = 0;
  const Ship& me = w.ships[self];
  for (const Ship& s : w.ships) {
    if (s.id == self || !s.alive || !w.hostile(me, s)) continue;
    const double health = (s.hull + s.shield) / std::max(1e-9, s.cls->hull + s.cls->shield);
    const double score = safe_len(s.position - me.position) * (0.4 + health);
    if (best < 0 || score < best_score) best = s.id, best_score = score;
  }
  return best;
}

void think(World& w, Ship& s) {
  const AiTuning tune = ai_tuning(w.difficulty);
  AiState& ai = s.ai_state;
  const Rng rng{w.seed, kAiStream + static_cast<uint64_t>(s.id), static_cast<uint64_t>(w.tick)};
  ai.next_think = w.tick + std::max<int64_t>(1, seconds_to_ticks(w, tune.reaction_s));
  if (ai.target < 0 || !w.ships[ai.target].alive || rng.uniform(0) < 0.25) ai.target = pick_target(w, s.id);
  s.target = ai.target;
  ai.aim_error = rng.unit_vector(1) * (tune.aim_error * rng.uniform(2));
  if (ai.target < 0) return;
  const Ship& t = w.ships[ai.target];
  const glm::dvec3 rel = t.position - s.position;
  const double dist = safe_len(rel);
  const double shield_frac = s.cls->shield > 0 ? s.shield / s.cls->shield : 0.0;
  const double hull_frac = s.hull / s.cls->hull;
  if (ai.mode != AiMode::Attack && w.tick < ai.mode_until) return;
  ai.mode = AiMode::Attack;
  const double evade_at = 0.35 * (1.3 - tune.aggression);
  // After an evasion or a break-off the pilot turns back and fights for a while before it may
  // evade again: a ship that is still under fire never recharges, so endless evading only
  // handed its pursuers a free tail.
  const bool may_evade = w.tick - ai.mode_until >= seconds_to_ticks(w, 2.0 + 4.0 * tune.aggression);
  if (may_evade && shield_frac < evade_at && hull_frac < 0.9 && rng.uniform(3) > 0.4 * tune.aggression) {
    ai.mode = AiMode::Evade;
    ai.mode_until = w.tick + seconds_to_ticks(w, 1.5 + rng.uniform(4));
    glm::dvec3 side = glm::cross(safe_norm(rel, forward_of(s.orientation)), rng.unit_vector(5));
    ai.evade_dir = safe_norm(side - 0.5 * safe_norm(rel, glm::dvec3(0, 0, -1)), glm::dvec3(0, 1, 0));
    return;
  }
  // Attack runs: close in firing, then break off and come round again instead of hovering at
  // point-blank range. Calmer pilots break off earlier and stay out longer (capped, so that even
  // an easy pilot outpaces a Warden's recharge), so a fight has lulls in which shields recharge;
  // the run ends at once if a collision is near.
  const double too_close = s.cls->collision_radius + t.cls->collision_radius + 30.0;
  const double run_end = too_close + 40.0 + 80.0 * (1.0 - tune.aggression);
  const bool closing = glm::dot(t.velocity - s.velocity, rel) < 0;
  if (dist < run_end && (closing || dist < too_close)) {
    ai.mode = AiMode::BreakOff;
    ai.mode_until = w.tick + seconds_to_ticks(w, std::min(1.75, 1.0 + 3.0 * (1.0 - tune.aggression)) + 0.5 * rng.uniform(6));
    ai.evade_dir = safe_norm(glm::cross(rel, rng.unit_vector(7)), glm::dvec3(0, 1, 0));
  }
}

// Whether a live ship of the shooter's own side sits in its line of fire nearer than `dist`:
// within its shield sphere, plus a little for the lightning's wander, of the ray from the shooter
// along `dir`. Allies take no damage, but they stop the beam, missiles and plasma meant for
// the enemy, so a pilot holds fire until the line is clear.
bool ally_in_line_of_fire(const World& w, const Ship& s, const glm::dvec3& dir, double dist) {
  for (const Ship& o : w.ships) {
    if (!o.alive || o.id == s.id || w.hostile(s, o)) continue;
    const glm::dvec3 rel = o.position - s.position;
    const double along = glm::dot(rel, dir);
    if (along <= 0.0 || along >= dist) continue;
    const double r = o.cls->shield_radius + 2.0;
    if (glm::dot(rel, rel) - along * along < r * r) return true;
  }
  return false;
}

void drive_ai(World& w, Ship& s) {
  if (w.tick >= s.ai_state.next_think) think(w, s);
  const AiTuning tune = ai_tuning(w.difficulty);
  AiState& ai = s.ai_state;
  InputFrame c;
  if (ai.target < 0 || !w.ships[ai.target].alive) {
    c.throttle = quantise_axis(0.5);
    c.roll = quantise_axis(-0.3 * s.angular_velocity.z);
    s.controls = c;
    return;
  }
  const Ship& t = w.ships[ai.target];
  const glm::dvec3 fwd = forward_of(s.orientation);
  if (ai.mode != AiMode::Attack) {
    steer_toward(s, ai.evade_dir, c);
    c.throttle = quantise_axis(1.0);
    if (s.energy > 0.3 * s.cls->energy) c.buttons |= kAfterburner;
    s.controls = c;
    return;
  }
  const bool plasma = s.secondary == SecondaryWeapon::Plasma && s.cls->plasma.present;
  const glm::dvec3 rel = t.position - s.position;
  const double dist = safe_len(rel);
  glm::dvec3 aim = plasma ? lead_point(s, t, s.cls->plasma.speed) : t.position + t.velocity * w.dt;
  glm::dvec3 dir = safe_norm(aim - s.position, fwd);
  dir = safe_norm(dir + ai.aim_error, dir);
  steer_toward(s, dir, c);
  const double off = std::acos(std::clamp(glm::dot(fwd, safe_norm(rel, fwd)), -1.0, 1.0));
  const double cone = std::atan2(t.cls->shield_radius, std::max(dist, 1.0)) * (0.6 + 0.6 * tune.aggression);
  double throttle = dist > 400 ? 1.0 : dist > 150 ? 0.7 : 0.35;
  c.throttle = quantise_axis(throttle);
  if (dist > 1500 && s.energy > 0.6 * s.cls->energy && off < 0.3) c.buttons |= kAfterburner;
  // Fire discipline: a burst runs until the energy is nearly spent, then the AI waits for it to
  // recover (longer the calmer it is) instead of flickering the beam at the regeneration rate.
  const double energy_frac = s.cls->energy > 0 ? s.energy / s.cls->energy : 0.0;
  const bool beam_ready = s.beam_firing ? energy_frac > 0.1 : energy_frac > 0.3 + 0.5 * (1.0 - tune.aggression);
  const bool line_clear = !ally_in_line_of_fire(w, s, fwd, dist);
  if (line_clear && beam_ready && off < cone + 0.02 && dist < s.cls->beam.range * 0.95) c.buttons |= kFirePrimary;
  const Rng rng{w.seed, kAiStream + 0x100 + static_cast<uint64_t>(s.id), static_cast<uint64_t>(w.tick)};
  if (line_clear && s.cls->missile.present && !plasma && off < 0.35 && dist < 1500 && dist > 80 &&
      rng.uniform(0) < 0.05 * tune.aggression)
    c.buttons |= kFireSecondary;
  if (line_clear && plasma && energy_frac > 0.25 && off < cone + 0.03 &&
      dist < s.cls->plasma.speed * s.cls->plasma.lifetime * 0.8)
    c.buttons |= kFireSecondary;
  // Switch weapons now and then so both get used.
  if (s.cls->missile.present && s.cls->plasma.present && rng.uniform(1) < 0.004)
    s.secondary = s.secondary == SecondaryWeapon::Missile ? SecondaryWeapon::Plasma : SecondaryWeapon::Missile;
  s.controls = c;
}

void drive_gunner(const World& w, Ship& s) {
  InputFrame c;
  // Three seconds on, one off: the beam's energy drain outpaces regeneration only slightly.
  if (w.tick % 240 < 180) c.buttons |= kFirePrimary;
  c.buttons |= kFireSecondary;
  s.controls = c;
}

// ---------------------------------------------------------------- weapons

void stop_beam(World& w, Ship& s) {
  for (ClusterHandle ch : s.beam_channels) w.particles->destroy(ch);
  s.beam_channels.clear();
  s.beam_hit_distance.clear();
  s.beam_firing = false;
  s.beam_target = -1;
}

void update_beam_trigger(World& w, Ship& s) {
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
    s.beam_channels.push_back(w.particles->spawn_lightning(kFxLightningBeam, ship_owner(s.id), m, {0, 0, -1}));
  s.beam_hit_distance.assign(s.beam_channels.size(), -1.0);
}

// The beam's path: the lightning channel's polyline clipped to the class's range, or a straight
// seed line while the channel has no points yet (the tick it was spawned).
std::vector<glm::dvec3> beam_path(const World& w, const Ship& s, size_t mount) {
  const double range = s.cls->beam.range;
  std::vector<glm::dvec3> pts = w.particles->lightning_points(s.beam_channels[mount]);
  if (pts.size() < 2) {
    glm::dvec3 origin = s.position + s.orientation * s.cls->beam.mounts[mount];
    return {origin, origin + forward_of(s.orientation) * range};
  }
  double along = 0;
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    const double seg = safe_len(pts[i + 1] - pts[i]);
    if (along + seg > range) {
      pts[i + 1] = pts[i] + (pts[i + 1] - pts[i]) * ((range - along) / seg);
      pts.resize(i + 2);
      break;
    }
    along += seg;
  }
  return pts;
}

void resolve_beams(World& w) {
  for (Ship& s : w.ships) {
    if (!s.alive || !s.beam_firing) continue;
    s.beam_target = -1;
    const size_t n = s.beam_channels.size();
    for (size_t m = 0; m < n; ++m) {
      ClusterHandle ch = s.beam_channels[m];
      BeamHit hit = trace_beam(w, s.id, beam_path(w, s, m));
      s.beam_hit_distance[m] = hit.distance;
      w.particles->cut_lightning(ch, hit.ship >= 0 ? hit.distance : s.cls->beam.range);
      if (hit.ship < 0) continue;
      Ship& t = w.ships[hit.ship];
      s.beam_target = hit.ship;
      if (w.hostile(s, t)) apply_damage(w, t, s.cls->beam.damage_per_second * w.dt / double(n), hit.point, s.id);
      if ((w.tick + static_cast<int64_t>(m)) % 4 == 0) {
        SpawnParams p;
        p.position = hit.point;
        p.velocity = t.velocity;
        p.orientation = glm::quatLookAt(safe_norm(hit.point - t.position, glm::dvec3(0, 1, 0)), glm::dvec3(0, 1, 0.001));
        p.priority = 0;
        spawn_fx(w, hit.on_shield ? kFxShieldHit : kFxHullSparks, p);
      }
    }
  }
}

void fire_secondary(World& w, Ship& s) {
  s.secondary_cooldown = std::max(0.0, s.secondary_cooldown - w.dt);
  if (!(s.controls.buttons & kFireSecondary)) return;
  const bool plasma = s.secondary == SecondaryWeapon::Plasma;
  const ProjectileWeaponDef& wd = plasma ? s.cls->plasma : s.cls->missile;
  if (!wd.present || s.secondary_cooldown > 0 || s.energy < wd.energy) return;
  s.energy -= wd.energy;
  s.secondary_cooldown = wd.cooldown;
  const glm::dvec3 hp = wd.hardpoints[s.hardpoint_cycle++ % wd.hardpoints.size()];
  Projectile p;
  p.serial = w.next_projectile_serial++;
  p.kind = s.secondary;
  p.owner = s.id;
  p.target = plasma ? -1 : s.target;
  if (p.target >= 0 && !w.hostile(s, w.ships[p.target])) p.target = -1;
  p.position = p.prev_position = s.position + s.orientation * hp;
  p.velocity = s.velocity + forward_of(s.orientation) * wd.speed;
  p.damage = wd.damage;
  p.turn_rate = wd.turn_rate * kDeg;
  p.hit_radius = wd.hit_radius;
  p.expire_tick = w.tick + std::max<int64_t>(1, seconds_to_ticks(w, wd.lifetime));
  set_owner(w, projectile_owner(p.serial), p.position, s.orientation, p.velocity);
  SpawnParams sp;
  sp.owner = projectile_owner(p.serial);
  p.trail = spawn_fx(w, plasma ? kFxPlasmaBolt : kFxMissileTrail, sp);
  w.projectiles.push_back(std::move(p));
}

void end_projectile(World& w, Projectile& p) {
  if (p.kind == SecondaryWeapon::Missile) {
    // The smoke stays behind and fades; the flame goes with the missile.
    w.particles->release_owner(projectile_owner(p.serial));
  } else {
    w.particles->destroy_owner(projectile_owner(p.serial));
  }
}

void move_projectiles(World& w) {
  for (Projectile& p : w.projectiles) {
    p.prev_position = p.position;
    if (p.kind == SecondaryWeapon::Missile && p.target >= 0 && w.ships[p.target].alive) {
      const double speed = safe_len(p.velocity);
      glm::dvec3 dir = safe_norm(p.velocity, glm::dvec3(0, 0, -1));
      glm::dvec3 want = safe_norm(w.ships[p.target].position - p.position, dir);
      double angle = std::acos(std::clamp(glm::dot(dir, want), -1.0, 1.0));
      double step = p.turn_rate * w.dt;
      if (angle > 1e-9) {
        glm::dvec3 axis = safe_norm(glm::cross(dir, want), glm::dvec3(0, 1, 0));
        dir = glm::angleAxis(std::min(angle, step), axis) * dir;
      }
      p.velocity = dir * speed;
    }
    p.position += p.velocity * w.dt;
    glm::dquat q = glm::quatLookAt(safe_norm(p.velocity, glm::dvec3(0, 0, -1)), glm::dvec3(0, 1, 0.001));
    set_owner(w, projectile_owner(p.serial), p.position, q, p.velocity);
  }
}

void hit_projectiles(World& w) {
  size_t keep = 0;
  for (size_t i = 0; i < w.projectiles.size(); ++i) {
    Projectile& p = w.projectiles[i];
    int hit_ship = -1;
    double best_t = 2.0;
    bool on_shield = false;
    for (const Ship& s : w.ships) {
      if (!s.alive || s.id == p.owner) continue;
      const bool shield_up = s.shield > 0;
      double r = (shield_up ? s.cls->shield_radius : s.cls->collision_radius) + p.hit_radius;
      double t = segment_sphere(p.prev_position, p.position, s.position, r);
      if (t >= 0 && t < best_t) best_t = t, hit_ship = s.id, on_shield = shield_up;
    }
    if (hit_ship >= 0) {
      Ship& t = w.ships[hit_ship];
      glm::dvec3 point = p.prev_position + (p.position - p.prev_position) * best_t;
      SpawnParams sp;
      sp.position = point;
      sp.velocity = t.velocity;
      spawn_fx(w, on_shield ? kFxShieldHit : kFxHullSparks, sp);
      if (w.hostile(w.ships[p.owner], t)) apply_damage(w, t, p.damage, point, p.owner);
      end_projectile(w, p);
      continue;
    }
    if (w.tick >= p.expire_tick) {
      end_projectile(w, p);
      continue;
    }
    if (keep != i) w.projectiles[keep] = std::move(p);
    ++keep;
  }
  w.projectiles.resize(keep);
}

// ---------------------------------------------------------------- collisions, deaths, shields

void collide_ships(World& w) {
  const size_t n = w.ships.size();
  for (size_t i = 0; i < n; ++i) {
    Ship& a = w.ships[i];
    if (!a.alive) continue;
    for (size_t j = i + 1; j < n; ++j) {
      Ship& b = w.ships[j];
      if (!b.alive) continue;
      glm::dvec3 d = b.position - a.position;
      double r = a.cls->collision_radius + b.cls->collision_radius;
      double dd = glm::dot(d, d);
      if (dd >= r * r) continue;
      double dist = std::sqrt(dd);
      glm::dvec3 nrm = safe_norm(d, glm::dvec3(0, 1, 0));
      double ma = a.cls->mass, mb = b.cls->mass;
      double push = (r - dist);
      a.position -= nrm * (push * mb / (ma + mb));
      b.position += nrm * (push * ma / (ma + mb));
      double vn = glm::dot(b.velocity - a.velocity, nrm);
      if (vn >= 0) continue;
      double jimp = -1.5 * vn / (1.0 / ma + 1.0 / mb);  // restitution 0.5
      a.velocity -= nrm * (jimp / ma);
      b.velocity += nrm * (jimp / mb);
      double damage = 0.2 * -vn;
      glm::dvec3 contact = a.position + nrm * a.cls->collision_radius;
      apply_damage(w, a, damage, contact, b.id);
      apply_damage(w, b, damage, contact, a.id);
    }
    for (const Prop& p : w.props) {
      if (p.radius <= 0) continue;
      glm::dvec3 d = a.position - p.position;
      double r = a.cls->collision_radius + p.radius;
      double dd = glm::dot(d, d);
      if (dd >= r * r) continue;
      glm::dvec3 nrm = safe_norm(d, glm::dvec3(0, 1, 0));
      a.position = p.position + nrm * r;
      double vn = glm::dot(a.velocity, nrm);
      if (vn < 0) {
        a.velocity -= nrm * (1.5 * vn);
        apply_damage(w, a, 0.2 * -vn, p.position + nrm * p.radius, -1);
      }
    }
  }
}

void kill_ship(World& w, Ship& s) {
  s.alive = false;
  s.death_tick = w.tick;
  s.hull = 0;
  stop_beam(w, s);
  w.particles->destroy_owner(ship_owner(s.id));
  s.shield_fx = {};
  s.exhaust_fx.clear();
  SpawnParams p;
  p.position = s.position;
  p.velocity = s.velocity;
  p.scale = s.cls->collision_radius / 8.0;
  p.priority = 2;
  spawn_fx(w, kFxShipExplosion, p);
  w.explosions.push_back({s.position, w.tick, s.cls->collision_radius * 6.0});
  if (s.last_attacker >= 0 && s.last_attacker != s.id) w.ships[s.last_attacker].kills++;
  if (!w.level.splash) return;
  for (Ship& o : w.ships) {
    if (!o.alive) continue;
    double d = safe_len(o.position - s.position);
    if (d >= w.level.splash_radius) continue;
    double falloff = 1.0 - d / w.level.splash_radius;
    apply_damage(w, o, w.level.splash_damage * falloff, o.position, s.last_attacker);
  }
}

void resolve_deaths(World& w) {
  // Splash damage can kill more ships; repeat until nothing changes, always in id order.
  bool again = true;
  while (again) {
    again = false;
    for (Ship& s : w.ships)
      if (s.alive && s.hull <= 0) kill_ship(w, s), again = true;
  }
  for (Ship& s : w.ships)
    if (s.target >= 0 && !w.ships[s.target].alive) s.target = -1;
  std::erase_if(w.explosions, [&](const ExplosionEvent& e) {
    return w.tick - e.tick > seconds_to_ticks(w, kExplosionMemorySeconds);
  });
}

// The shield cluster's particle count is fixed by its burst, so density follows strength by
// respawning the sphere whenever strength crosses a quarter (a few times per fight at most).
void spawn_shield(World& w, Ship& s, int quarters) {
  if (!s.shield_fx.clusters.empty()) w.particles->destroy(s.shield_fx);
  SpawnParams sp;
  sp.owner = ship_owner(s.id);
  sp.scale = s.cls->shield_radius / 10.0;
  sp.intensity = quarters / 4.0;
  s.shield_fx = spawn_fx(w, kFxShieldSphere, sp);
  s.shield_density = quarters;
  s.shield_spawn_tick = w.tick;
  s.shown_shield_intensity = -1;
}

void update_shields_and_energy(World& w) {
  for (Ship& s : w.ships) {
    if (!s.alive) continue;
    const ShipClassDef& c = *s.cls;
    s.energy = std::min(c.energy, s.energy + c.energy_regen * w.dt);
    const bool regen_allowed = w.tick - s.last_hit_tick >= seconds_to_ticks(w, c.shield_regen_delay);
    const bool recharging = regen_allowed && s.shield < c.shield;
    if (recharging) s.shield = std::min(c.shield, s.shield + c.shield_regen * w.dt);
    if (s.shield_fx.clusters.empty()) continue;
    const int quarters = static_cast<int>(std::ceil(4.0 * s.shield / c.shield));
    if (quarters > 0 && quarters != s.shield_density) spawn_shield(w, s, quarters);
    // A new sphere keeps its spawn intensity until its burst has been emitted.
    if (s.shield_spawn_tick == w.tick) continue;
    // Brightest at a hit and fading in about half a second; a faint glow while recharging (it must
    // not hide the view from the chase camera); density and
    // brightness follow strength.
    double since_hit = double(w.tick - s.shield_flash_tick) * w.dt;
    double flash = std::max(0.0, 1.0 - since_hit / kFlashSeconds);
    double strength = c.shield > 0 ? s.shield / c.shield : 0.0;
    double visible = std::max(flash, recharging ? 0.12 : 0.0) * (0.25 + 0.75 * strength);
    double q = std::round(visible * 64.0) / 64.0;
    if (q != s.shown_shield_intensity) {
      for (ClusterHandle ch : s.shield_fx.clusters) w.particles->set_intensity(ch, q);
      s.shown_shield_intensity = q;
    }
  }
}

void update_exhausts(World& w) {
  for (Ship& s : w.ships) {
    if (!s.alive || s.exhaust_fx.empty()) continue;
    double t = std::max(0.0, axis_value(s.controls.throttle));
    // Idle engines keep a faint glow; the afterburner is the only way to full brightness.
    double q = std::round((s.afterburner_on ? 1.0 : 0.15 + 0.55 * t) * 16.0) / 16.0;
    if (q == s.shown_exhaust_intensity) continue;
    for (const EffectHandle& e : s.exhaust_fx)
      for (ClusterHandle ch : e.clusters) w.particles->set_intensity(ch, q);
    s.shown_exhaust_intensity = q;
  }
}

// ---------------------------------------------------------------- outcome and camera

void decide(World& w, Outcome o, const std::string& winner) {
  w.outcome = o;
  w.winner = winner;
  w.outcome_tick = w.tick;
}

std::string first_live_team(const World& w, const std::string& except) {
  for (const Ship& s : w.ships)
    if (s.alive && s.team != except) return s.team;
  return "none";
}

void update_outcome(World& w) {
  if (w.outcome != Outcome::Undecided) return;
  const LevelDef& L = w.level;
  const Ship* player = w.player >= 0 ? &w.ships[w.player] : nullptr;
  const std::string side = player ? player->team : w.ships.front().team;
  if (L.lose == LoseKind::PlayerDestroyed && player && !player->alive)
    return decide(w, Outcome::Defeat, first_live_team(w, side));
  if (L.lose == LoseKind::Protect) {
    for (const Ship& s : w.ships)
      if (s.name == L.protect_ship && !s.alive) return decide(w, Outcome::Defeat, first_live_team(w, side));
  }
  switch (L.win) {
    case WinKind::DestroyAllHostiles: {
      bool any = false, friends = false;
      for (const Ship& s : w.ships) {
        any = any || (s.alive && s.team != side);
        friends = friends || (s.alive && s.team == side);
      }
      if (!any) decide(w, player ? Outcome::Victory : Outcome::TeamWon, side);
      else if (!friends) decide(w, player ? Outcome::Defeat : Outcome::TeamWon, first_live_team(w, side));
      break;
    }
    case WinKind::SurviveTicks:
      if (w.tick >= L.win_ticks) decide(w, player ? Outcome::Victory : Outcome::TeamWon, side);
      break;
    case WinKind::LastTeamStanding: {
      std::vector<std::string> teams;
      for (const Ship& s : w.ships)
        if (s.alive && std::find(teams.begin(), teams.end(), s.team) == teams.end()) teams.push_back(s.team);
      if (teams.size() > 1) break;
      std::string winner = teams.empty() ? "none" : teams.front();
      if (player) decide(w, player->team == winner ? Outcome::Victory : Outcome::Defeat, winner);
      else decide(w, Outcome::TeamWon, winner);
      break;
    }
  }
}

void update_camera(World& w) {
  w.prev_camera = w.camera;
  if (w.camera_mode == CameraMode::Fixed) {
    w.camera.position = w.level.camera.position;
    glm::dvec3 dir = safe_norm(w.level.camera.look_at - w.level.camera.position, glm::dvec3(0, 0, -1));
    w.camera.orientation = glm::quatLookAt(dir, std::fabs(dir.y) > 0.999 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0));
    return;
  }
  int f = w.focus_ship();
  if (f < 0) return;
  const Ship& s = w.ships[f];
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

void publish_owner_transforms(World& w) {
  for (const Ship& s : w.ships)
    if (s.alive) set_owner(w, ship_owner(s.id), s.position, s.orientation, s.velocity);
}

ParticleCamera particle_camera(const World& w) {
  ParticleCamera c;
  c.position = w.camera.position;
  c.orientation = w.camera.orientation;
  c.fov_y_radians = w.level.camera.fov_deg * kDeg;
  return c;
}

void spawn_level_effects(World& w) {
  for (const EffectSpawnDef& e : w.level.effects) {
    bool due = e.repeat_ticks > 0 ? w.tick % e.repeat_ticks == 1 % e.repeat_ticks : w.tick == 1;
    if (!due) continue;
    SpawnParams p;
    p.position = e.position;
    p.orientation = orientation_from_degrees(e.orientation_deg);
    p.scale = e.scale;
    spawn_fx(w, e.effect, p);
  }
}

}  // namespace

AiTuning ai_tuning(int difficulty) {
  switch (difficulty) {
    case 0: return {0.065, 0.45, 0.5};
    case 2: return {0.012, 0.1, 1.0};
    default: return {0.05, 0.25, 0.75};
  }
}

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

BeamHit trace_beam(const World& w, int shooter, const std::vector<glm::dvec3>& line) {
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
      if (t >= 0 && t < best_t) {
        best_t = t;
        best.ship = s.id;
        best.on_shield = shield_up;
      }
    }
    if (best.ship >= 0) {
      best.point = a + (b - a) * best_t;
      best.distance = along + seg * best_t;
      return best;
    }
    along += seg;
  }
  return best;
}

void apply_damage(World& w, Ship& t, double amount, const glm::dvec3& point, int attacker) {
  if (!t.alive || amount <= 0) return;
  t.last_hit_tick = w.tick;
  if (attacker >= 0) t.last_attacker = attacker;
  double to_shield = std::min(t.shield, amount);
  t.shield -= to_shield;
  t.hull -= amount - to_shield;
  if (to_shield > 0 && !t.shield_fx.clusters.empty()) {
    if (t.shield_flash_tick != w.tick)
      for (ClusterHandle ch : t.shield_fx.clusters) w.particles->flash(ch, point, kFlashSeconds);
    t.shield_flash_tick = w.tick;
  }
}

void integrate_flight(Ship& s, double h) {
  const ShipClassDef& c = *s.cls;
  const InputFrame& in = s.controls;
  // Angular rates follow the stick exponentially (exact for a first-order response).
  const glm::dvec3 cmd(axis_value(in.pitch) * c.turn_rate[0] * kDeg, -axis_value(in.yaw) * c.turn_rate[1] * kDeg,
                       -axis_value(in.roll) * c.turn_rate[2] * kDeg);
  const double decay = std::exp(-c.turn_response * h);
  s.angular_velocity = cmd + (s.angular_velocity - cmd) * decay;
  const double rate = safe_len(s.angular_velocity);
  if (rate > 0) s.orientation = glm::normalize(s.orientation * glm::angleAxis(rate * h, s.angular_velocity / rate));

  const double boost = s.afterburner_on ? c.afterburner_speed : 1.0;
  const glm::dvec3 fwd = forward_of(s.orientation);
  const glm::dvec3 right = s.orientation * glm::dvec3(1, 0, 0);
  const glm::dvec3 up = s.orientation * glm::dvec3(0, 1, 0);
  const double throttle = axis_value(in.throttle), sx = axis_value(in.strafe_x), sy = axis_value(in.strafe_y);
  const bool assist = !(in.buttons & kFlightAssist);
  if (assist) {
    // Flight assist: thrust toward the commanded velocity, never harder than the engines allow.
    const double fwd_speed = throttle >= 0 ? throttle * c.max_speed * boost : throttle * c.reverse_fraction * c.max_speed;
    const glm::dvec3 want = fwd * fwd_speed + (right * sx + up * sy) * (0.3 * c.max_speed);
    const glm::dvec3 dv = want - s.velocity;
    const double max_dv = c.thrust * boost / c.mass * h;
    const double need = safe_len(dv);
    s.velocity += need <= max_dv ? dv : dv * (max_dv / need);
  } else {
    const glm::dvec3 a = fwd * (throttle * c.thrust * boost / c.mass) + (right * sx + up * sy) * (c.strafe_thrust / c.mass);
    s.velocity += a * h;
  }
  const double limit = c.max_speed * c.afterburner_speed;
  const double speed = safe_len(s.velocity);
  if (speed > limit) s.velocity *= limit / speed;
  s.position += s.velocity * h;
}

void init_world(World& w, LevelDef level, std::shared_ptr<const EffectLibrary> effects, const GameOptions& o) {
  w.options = o;
  w.level = std::move(level);
  w.seed = o.seed_override ? o.seed : w.level.seed;
  w.difficulty = o.difficulty_override ? static_cast<int>(o.difficulty) : w.level.difficulty;
  w.dt = 1.0 / w.level.tick_rate;
  for (const auto& [name, cls] : w.level.classes) w.class_names.push_back(name);
  auto add_model = [&](const std::string& path) {
    for (size_t i = 0; i < w.model_paths.size(); ++i)
      if (w.model_paths[i] == path) return static_cast<int>(i);
    w.model_paths.push_back(path);
    return static_cast<int>(w.model_paths.size() - 1);
  };
  w.effects = std::move(effects);
  ParticleConfig pc;
  pc.seed = w.seed;
  pc.budget = o.particle_budget;
  pc.lightning_interval = o.lightning_interval;
  pc.tick_seconds = w.dt;
  w.particles = std::make_unique<ParticleWorld>(pc, w.effects.get());
  for (const ShipSpawnDef& d : w.level.ships) {
    Ship s;
    s.id = static_cast<int>(w.ships.size());
    s.name = d.name;
    s.team = d.team;
    s.cls = &w.level.classes.at(d.ship_class);
    s.class_index = static_cast<int>(std::find(w.class_names.begin(), w.class_names.end(), d.ship_class) - w.class_names.begin());
    s.model = add_model(s.cls->model);
    s.player = d.player;
    s.ai = d.ai;
    s.position = s.prev_position = d.position;
    s.orientation = s.prev_orientation = orientation_from_degrees(d.orientation_deg);
    s.velocity = d.velocity;
    s.hull = s.cls->hull;
    s.shield = s.cls->shield;
    s.energy = s.cls->energy;
    if (!s.cls->missile.present && s.cls->plasma.present) s.secondary = SecondaryWeapon::Plasma;
    if (d.player) w.player = s.id;
    w.ships.push_back(std::move(s));
  }
  for (const PropDef& d : w.level.props) {
    Prop p;
    p.model = add_model(d.model);
    p.label = d.label;
    p.position = d.position;
    p.orientation = orientation_from_degrees(d.orientation_deg);
    p.scale = d.scale;
    p.radius = d.radius;
    w.props.push_back(std::move(p));
  }
  w.camera_mode = w.level.camera.mode == "cockpit" ? CameraMode::Cockpit
                  : w.level.camera.mode == "fixed" ? CameraMode::Fixed
                                                   : CameraMode::Chase;
  if (int f = w.focus_ship(); f >= 0) w.camera.orientation = w.ships[f].orientation;
  update_camera(w);
  w.prev_camera = w.camera;
  publish_owner_transforms(w);
  try {
    for (Ship& s : w.ships) {
      // Spawned at full intensity: the burst's particle count is scaled by the intensity of the
      // first particle step, after which update_shields_and_energy() dims it to what it shows.
      if (s.cls->shield > 0) spawn_shield(w, s, 4);
      for (const glm::dvec3& e : s.cls->exhausts) {
        SpawnParams ep;
        ep.owner = ship_owner(s.id);
        ep.position = e;
        ep.orientation = glm::angleAxis(kPi, glm::dvec3(0, 1, 0));  // exhaust cone points backwards (+Z)
        ep.scale = s.cls->collision_radius / 8.0;
        ep.priority = 0;
        s.exhaust_fx.push_back(spawn_fx(w, kFxEngineExhaust, ep));
      }
    }
  } catch (const InputError& e) {
    throw InputError(w.level.path + ": " + e.what());
  }
}

void step_world(World& w, const InputFrame& input, const std::vector<Command>& commands) {
  apply_commands(w, commands);
  if (w.paused) return;
  ++w.tick;
  for (Ship& s : w.ships) {
    s.prev_position = s.position;
    s.prev_orientation = s.orientation;
  }
  for (Ship& s : w.ships) {
    if (!s.alive) continue;
    if (s.id == w.player && s.ai == AiKind::None) s.controls = input;
    else if (s.ai == AiKind::Fighter) drive_ai(w, s);
    else if (s.ai == AiKind::Gunner) drive_gunner(w, s);
    else s.controls = InputFrame{};
    s.afterburner_on = (s.controls.buttons & kAfterburner) && s.energy > 0;
    if (s.afterburner_on) s.energy = std::max(0.0, s.energy - s.cls->afterburner_energy * w.dt);
    const int substeps = std::max(1, w.options.substeps);
    for (int k = 0; k < substeps; ++k) integrate_flight(s, w.dt / substeps);
  }
  collide_ships(w);
  for (Ship& s : w.ships) {
    if (!s.alive) continue;
    update_beam_trigger(w, s);
    fire_secondary(w, s);
  }
  move_projectiles(w);
  publish_owner_transforms(w);
  if (!w.level.effects.empty()) {
    try {
      spawn_level_effects(w);
    } catch (const InputError& e) {
      throw InputError(w.level.path + ": " + e.what());
    }
  }
  w.particles->step(static_cast<uint64_t>(w.tick), particle_camera(w));
  // After the step, so a new exhaust's one-off nozzle burst is emitted at full intensity.
  update_exhausts(w);
  resolve_beams(w);
  hit_projectiles(w);
  resolve_deaths(w);
  update_shields_and_energy(w);
  update_outcome(w);
  update_camera(w);
}

}  // namespace arc
