// game/sim/projectiles.cpp — the secondary weapons: missiles (homing, their smoke stays behind)
// and plasma bolts, from the shot through flight to a hit or expiry.
#include "game/sim/projectiles.h"

#include <algorithm>
#include <cmath>

#include "game/sim/capital.h"
#include "game/sim/damage.h"
#include "game/sim/effects.h"
#include "game/sim/geometry.h"
#include "game/sim/seekers.h"
#include "game/sim/world.h"

namespace arc {
namespace {

constexpr double kDecoyBurstRadius = 4.0;  // metres: a decoyed missile this near its flare bursts

void end_projectile(World& w, Projectile& p) {
  if (p.kind != SecondaryWeapon::Plasma) {
    // The smoke stays behind and fades; the flame goes with the missile.
    w.particles->release_owner(p.particle_owner);
  } else {
    w.particles->destroy_owner(p.particle_owner);
  }
}

}  // namespace

namespace {

const ProjectileWeaponDef& weapon_def(const Ship& s, SecondaryWeapon kind) {
  return kind == SecondaryWeapon::Plasma ? s.cls->plasma : kind == SecondaryWeapon::Torpedo ? s.cls->torpedo : s.cls->missile;
}

// One shot of `kind` when `held`, cooled down (`cooldown` counts down here) and paid for.
void launch(World& w, Ship& s, SecondaryWeapon kind, bool held, double& cooldown) {
  cooldown = std::max(0.0, cooldown - w.dt);
  if (!held) return;
  const bool plasma = kind == SecondaryWeapon::Plasma;
  const bool torpedo = kind == SecondaryWeapon::Torpedo;
  const ProjectileWeaponDef& wd = weapon_def(s, kind);
  if (!wd.present || cooldown > 0 || s.energy < wd.energy) return;
  // A missile leaves only with a complete lock: a trigger held early fires the moment it locks.
  if (kind == SecondaryWeapon::Missile && !missile_locked(w, s)) return;
  // A torpedo needs a capital ship targeted: it harms nothing else.
  if (torpedo && (!s.target || !w.ship(s.target).alive || !w.ship(s.target).cls->capital())) return;
  s.energy -= wd.energy;
  cooldown = wd.cooldown;
  s.stats.missiles_fired++;
  if (plasma) s.stats.plasma_fired++;
  const glm::dvec3 hp = wd.hardpoints[s.hardpoint_cycle++ % wd.hardpoints.size()];
  Projectile p;
  p.serial = w.next_projectile_serial++;
  p.kind = kind;
  p.owner = s.id;
  p.target = plasma ? ShipId{} : s.target;
  if (torpedo && target_part(w, s) >= 0) p.part.push_back(target_part(w, s));
  p.particle_owner = allocate_owner(w);
  p.position = p.prev_position = s.position + s.orientation * hp;
  p.velocity = s.velocity + forward_of(s.orientation) * wd.speed;
  p.damage = wd.damage;
  p.turn_rate = wd.turn_rate * kDeg;
  p.hit_radius = wd.hit_radius;
  p.expire_tick = w.tick + std::max<int64_t>(1, seconds_to_ticks(w, wd.lifetime));
  set_owner(w, p.particle_owner, p.position, s.orientation, p.velocity);
  SpawnParams sp;
  sp.owner = p.particle_owner;
  if (torpedo) sp.scale = 1.8;
  p.trail = spawn_fx(w, plasma ? w.fx.plasma_bolt : w.fx.missile_trail, sp);
  w.projectiles.push_back(std::move(p));
}

}  // namespace

void fire_secondary(World& w, Ship& s) {
  launch(w, s, s.secondary, s.controls.buttons & kFireSecondary, s.secondary_cooldown);
}

void fire_primary_plasma(World& w, Ship& s) {
  if (s.primary_cooldown.empty()) s.primary_cooldown.push_back(0.0);
  launch(w, s, SecondaryWeapon::Plasma, s.controls.buttons & kFirePrimary, s.primary_cooldown[0]);
}

// Where a homing missile steers: its decoy flare, else its target; none once the target has
// left its seeker cone (it then flies straight on: a hard turn can shake it off).
const glm::dvec3* seeker_aim(const World& w, Projectile& p, glm::dvec3& part_at) {
  if (p.kind == SecondaryWeapon::Torpedo) {
    // A torpedo keeps its target whatever it does (no seeker cone, no flares): slow, not blind.
    if (!p.target || !w.ship(p.target).alive) return nullptr;
    const Ship& t = w.ship(p.target);
    if (p.part.empty() || !part_alive(t, size_t(p.part[0]))) return &t.position;
    part_at = part_position(t, size_t(p.part[0]));
    return &part_at;
  }
  if (p.kind != SecondaryWeapon::Missile) return nullptr;
  if (p.decoy != 0) {
    const Flare* f = find_flare(w, p.decoy);
    return f ? &f->position : nullptr;
  }
  if (!p.target || !w.ship(p.target).alive) return nullptr;
  const glm::dvec3& at = w.ship(p.target).position;
  const glm::dvec3 dir = safe_norm(p.velocity, glm::dvec3(0, 0, -1));
  const double off = std::acos(std::clamp(glm::dot(dir, safe_norm(at - p.position, dir)), -1.0, 1.0));
  if (off > w.ship(p.owner).cls->missile.seeker_cone * kDeg) {
    p.target = {};
    return nullptr;
  }
  return &at;
}

void move_projectiles(World& w) {
  for (Projectile& p : w.projectiles) {
    p.prev_position = p.position;
    glm::dvec3 part_at(0.0);
    if (const glm::dvec3* aim = seeker_aim(w, p, part_at)) {
      const double speed = safe_len(p.velocity);
      glm::dvec3 dir = safe_norm(p.velocity, glm::dvec3(0, 0, -1));
      glm::dvec3 want = safe_norm(*aim - p.position, dir);
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
    set_owner(w, p.particle_owner, p.position, q, p.velocity);
  }
}

void hit_projectiles(World& w) {
  size_t keep = 0;
  for (size_t i = 0; i < w.projectiles.size(); ++i) {
    Projectile& p = w.projectiles[i];
    // A decoyed missile's fuse waits for its flare: it bursts there and passes through ships.
    const Flare* decoy = p.decoy ? find_flare(w, p.decoy) : nullptr;
    if (decoy && segment_sphere(p.prev_position, p.position, decoy->position, kDecoyBurstRadius) >= 0) {
      SpawnParams sp;
      sp.position = decoy->position;
      spawn_fx(w, w.fx.hull_sparks, sp);
      end_projectile(w, p);
      continue;
    }
    ShipId hit_ship;
    double best_t = 2.0;
    bool on_shield = false;
    const bool torpedo = p.kind == SecondaryWeapon::Torpedo;
    for (const Ship& s : w.ships) {
      if (!s.alive || s.id == p.owner || decoy) continue;
      if (torpedo && !s.cls->capital()) continue;  // it passes fighters by
      const bool shield_up = s.shield > 0;
      double r = (shield_up ? s.cls->shield_radius : s.cls->collision_radius) + p.hit_radius;
      double t = segment_sphere(p.prev_position, p.position, s.position, r);
      if (!shield_up && !s.parts.empty()) {
        const double tp = segment_parts(s, p.prev_position, p.position);
        if (tp >= 0 && (t < 0 || tp < t)) t = tp;
      }
      if (t >= 0 && t < best_t) best_t = t, hit_ship = s.id, on_shield = shield_up;
    }
    if (hit_ship) {
      Ship& t = w.ship(hit_ship);
      glm::dvec3 point = p.prev_position + (p.position - p.prev_position) * best_t;
      SpawnParams sp;
      sp.position = point;
      sp.velocity = t.velocity;
      spawn_fx(w, on_shield ? w.fx.shield_hit : w.fx.hull_sparks, sp);
      if (w.hostile(w.ship(p.owner), t)) {
        CombatStats& st = w.ship(p.owner).stats;
        const double dealt_before = st.damage_dealt;
        st.missiles_hit++;
        if (torpedo) {
          // Through the shield to the part it homed on (or the parts where it struck).
          apply_damage(w, t, p.damage, point, p.owner, false);
          damage_parts(w, t, point, p.damage, p.owner, p.part.empty() ? -1 : p.part[0]);
        } else {
          apply_damage(w, t, p.damage, point, p.owner);
        }
        const double dealt = st.damage_dealt - dealt_before;
        if (p.kind == SecondaryWeapon::Plasma) st.plasma_hit++, st.plasma_damage += dealt;
        else st.missile_damage += dealt;
      }
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

}  // namespace arc
