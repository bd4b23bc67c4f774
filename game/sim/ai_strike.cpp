// game/sim/ai_strike.cpp — a fighter against a capital ship: the subsystem it goes for and its
// torpedo runs. Deterministic: no random draws, so a strike follows the ships alone.
#include "game/sim/ai_strike.h"

#include <algorithm>
#include <cmath>

#include "game/sim/capital.h"
#include "game/sim/geometry.h"
#include "game/sim/world.h"

namespace arc {
namespace {

// A torpedo is slow: launched farther than this share of its reach, a turning target outruns it.
constexpr double kTorpedoReach = 0.6;
// Radians off the nose within which a pilot launches (a torpedo turns 45 °/s after it).
constexpr double kTorpedoCone = 0.3;

int first_live_subsystem(const Ship& t, SubsystemKind kind) {
  const ShipClassDef& c = *t.cls;
  for (size_t k = 0; k < c.subsystems.size(); ++k)
    if (c.subsystems[k].kind == kind && part_alive(t, c.turrets.size() + k)) return int(c.turrets.size() + k);
  return -1;
}

}  // namespace

int pick_strike_part(const World&, const Ship& s, const Ship& t) {
  if (!t.cls->capital() || t.parts.empty()) return -1;
  for (SubsystemKind kind : {SubsystemKind::ShieldGenerator, SubsystemKind::Engine})
    if (const int i = first_live_subsystem(t, kind); i >= 0) return i;
  int best = -1;
  double best_d = 0;
  for (size_t i = 0; i < t.cls->turrets.size(); ++i) {
    if (!part_alive(t, i)) continue;
    const double d = safe_len(part_position(t, i) - s.position);
    if (best < 0 || d < best_d) best = int(i), best_d = d;
  }
  return best;
}

void choose_strike_part(const World& w, Ship& s) {
  const bool capital = s.target && w.ship(s.target).cls->capital();
  if (!capital && s.target_part.empty()) return;
  s.target_part.clear();
  if (!capital) return;
  if (const int i = pick_strike_part(w, s, w.ship(s.target)); i >= 0) s.target_part.push_back(int32_t(i));
}

glm::dvec3 strike_aim_point(const World& w, const Ship& s, const Ship& t) {
  const int i = t.id == s.target ? target_part(w, s) : -1;
  return i >= 0 ? part_position(t, size_t(i)) : t.position;
}

void use_torpedoes(const World& w, Ship& s, const Ship& t, bool line_clear, InputFrame& c) {
  const ProjectileWeaponDef& torpedo = s.cls->torpedo;
  if (!torpedo.present) return;
  if (!t.cls->capital()) {
    // Back to the bank that hurts fighters, where the ship carries one.
    if (s.secondary != SecondaryWeapon::Torpedo) return;
    if (s.cls->missile.present) s.secondary = SecondaryWeapon::Missile;
    else if (s.cls->plasma.present && !s.cls->primary_plasma) s.secondary = SecondaryWeapon::Plasma;
    return;
  }
  s.secondary = SecondaryWeapon::Torpedo;
  const glm::dvec3 fwd = forward_of(s.orientation);
  const glm::dvec3 rel = strike_aim_point(w, s, t) - s.position;
  const double dist = safe_len(rel);
  const double off = std::acos(std::clamp(glm::dot(fwd, safe_norm(rel, fwd)), -1.0, 1.0));
  const bool ready = s.secondary_cooldown <= 0 && s.energy >= torpedo.energy;
  if (ready && line_clear && off < kTorpedoCone && dist < kTorpedoReach * torpedo.speed * torpedo.lifetime)
    c.buttons |= kFireSecondary;
}

}  // namespace arc
