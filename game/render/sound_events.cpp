#include "game/render/sound_events.h"

#include <algorithm>
#include <cmath>

#include "game/sim/seekers.h"
#include "game/sim/world.h"

namespace arc {
namespace {

constexpr int64_t kHitInterval = 6;  // ticks between two hit sounds on one ship
constexpr int64_t kPlayerHitInterval = 30;  // on the player's: each cuts through, so fewer
constexpr uint64_t kProjectileOwner = uint64_t(1) << 32;
constexpr uint64_t kLockOwner = uint64_t(3) << 32;  // the player's lock tone: one loop
// Seconds between lock ticks as the lock starts and just before it completes.
constexpr double kLockTickSlowest = 0.4, kLockTickFastest = 0.1;
constexpr double kWarningInterval = 1.5;  // seconds between missile warnings while one homes on the player

SoundEvent event(SoundKind kind, const glm::dvec3& p, const glm::dvec3& v, uint64_t owner, double intensity = 1) {
  SoundEvent e;
  e.kind = kind;
  e.position = p;
  e.velocity = v;
  e.owner = owner;
  e.intensity = intensity;
  return e;
}

}  // namespace

const char* sound_kind_name(SoundKind kind) {
  switch (kind) {
    case SoundKind::Beam: return "beam";
    case SoundKind::BeamHitShield: return "beam_hit_shield";
    case SoundKind::BeamHitHull: return "beam_hit_hull";
    case SoundKind::ShieldRecharge: return "shield_recharge";
    case SoundKind::MissileLaunch: return "missile_launch";
    case SoundKind::MissileFlight: return "missile_flight";
    case SoundKind::PlasmaShot: return "plasma_shot";
    case SoundKind::Explosion: return "explosion";
    case SoundKind::Afterburner: return "afterburner";
    case SoundKind::EngineHum: return "engine_hum";
    case SoundKind::LockTick: return "lock_tick";
    case SoundKind::LockTone: return "lock_tone";
    case SoundKind::Flare: return "flare";
    case SoundKind::PlayerHit: return "player_hit";
    case SoundKind::MissileWarning: return "missile_warning";
    case SoundKind::Kill: return "kill_confirm";
  }
  return "";
}

bool is_loop(SoundKind kind) {
  return kind == SoundKind::Beam || kind == SoundKind::MissileFlight || kind == SoundKind::EngineHum ||
         kind == SoundKind::LockTone;
}

// Where a damaged ship is being hit: on the beam of a ship firing at it, else at its centre.
glm::dvec3 SoundEventTracker::hit_point(const World& w, size_t target) const {
  const Ship& t = w.ships[target];
  for (const Ship& s : w.ships) {
    if (!s.alive || !s.beam_firing || s.beam_target != t.id) continue;
    for (double d : s.beam_hit_distance)
      if (d >= 0) return s.position + forward_of(s.orientation) * d;
  }
  return t.position;
}

void SoundEventTracker::ship_events(const World& w, size_t i, std::vector<SoundEvent>& out) {
  const Ship& s = w.ships[i];
  ShipMemory& m = ships_[i];
  const uint64_t owner = i + 1;
  if (s.alive) {
    const double throttle = std::abs(axis_value(s.controls.throttle));
    out.push_back(event(SoundKind::EngineHum, s.position, s.velocity, owner,
                        s.afterburner_on ? 1.0 : 0.35 + 0.55 * throttle));
    if (s.beam_firing) out.push_back(event(SoundKind::Beam, s.position, s.velocity, owner));
  }
  const bool regenerating = s.alive && s.shield > m.shield;
  if (primed_ && s.alive) {
    const double max_shield = std::max(s.cls->shield, 1e-9);
    if ((s.shield < m.shield || s.hull < m.hull) && w.tick >= m.next_hit_sound) {
      const bool shield = s.shield < m.shield;
      const double share = ((m.shield - s.shield) + (m.hull - s.hull)) / max_shield;
      const SoundKind kind = s.id == w.player ? SoundKind::PlayerHit
                             : shield         ? SoundKind::BeamHitShield
                                              : SoundKind::BeamHitHull;
      double intensity = std::clamp(0.5 + 10.0 * share, 0.5, 1.0);
      // The first hit on the player after a lull cuts through; the rest of a burst is quieter.
      if (kind == SoundKind::PlayerHit && w.tick < m.next_hit_sound + kPlayerHitInterval * 3) intensity = 0.4;
      out.push_back(event(kind, hit_point(w, i), s.velocity, owner, intensity));
      m.next_hit_sound = w.tick + (kind == SoundKind::PlayerHit ? kPlayerHitInterval : kHitInterval);
    }
    if (regenerating && !m.regenerating) out.push_back(event(SoundKind::ShieldRecharge, s.position, s.velocity, owner));
    if (s.afterburner_on && !m.afterburner) out.push_back(event(SoundKind::Afterburner, s.position, s.velocity, owner));
  }
  m.alive = s.alive;
  m.afterburner = s.afterburner_on;
  m.regenerating = regenerating;
  m.shield = s.shield;
  m.hull = s.hull;
}

void SoundEventTracker::projectile_events(const World& w, std::vector<SoundEvent>& out) {
  std::vector<uint32_t> now;
  for (const Projectile& p : w.projectiles) {
    now.push_back(p.serial);
    const uint64_t owner = kProjectileOwner + p.serial;
    const bool fresh = !std::binary_search(projectiles_.begin(), projectiles_.end(), p.serial);
    if (fresh && primed_)
      out.push_back(event(p.kind != SecondaryWeapon::Plasma ? SoundKind::MissileLaunch : SoundKind::PlasmaShot,
                          p.position, p.velocity, owner));
    if (p.kind != SecondaryWeapon::Plasma) out.push_back(event(SoundKind::MissileFlight, p.position, p.velocity, owner));
  }
  std::sort(now.begin(), now.end());
  projectiles_ = std::move(now);
}

// The player's lock: a tick each interval while it builds, the interval shrinking as it fills,
// and a steady tone once it is complete. Heard at the listener's ship.
void SoundEventTracker::lock_events(const World& w, std::vector<SoundEvent>& out) {
  if (!w.player || !w.ship(w.player).alive) return;
  const Ship& me = w.ship(w.player);
  const double progress = lock_progress(w, me);
  if (progress >= 1.0) {
    out.push_back(event(SoundKind::LockTone, me.position, me.velocity, kLockOwner));
    return;
  }
  if (progress <= 0.0) {
    next_lock_tick_ = 0;
    return;
  }
  if (!primed_ || w.tick < next_lock_tick_) return;
  out.push_back(event(SoundKind::LockTick, me.position, me.velocity, kLockOwner, 0.6 + 0.4 * progress));
  const double gap = kLockTickSlowest + (kLockTickFastest - kLockTickSlowest) * progress;
  next_lock_tick_ = w.tick + std::max<int64_t>(1, std::llround(gap / w.dt));
}

void SoundEventTracker::flare_events(const World& w, std::vector<SoundEvent>& out) {
  std::vector<uint32_t> now;
  for (const Flare& f : w.flares) {
    now.push_back(f.serial);
    if (primed_ && !std::binary_search(flares_.begin(), flares_.end(), f.serial))
      out.push_back(event(SoundKind::Flare, f.position, f.velocity, kProjectileOwner + f.serial));
  }
  std::sort(now.begin(), now.end());
  flares_ = std::move(now);
}

// The cues that must cut through the fight: a missile homing on the player (not one a flare
// pulled away) and each kill the player makes.
void SoundEventTracker::player_events(const World& w, std::vector<SoundEvent>& out) {
  if (!w.player) return;
  const Ship& me = w.ship(w.player);
  bool homing = false;
  for (const Projectile& p : w.projectiles) homing = homing || (p.kind == SecondaryWeapon::Missile && p.target == me.id && !p.decoy);
  if (!homing) next_warning_ = 0;
  if (homing && me.alive && primed_ && w.tick >= next_warning_) {
    // The first warning of a threat cuts through; its repeats remind, quieter.
    out.push_back(event(SoundKind::MissileWarning, me.position, me.velocity, kLockOwner, next_warning_ ? 0.3 : 1.0));
    next_warning_ = w.tick + std::max<int64_t>(1, std::llround(kWarningInterval / w.dt));
  }
  if (primed_ && me.kills > player_kills_) out.push_back(event(SoundKind::Kill, me.position, me.velocity, kLockOwner));
  player_kills_ = me.kills;
}

std::vector<SoundEvent> SoundEventTracker::collect(const World& w) {
  std::vector<SoundEvent> out;
  if (w.tick < tick_ || ships_.size() != w.ships.size()) {
    ships_.assign(w.ships.size(), ShipMemory{});
    projectiles_.clear();
    flares_.clear();
    next_lock_tick_ = 0;
    next_warning_ = 0;
    player_kills_ = 0;
    primed_ = false;
  }
  if (w.paused || (primed_ && w.tick == tick_)) return out;
  for (size_t i = 0; i < w.ships.size(); ++i) ship_events(w, i, out);
  projectile_events(w, out);
  flare_events(w, out);
  lock_events(w, out);
  player_events(w, out);
  if (primed_) {
    for (const ExplosionEvent& e : w.explosions) {
      if (e.tick <= tick_ || e.tick > w.tick) continue;
      SoundEvent boom = event(SoundKind::Explosion, e.position, glm::dvec3(0.0), 0);
      boom.size = e.radius;
      out.push_back(boom);
    }
  }
  tick_ = w.tick;
  primed_ = true;
  return out;
}

}  // namespace arc
