// game/sim/ai_orders.cpp — how a wingman follows the player's orders (wing.h): its target at
// each decision, when it pulls out of a fight it would lose, and formation flight.
#include <algorithm>
#include <cmath>

#include "core/rng.h"
#include "game/sim/geometry.h"
#include "game/sim/wing.h"

namespace arc {
namespace {

bool recently_hit_by(const World& w, const Ship& victim, const Ship& attacker, double seconds) {
  return victim.last_attacker == attacker.id && w.tick - victim.last_hit_tick <= seconds_to_ticks(w, seconds);
}

// Who the covering wingman goes for: the hostile attacking the player nearest to the player,
// else the hostile nearest to the player within 60 % of the cover radius; none otherwise.
// Capital ships are left to the player's strike (leaves_capitals).
ShipId cover_target(const World& w, const Ship& p) {
  ShipId attacker, nearest;
  double attacker_d = 0, nearest_d = 0;
  for (const Ship& h : w.ships) {
    if (!h.alive || !w.hostile(p, h) || h.cls->capital()) continue;  // the player's own strike
    const double d = safe_len(h.position - p.position);
    if (d > kCoverRadius) continue;
    const bool attacking = h.ai_state.target == p.id || h.beam_target == p.id || recently_hit_by(w, p, h, 3.0);
    if (attacking && (!attacker || d < attacker_d)) attacker = h.id, attacker_d = d;
    if (d < 0.6 * kCoverRadius && (!nearest || d < nearest_d)) nearest = h.id, nearest_d = d;
  }
  return attacker ? attacker : nearest;
}

// A hostile within `range` of `s` whose nose points at it: someone on its tail or lining it up.
bool under_guns(const World& w, const Ship& s, double range) {
  for (const Ship& h : w.ships) {
    if (!h.alive || !w.hostile(s, h)) continue;
    const glm::dvec3 to_s = s.position - h.position;
    const double d = safe_len(to_s);
    if (d < range && glm::dot(forward_of(h.orientation), to_s) > std::cos(0.45) * d) return true;
  }
  return false;
}

// Hostiles and friends (itself not counted) within `radius` of `s`.
void count_near(const World& w, const Ship& s, double radius, int& hostiles, int& friends) {
  hostiles = friends = 0;
  for (const Ship& o : w.ships) {
    if (!o.alive || o.id == s.id || safe_len(o.position - s.position) > radius) continue;
    (w.hostile(s, o) ? hostiles : friends)++;
  }
}

// The slot's place off the player's wing, in the player's frame: alternately right and left,
// each pair farther back and out.
glm::dvec3 slot_offset(int slot) {
  const int pair = (std::max(slot, 1) + 1) / 2;
  const double side = slot % 2 == 1 ? 1.0 : -1.0;
  return {side * 45.0 * pair, 0.0, 35.0 * pair};
}

}  // namespace

ShipId wing_target(const World& w, const Ship& s, const Wingman& m, ShipId fallback) {
  if (!w.player || !w.ship(w.player).alive) return fallback;
  const Ship& p = w.ship(w.player);
  // Whatever the order, a wingman fights back against a hostile that is shooting it.
  const Ship* shooter = s.last_attacker ? &w.ship(s.last_attacker) : nullptr;
  const bool fired_upon = shooter && shooter->alive && w.hostile(s, *shooter) && recently_hit_by(w, s, *shooter, 2.0);
  switch (m.order) {
    case WingOrder::Attack: return m.target && w.ship(m.target).alive ? m.target : fallback;
    case WingOrder::Cover: {
      const ShipId t = cover_target(w, p);
      return t ? t : fired_upon ? shooter->id : ShipId{};
    }
    case WingOrder::FormUp: return fired_upon ? shooter->id : ShipId{};
    default: return fallback;
  }
}

bool wing_withdraw(World& w, Ship& s, const Rng& rng) {
  AiState& ai = s.ai_state;
  if (w.tick - ai.mode_until < seconds_to_ticks(w, 1.5)) return false;  // fights a while between withdrawals
  const double shield = s.cls->shield > 0 ? s.shield / s.cls->shield : 0.0;
  const double hull = s.hull / s.cls->hull;
  int hostiles = 0, friends = 0;
  count_near(w, s, 700.0, hostiles, friends);
  const bool hunted = (shield < 0.4 || hull < 0.5) && under_guns(w, s, 1.2 * s.cls->beam.range);
  const bool outnumbered = hostiles >= friends + 2 && shield < 0.75;
  if (!hunted && !outnumbered) return false;
  // Away across the attacker's line and back toward the player, where the friends are.
  glm::dvec3 home = forward_of(s.orientation);
  if (w.player && w.ship(w.player).alive) home = safe_norm(w.ship(w.player).position - s.position, home);
  const glm::dvec3 side = safe_norm(glm::cross(forward_of(s.orientation), rng.unit_vector(9)), glm::dvec3(0, 1, 0));
  ai.mode = AiMode::BreakOff;
  ai.mode_until = w.tick + seconds_to_ticks(w, 2.0 + 1.5 * rng.uniform(10));
  ai.evade_dir = safe_norm(side + home, side);
  return true;
}

bool leaves_capitals(const World& w, const Ship& chooser) {
  return w.player && chooser.id != w.player && chooser.team == w.ship(w.player).team;
}

double target_weight(const World& w, const Ship& chooser, const Ship& candidate) {
  if (w.wing.empty()) return 1.0;
  int hunters = 0;
  for (const Ship& o : w.ships)
    hunters += o.alive && o.id != chooser.id && o.team == chooser.team && o.ai_state.target == candidate.id ? 1 : 0;
  bool wingman = false;
  for (const Wingman& m : w.wing) wingman = wingman || m.ship == candidate.id;
  return (candidate.player ? 2.0 : wingman ? 1.25 : 1.0) * (1.0 + 0.6 * hunters);
}

bool fly_formation(const World& w, const Ship& s, const Wingman& m, InputFrame& c) {
  if (s.ai_state.target || !w.player || !w.ship(w.player).alive) return false;
  const Ship& p = w.ship(w.player);
  const glm::dvec3 spot = p.position + p.orientation * slot_offset(m.slot) + p.velocity * 0.5;
  const glm::dvec3 to_spot = spot - s.position;
  const double dist = safe_len(to_spot);
  const glm::dvec3 fwd = forward_of(s.orientation), heading = forward_of(p.orientation);
  // Far off: head for the spot; near it: turn to the player's heading, closing what is left.
  const double near = std::clamp(1.0 - dist / 250.0, 0.0, 1.0);
  const glm::dvec3 dir = safe_norm((1.0 - near) * safe_norm(to_spot, fwd) + near * (heading + to_spot / 120.0), fwd);
  glm::dvec3 local = glm::conjugate(s.orientation) * dir;
  const double yaw = std::atan2(local.x, -local.z);
  const double pitch = std::atan2(local.y, std::sqrt(local.x * local.x + local.z * local.z));
  const double yaw_rate = s.cls->turn_rate[1] * kDeg, pitch_rate = s.cls->turn_rate[0] * kDeg;
  c.yaw = quantise_axis(std::clamp(3.0 * yaw + 0.35 * s.angular_velocity.y / yaw_rate, -1.0, 1.0));
  c.pitch = quantise_axis(std::clamp(3.0 * pitch - 0.35 * s.angular_velocity.x / pitch_rate, -1.0, 1.0));
  c.roll = quantise_axis(-0.3 * s.angular_velocity.z);
  // Speed: the player's, plus what closes the gap along the nose within a few seconds.
  const double want = glm::dot(p.velocity, fwd) + 0.4 * glm::dot(to_spot, fwd);
  c.throttle = quantise_axis(std::clamp(want / s.cls->max_speed, 0.15, 1.0));
  if (dist > 600.0 && s.energy > 0.4 * s.cls->energy && glm::dot(fwd, safe_norm(to_spot, fwd)) > 0.9)
    c.buttons |= kAfterburner;
  return true;
}

}  // namespace arc
