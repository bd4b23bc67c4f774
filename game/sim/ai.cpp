// game/sim/ai.cpp — the pilots: fighters think at their reaction time (target, evade, break off)
// and steer, aim and fire every tick; gunners fire in fixed bursts.
#include "game/sim/ai.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"
#include "game/sim/ai_strike.h"
#include "game/sim/geometry.h"
#include "game/sim/mission_events.h"
#include "game/sim/seekers.h"
#include "game/sim/wing.h"
#include "game/sim/world.h"

namespace arc {

void steer_toward(const Ship& s, const glm::dvec3& dir, double stick_limit, InputFrame& out) {
  glm::dvec3 local = glm::conjugate(s.orientation) * dir;
  double yaw_angle = std::atan2(local.x, -local.z);
  double pitch_angle = std::atan2(local.y, std::sqrt(local.x * local.x + local.z * local.z));
  if (local.z > 0 && std::fabs(local.x) < 1e-9 && std::fabs(local.y) < 1e-9) pitch_angle = kPi / 2;
  const double gain = 3.0, damping = 0.35;
  double yaw_rate = s.cls->turn_rate[1] * kDeg, pitch_rate = s.cls->turn_rate[0] * kDeg;
  // Yawing right is a negative rate about +Y, hence the sign of the damping term.
  double yaw_cmd = gain * yaw_angle + damping * (s.angular_velocity.y / std::max(yaw_rate, 1e-6));
  double pitch_cmd = gain * pitch_angle - damping * (s.angular_velocity.x / std::max(pitch_rate, 1e-6));
  out.yaw = quantise_axis(std::clamp(yaw_cmd, -stick_limit, stick_limit));
  out.pitch = quantise_axis(std::clamp(pitch_cmd, -stick_limit, stick_limit));
  // Level the wings slowly so the ship does not corkscrew.
  out.roll = quantise_axis(-0.3 * s.angular_velocity.z);
}

namespace {

constexpr uint64_t kAiStream = 0x41490000ull;

glm::dvec3 lead_point(const Ship& shooter, const Ship& target, double projectile_speed) {
  glm::dvec3 rel = target.position - shooter.position;
  if (projectile_speed <= 0) return target.position;
  double t = safe_len(rel) / projectile_speed;
  glm::dvec3 rel_v = target.velocity - shooter.velocity;
  for (int i = 0; i < 2; ++i) t = safe_len(rel + rel_v * t) / projectile_speed;
  return target.position + rel_v * t;
}

// The nearest hostile, but a damaged one counts as nearer: pilots go for the kill, so fights end
// in explosions instead of spreading damage over everyone. Where the player leads a wing, the
// player and ships already under attack count as farther (target_weight, ai_orders.cpp).
// The player's side leaves capital ships to the player (leaves_capitals, ai_orders.cpp).
ShipId pick_target(const World& w, ShipId self) {
  ShipId best;
  double best_score = 0;
  const Ship& me = w.ship(self);
  const bool no_capitals = leaves_capitals(w, me);
  for (const Ship& s : w.ships) {
    if (s.id == self || !s.alive || !w.hostile(me, s) || (no_capitals && s.cls->capital())) continue;
    const double health = (s.hull + s.shield) / std::max(1e-9, s.cls->hull + s.cls->shield);
    const double score = safe_len(s.position - me.position) * (0.4 + health) * target_weight(w, me, s);
    if (!best || score < best_score) best = s.id, best_score = score;
  }
  return best;
}

// Sitting on a player's tail: behind it (within 60 degrees of its tail), nose on it, in range.
bool on_players_tail(const Ship& s, const Ship& t, const glm::dvec3& rel, double dist) {
  if (!t.player || dist > 1.25 * s.cls->beam.range) return false;
  const bool behind = glm::dot(forward_of(t.orientation), rel) > 0.5 * dist;
  const bool nose_on = glm::dot(forward_of(s.orientation), rel) > 0.85 * dist;
  return behind && nose_on;
}

// A person cannot shake a pilot that never lets go, so after tail_limit_s on a player's tail
// the pilot breaks off to the side and gives the player a firing window (AI-versus-AI fights
// need no such mercy). Returns whether it broke off.
bool break_off_players_tail(const World& w, Ship& s, const Ship& t, const glm::dvec3& rel, double dist, const Rng& rng) {
  const AiDifficultyDef& tune = ai_difficulty(w, s);
  AiState& ai = s.ai_state;
  if (!on_players_tail(s, t, rel, dist)) {
    ai.tail_since = -1;
    return false;
  }
  if (ai.tail_since < 0) ai.tail_since = w.tick;
  if (tune.tail_limit_s <= 0 || w.tick - ai.tail_since < seconds_to_ticks(w, tune.tail_limit_s)) return false;
  ai.tail_since = -1;
  ai.mode = AiMode::BreakOff;
  ai.mode_until = w.tick + seconds_to_ticks(w, tune.tail_break_s);
  ai.evade_dir = safe_norm(glm::cross(rel, rng.unit_vector(8)), glm::dvec3(0, 1, 0));
  return true;
}

// The autopilot in the player's seat leads a strike as the briefings tell a player to: on a
// capital ship it orders the wing to attack its target (F5), since the wing leaves one alone.
void lead_strike(World& w, const Ship& s) {
  if (s.id != w.player || !s.target || !w.ship(s.target).cls->capital()) return;
  for (const Wingman& m : w.wing)
    if (w.ship(m.ship).alive && (m.order != WingOrder::Attack || m.target != s.target))
      return order_wing(w, Command::OrderAttack);
}

void think(World& w, Ship& s) {
  const AiDifficultyDef& tune = ai_difficulty(w, s);
  AiState& ai = s.ai_state;
  const Rng rng{w.seed, kAiStream + static_cast<uint64_t>(s.id.index()), static_cast<uint64_t>(w.tick)};
  ai.next_think = w.tick + std::max<int64_t>(1, seconds_to_ticks(w, tune.reaction_s));
  if (!ai.target || !w.ship(ai.target).alive || rng.uniform(0) < 0.25) ai.target = pick_target(w, s.id);
  if (const ShipId ordered = ordered_target(w, s.id)) ai.target = ordered;  // an event's attack order
  const Wingman* wing = wingman_of(w, s.id);  // the player's orders come first (ai_orders.cpp)
  if (wing) ai.target = wing_target(w, s, *wing, ai.target);
  s.target = ai.target;
  lead_strike(w, s);
  choose_strike_part(w, s);
  ai.aim_error = rng.unit_vector(1) * (tune.aim_error * rng.uniform(2));
  if (!ai.target) return;
  const Ship& t = w.ship(ai.target);
  const glm::dvec3 rel = t.position - s.position;
  const double dist = safe_len(rel);
  const double shield_frac = s.cls->shield > 0 ? s.shield / s.cls->shield : 0.0;
  const double hull_frac = s.hull / s.cls->hull;
  if (ai.mode != AiMode::Attack && w.tick < ai.mode_until) {
    ai.tail_since = -1;
    return;
  }
  ai.mode = AiMode::Attack;
  if (break_off_players_tail(w, s, t, rel, dist, rng)) return;
  if (wing && wing_withdraw(w, s, rng)) return;
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

// Under its target's guns (the target's nose within about 9 degrees of this ship, within a
// little more than its beam range) a pilot jinks: it strafes at `jink` of full thrust in a
// direction drawn anew every 0.8 s, so a shooter who reacts late slides off it.
void jink(const World& w, const Ship& s, const Ship& t, double amount, InputFrame& c) {
  const glm::dvec3 from_t = s.position - t.position;
  const double dist = safe_len(from_t);
  if (amount <= 0 || dist > 1.2 * t.cls->beam.range) return;
  if (glm::dot(forward_of(t.orientation), from_t) < std::cos(0.15) * dist) return;
  const int64_t period = std::max<int64_t>(1, seconds_to_ticks(w, 0.8));
  const Rng rng{w.seed, kAiStream + 0x200 + static_cast<uint64_t>(s.id.index()), static_cast<uint64_t>(w.tick / period)};
  const double a = 2.0 * kPi * rng.uniform(0);
  c.strafe_x = quantise_axis(amount * std::cos(a));
  c.strafe_y = quantise_axis(amount * std::sin(a));
}

}  // namespace

const AiDifficultyDef& ai_difficulty(const World& w) {
  return w.level.ai[static_cast<size_t>(std::clamp(w.difficulty, 0, 2))];
}

const AiDifficultyDef& ai_difficulty(const World& w, const Ship& s) {
  const bool ally = w.player && w.ship(w.player).id != s.id && !w.hostile(w.ship(w.player), s);
  return ally && w.level.ai.allies ? *w.level.ai.allies : ai_difficulty(w);
}

void drive_ai(World& w, Ship& s) {
  if (w.tick >= s.ai_state.next_think) think(w, s);
  const AiDifficultyDef& tune = ai_difficulty(w, s);
  AiState& ai = s.ai_state;
  InputFrame c;
  if (const Wingman* m = wingman_of(w, s.id); m && fly_formation(w, s, *m, c)) {
    s.controls = c;
    return;
  }
  if (!ai.target || !w.ship(ai.target).alive) {
    c.throttle = quantise_axis(0.5);
    c.roll = quantise_axis(-0.3 * s.angular_velocity.z);
    s.controls = c;
    return;
  }
  const Ship& t = w.ship(ai.target);
  const glm::dvec3 fwd = forward_of(s.orientation);
  if (ai.mode != AiMode::Attack) {
    steer_toward(s, ai.evade_dir, tune.stick_limit, c);
    c.throttle = quantise_axis(1.0);
    if (s.energy > 0.3 * s.cls->energy) c.buttons |= kAfterburner;
    jink(w, s, t, tune.jink, c);
    s.controls = c;
    return;
  }
  const bool plasma = s.secondary == SecondaryWeapon::Plasma && s.cls->plasma.present;
  // Against a capital ship: the part it goes for (ai_strike.h), which moves with the hull.
  const glm::dvec3 on = t.cls->capital() ? strike_aim_point(w, s, t) - t.position : glm::dvec3(0.0);
  const glm::dvec3 rel = t.position + on - s.position;
  const double dist = safe_len(rel);
  glm::dvec3 aim = (plasma ? lead_point(s, t, s.cls->plasma.speed) : t.position + t.velocity * w.dt) + on;
  glm::dvec3 dir = safe_norm(aim - s.position, fwd);
  dir = safe_norm(dir + ai.aim_error, dir);
  steer_toward(s, dir, tune.stick_limit, c);
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
  const Rng rng{w.seed, kAiStream + 0x100 + static_cast<uint64_t>(s.id.index()), static_cast<uint64_t>(w.tick)};
  if (line_clear && s.cls->missile.present && !plasma && missile_locked(w, s) && dist > 80 &&
      rng.uniform(0) < 0.02 * tune.aggression)
    c.buttons |= kFireSecondary;
  if (line_clear && plasma && energy_frac > 0.25 && off < cone + 0.03 &&
      dist < s.cls->plasma.speed * s.cls->plasma.lifetime * 0.8)
    c.buttons |= kFireSecondary;
  // Switch weapons now and then so both get used.
  if (s.cls->missile.present && s.cls->plasma.present && rng.uniform(1) < 0.004)
    s.secondary = s.secondary == SecondaryWeapon::Missile ? SecondaryWeapon::Plasma : SecondaryWeapon::Missile;
  use_torpedoes(w, s, t, line_clear, c);
  jink(w, s, t, tune.jink, c);
  s.controls = c;
}

// Straight ahead until AiState::mode_until (set when it arrives), then slow circles, at a third of
// its speed; it fires its missile once at a target a training step gave it, then forgets the
// target (with the missile on its way, the cooldown is running).
void drive_drone(const World& w, Ship& s) {
  InputFrame c;
  c.throttle = quantise_axis(0.35);
  if (w.tick >= s.ai_state.mode_until) c.yaw = quantise_axis(0.12);
  c.roll = quantise_axis(-0.3 * s.angular_velocity.z);
  if (s.target && (!w.ship(s.target).alive || s.secondary_cooldown > 0)) s.target = {};
  if (s.target) {
    steer_toward(s, safe_norm(w.ship(s.target).position - s.position, forward_of(s.orientation)), 1.0, c);
    c.buttons |= kFireSecondary;
  }
  s.controls = c;
}

void drive_gunner(const World& w, Ship& s) {
  InputFrame c;
  // Three seconds on, one off: the beam's energy drain outpaces regeneration only slightly.
  if (w.tick % 240 < 180) c.buttons |= kFirePrimary;
  c.buttons |= kFireSecondary;
  s.controls = c;
}

}  // namespace arc
