// game/sim/seekers.cpp — missile locks, flares, decoyed missiles, and the AI's defence against
// missiles (game/sim/seekers.h).
#include "game/sim/seekers.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"
#include "game/sim/ai.h"
#include "game/sim/effects.h"
#include "game/sim/geometry.h"

namespace arc {
namespace {

constexpr uint64_t kDecoyStream = 0x464C0000ull;    // which missiles a flare pulls
constexpr uint64_t kDefenceStream = 0x464C1000ull;  // when an AI pilot notices a missile
constexpr double kFlareDrag = 1.2;                  // 1/s: a flare slows behind its ship
constexpr double kFlareEjectSpeed = 25.0;           // m/s out to one side, up and back from the ship

double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
  return std::acos(std::clamp(glm::dot(safe_norm(a, glm::dvec3(0, 0, -1)), safe_norm(b, glm::dvec3(0, 0, -1))), -1.0, 1.0));
}

bool lock_holds(const World& w, const Ship& s) {
  const ProjectileWeaponDef& m = s.cls->missile;
  if (!m.present || s.secondary != SecondaryWeapon::Missile || !s.target) return false;
  const Ship& t = w.ship(s.target);
  if (!t.alive || !w.hostile(s, t)) return false;
  const glm::dvec3 rel = t.position - s.position;
  return safe_len(rel) <= m.lock_range && angle_between(forward_of(s.orientation), rel) <= m.lock_cone * kDeg;
}

int64_t lock_ticks_needed(const World& w, const Ship& s) {
  return std::max<int64_t>(1, seconds_to_ticks(w, s.cls->missile.lock_time));
}

// Each missile homing on `s` with the flare inside its seeker cone may take it for its target.
void pull_missiles(World& w, const Ship& s, const Flare& f) {
  for (Projectile& p : w.projectiles) {
    if (p.kind != SecondaryWeapon::Missile || p.target != s.id || p.decoy != 0) continue;
    const double cone = w.ship(p.owner).cls->missile.seeker_cone * kDeg;
    if (angle_between(p.velocity, f.position - p.position) > cone) continue;
    const Rng rng{w.seed, kDecoyStream, p.serial};
    if (rng.uniform(f.serial) < s.cls->countermeasures.decoy_chance) p.decoy = f.serial;
  }
}

// Stick commands turning the nose toward a world direction, full deflection.
void hard_turn(const Ship& s, const glm::dvec3& dir, InputFrame& c) {
  const glm::dvec3 local = glm::conjugate(s.orientation) * dir;
  const double yaw = std::atan2(local.x, -local.z);
  const double pitch = std::atan2(local.y, std::sqrt(local.x * local.x + local.z * local.z));
  c.yaw = quantise_axis(std::clamp(4.0 * yaw, -1.0, 1.0));
  c.pitch = quantise_axis(std::clamp(4.0 * pitch, -1.0, 1.0));
}

}  // namespace

void update_locks(World& w) {
  for (Ship& s : w.ships) {
    SeekerState& k = s.seeker;
    if (!s.alive || !lock_holds(w, s)) {
      k.lock_target = {};
      k.lock_ticks = 0;
      continue;
    }
    if (k.lock_target != s.target) k.lock_target = s.target, k.lock_ticks = 0;
    k.lock_ticks = std::min(k.lock_ticks + 1, lock_ticks_needed(w, s));
  }
}

bool missile_locked(const World& w, const Ship& s) {
  return s.seeker.lock_target && s.seeker.lock_target == s.target && s.seeker.lock_ticks >= lock_ticks_needed(w, s);
}

double lock_progress(const World& w, const Ship& s) {
  if (!s.cls->missile.present || !s.seeker.lock_target || s.seeker.lock_target != s.target) return 0.0;
  return std::clamp(double(s.seeker.lock_ticks) / double(lock_ticks_needed(w, s)), 0.0, 1.0);
}

bool drop_flare(World& w, Ship& s) {
  SeekerState& k = s.seeker;
  if (!s.alive || k.flares <= 0 || w.tick < k.flare_ready_tick) return false;
  const CountermeasureDef& cm = s.cls->countermeasures;
  k.flares--;
  k.flare_ready_tick = w.tick + std::max<int64_t>(1, seconds_to_ticks(w, cm.cooldown));
  Flare f;
  f.serial = w.next_projectile_serial++;
  f.owner = s.id;
  f.particle_owner = allocate_owner(w);
  // Out to one side (alternating), up and back: it drifts past the chase eye beside the ship,
  // where the player sees it burn (the ship sits low in the chase frame, so a flare falling under
  // it would leave the screen at once, and one straight back would glow across the eye).
  const double side = k.flares % 2 == 0 ? 1.0 : -1.0;
  const glm::dvec3 back = s.orientation * glm::dvec3(0.7 * side, 0.3, 0.65);
  f.position = f.prev_position = s.position + back * (s.cls->shield_radius + 2.0);
  f.velocity = s.velocity + safe_norm(back, glm::dvec3(0, 0, 1)) * kFlareEjectSpeed;
  f.expire_tick = w.tick + std::max<int64_t>(1, seconds_to_ticks(w, cm.lifetime));
  set_owner(w, f.particle_owner, f.position, s.orientation, f.velocity);
  SpawnParams sp;
  sp.owner = f.particle_owner;
  f.fx = spawn_fx(w, w.fx.flare, sp);
  pull_missiles(w, s, f);
  w.flares.push_back(std::move(f));
  return true;
}

const Flare* find_flare(const World& w, uint32_t serial) {
  for (const Flare& f : w.flares)
    if (f.serial == serial) return &f;
  return nullptr;
}

void update_flares(World& w) {
  const double keep = std::exp(-kFlareDrag * w.dt);
  size_t n = 0;
  for (size_t i = 0; i < w.flares.size(); ++i) {
    Flare& f = w.flares[i];
    if (w.tick >= f.expire_tick) {
      w.particles->release_owner(f.particle_owner);
      continue;
    }
    f.prev_position = f.position;
    f.velocity *= keep;
    f.position += f.velocity * w.dt;
    set_owner(w, f.particle_owner, f.position, glm::dquat(1, 0, 0, 0), f.velocity);
    if (n != i) w.flares[n] = std::move(f);
    ++n;
  }
  w.flares.resize(n);
  // A missile whose flare burnt out has lost its target and flies straight on.
  for (Projectile& p : w.projectiles) {
    if (p.decoy == 0 || find_flare(w, p.decoy)) continue;
    p.decoy = 0;
    p.target = {};
  }
}

void defend_against_missiles(World& w, Ship& s) {
  const Projectile* nearest = nullptr;
  double best = 0;
  for (const Projectile& p : w.projectiles) {
    if (p.kind != SecondaryWeapon::Missile || p.target != s.id || p.decoy != 0) continue;
    const double d = safe_len(p.position - s.position);
    if (!nearest || d < best) nearest = &p, best = d;
  }
  if (!nearest) return;
  const AiDifficultyDef& tune = ai_difficulty(w, s);
  const double notice = 250.0 + 350.0 * tune.aggression;  // metres: calmer pilots see it later
  if (best > notice) return;
  // Noticing takes the pilot's reaction time on average.
  const Rng rng{w.seed, kDefenceStream + static_cast<uint64_t>(s.id.index()), static_cast<uint64_t>(w.tick)};
  if (rng.uniform(0) < w.dt / std::max(tune.reaction_s, w.dt)) drop_flare(w, s);
  // Turn across the missile's path: the side of its line of flight the ship is already on.
  const glm::dvec3 mdir = safe_norm(nearest->velocity, glm::dvec3(0, 0, -1));
  const glm::dvec3 off = s.position - nearest->position;
  glm::dvec3 across = off - mdir * glm::dot(off, mdir);
  across = safe_norm(across, safe_norm(glm::cross(mdir, glm::dvec3(0, 1, 0)), glm::dvec3(1, 0, 0)));
  if (best < 0.6 * notice) {
    hard_turn(s, across, s.controls);
    s.controls.throttle = quantise_axis(1.0);
    s.controls.buttons &= uint16_t(~(kFirePrimary | kFireSecondary));
  }
}

}  // namespace arc
