// tests/unit/game/test_pilot.cpp — the test pilot: the HUD read like hud_layout.cpp lays it
// out, a 200 ms reaction delay, a wandering hand, and duels flown through the player's input.
#include "test_pilot.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/rng.h"
#include "game/sim/game.h"
#include "game/sim/geometry.h"
#include "game/sim/world.h"

namespace arc {
namespace {

constexpr uint64_t kHandStream = 0x50494c4f54ull;  // "PILOT"
constexpr double kNearPlane = 0.5;                 // CameraView's default

// The HUD's projection (hud_layout.cpp's Projector) through the World's camera rig.
struct Projection {
  glm::dvec3 position;
  glm::dquat inverse;
  double focal, cx, cy;
  glm::dvec3 to_view(const glm::dvec3& p) const { return inverse * (p - position); }
  bool project(const glm::dvec3& world, glm::dvec2& px) const {
    const glm::dvec3 v = to_view(world);
    if (v.z > -kNearPlane) return false;
    px = {cx + v.x / -v.z * focal, cy - v.y / -v.z * focal};
    return true;
  }
};

// The lead indicator as hud_target() computes it: where to aim the selected projectile.
bool lead_point(const Ship& me, const Ship& t, const Projection& pr, glm::dvec2& px) {
  const bool plasma = me.secondary == SecondaryWeapon::Plasma && me.cls->plasma.present;
  const double speed = plasma ? me.cls->plasma.speed : me.cls->missile.present ? me.cls->missile.speed : 0.0;
  if (speed <= 0) return false;
  const glm::dvec3 rel = t.position - me.position, rv = t.velocity - me.velocity;
  double time = std::sqrt(glm::dot(rel, rel)) / speed;
  for (int i = 0; i < 2; ++i) time = std::sqrt(glm::dot(rel + rv * time, rel + rv * time)) / speed;
  return pr.project(t.position + rv * time, px);
}

double stick(double v) { return std::clamp(v, -1.0, 1.0); }

}  // namespace

HudReading read_hud(const World& w, int width, int height) {
  HudReading h;
  h.width = width;
  h.height = height;
  const double fov = w.level.camera.fov_deg * kDeg;
  h.focal = (height * 0.5) / std::tan(fov * 0.5);
  const Projection pr{w.camera.position, glm::conjugate(w.camera.orientation), h.focal, width * 0.5, height * 0.5};
  h.crosshair = {width * 0.5, height * 0.5};
  const ShipId focus = w.focus_ship();
  if (!focus || !w.ship(focus).alive) return h;
  const Ship& me = w.ship(focus);
  pr.project(me.position + forward_of(me.orientation) * me.cls->beam.range * 0.5, h.crosshair);
  h.energy = me.cls->energy > 0 ? me.energy / me.cls->energy : 0.0;
  h.plasma = me.secondary == SecondaryWeapon::Plasma;
  if (!me.target || !w.ship(me.target).alive) return h;
  const Ship& t = w.ship(me.target);
  h.has_target = true;
  h.distance = glm::length(t.position - me.position);
  glm::dvec2 px;
  const bool in_front = pr.project(t.position, px);
  h.on_screen = in_front && px.x >= 0 && px.x <= width && px.y >= 0 && px.y <= height;
  if (h.on_screen) {
    h.target = px;
    h.bracket = std::max(t.cls->shield_radius * h.focal / -pr.to_view(t.position).z, 14.0);
    h.has_lead = lead_point(me, t, pr, h.lead);
    return h;
  }
  const glm::dvec3 v = pr.to_view(t.position);
  const glm::dvec2 dir(v.x, -v.y);
  const double len = glm::length(dir);
  h.arrow = len > 1e-9 ? dir / len : glm::dvec2(0, 1);
  return h;
}

TestPilot::TestPilot(uint64_t seed, PilotSkill skill) : seed_(seed), skill_(skill) {}

// The hand wanders: every hold period it drifts toward a fresh Gaussian offset (Box–Muller).
glm::dvec2 TestPilot::hand_offset(const World& w) {
  const int64_t hold = std::max<int64_t>(1, seconds_to_ticks(w, skill_.aim_noise_hold_s));
  const Rng rng{seed_, kHandStream, static_cast<uint64_t>(w.tick / hold)};
  const double r = std::sqrt(-2.0 * std::log(1.0 - rng.uniform(0))), a = 2.0 * kPi * rng.uniform(1);
  const glm::dvec2 goal = glm::dvec2(std::cos(a), std::sin(a)) * (r * skill_.aim_noise_px);
  hand_ += (goal - hand_) * (1.0 - std::exp(-w.dt / skill_.aim_noise_smooth_s));
  return hand_;
}

void TestPilot::steer(const HudReading& seen, const HudReading& before, const glm::dvec2& hand, double dt,
                      InputFrame& in) const {
  if (!seen.on_screen) {
    // Off screen: turn hard toward the arrow, the larger axis at full stick.
    const double m = std::max(std::fabs(seen.arrow.x), std::fabs(seen.arrow.y));
    in.yaw = quantise_axis(seen.arrow.x / m);
    in.pitch = quantise_axis(-seen.arrow.y / m);
    return;
  }
  const double scale = seen.height / 720.0;
  auto angle = [&](const HudReading& r, const glm::dvec2& p) {
    return glm::dvec2(std::atan((p.x - r.crosshair.x) / r.focal), std::atan((p.y - r.crosshair.y) / r.focal));
  };
  // Plasma flies straight: aim at the lead indicator; the beam hits at once and missiles home.
  auto aim = [&](const HudReading& r) { return (r.plasma && r.has_lead ? r.lead : r.target) + hand * scale; };
  const glm::dvec2 err = angle(seen, aim(seen));
  const glm::dvec2 rate = before.on_screen ? (err - angle(before, aim(before))) / dt : glm::dvec2(0.0);
  const glm::dvec2 cmd = err * skill_.turn_gain + rate * skill_.turn_damping;
  in.yaw = quantise_axis(stick(cmd.x));
  in.pitch = quantise_axis(stick(-cmd.y));
}

void TestPilot::act(const World& w, InputFrame& in, std::vector<Command>& commands) {
  in = InputFrame{};
  commands.clear();
  seen_.push_back(read_hud(w));
  const size_t delay = static_cast<size_t>(std::max<int64_t>(1, seconds_to_ticks(w, skill_.reaction_s)));
  while (seen_.size() > delay + 2) seen_.pop_front();
  // What it saw `delay` ticks ago, and the tick before that (for how fast things moved).
  const size_t now = seen_.size() > delay ? seen_.size() - 1 - delay : 0;
  const HudReading& seen = seen_[now];
  const HudReading& before = seen_[now > 0 ? now - 1 : 0];
  const glm::dvec2 hand = hand_offset(w);
  const ShipId me = w.focus_ship();
  if (!me || !w.ship(me).alive) return;
  const ShipClassDef& cls = *w.ship(me).cls;
  if (!seen.has_target) {
    // The Y key (next hostile), pressed again if nothing happened half a second later.
    if (w.tick - last_target_key_ > seconds_to_ticks(w, 0.5)) {
      commands.push_back(Command::TargetNextHostile);
      last_target_key_ = w.tick;
    }
    in.throttle = quantise_axis(0.5);
    return;
  }
  steer(seen, before, hand, w.dt, in);
  const double d = seen.distance;
  in.throttle = quantise_axis(d > 800 ? 1.0 : d > 400 ? 0.8 : d > 150 ? 0.55 : 0.35);
  if (d > 1500 && seen.on_screen && seen.energy > 0.5) in.buttons |= kAfterburner;
  if (!seen.on_screen) return;
  // The beam while the crosshair sits inside the brackets within beam range; missiles (they
  // home) when the target is near the crosshair; plasma when the lead indicator is on it.
  const double off = glm::length(seen.target - seen.crosshair);
  if (off < seen.bracket && d < cls.beam.range) in.buttons |= kFirePrimary;
  if (!seen.plasma && off < 3.0 * seen.bracket && d < 1200) in.buttons |= kFireSecondary;
  if (seen.plasma && seen.has_lead && glm::length(seen.lead - seen.crosshair) < seen.bracket &&
      d < cls.plasma.speed * cls.plasma.lifetime)
    in.buttons |= kFireSecondary;
}

Game load_flight(const std::string& root_dir, const std::string& level, int difficulty, uint64_t seed) {
  GameOptions o;
  o.root_dir = root_dir;
  o.difficulty_override = true;
  o.difficulty = static_cast<Difficulty>(difficulty);
  o.seed_override = true;
  o.seed = seed;
  return Game::load_level(level.rfind('/', 0) == 0 ? level : root_dir + "/" + level, o);
}

void fly_to_outcome(Game& g, uint64_t seed, PilotKind pilot, double max_seconds) {
  const World& w = g.world();
  TestPilot person(seed);
  InputFrame in;
  std::vector<Command> keys;
  const int64_t limit = seconds_to_ticks(w, max_seconds);
  while (w.outcome == Outcome::Undecided && w.tick < limit) {
    if (pilot == PilotKind::Person) person.act(w, in, keys);
    g.step(in, keys);
  }
}

DuelResult fly_duel(const std::string& root_dir, int difficulty, uint64_t seed, PilotKind pilot, double max_seconds) {
  Game g = load_flight(root_dir, "levels/duel.json", difficulty, seed);
  fly_to_outcome(g, seed, pilot, max_seconds);
  const World& w = g.world();
  DuelResult r;
  r.won = w.outcome == Outcome::Victory;
  r.lost = w.outcome == Outcome::Defeat;
  r.seconds = double(w.outcome == Outcome::Undecided ? w.tick : w.outcome_tick) * w.dt;
  return r;
}

DuelRates duel_rates(const std::string& root_dir, int difficulty, int seeds, PilotKind pilot) {
  DuelRates r;
  std::vector<double> win_s;
  for (int s = 1; s <= seeds; ++s) {
    const DuelResult d = fly_duel(root_dir, difficulty, static_cast<uint64_t>(s), pilot);
    ++r.fights;
    r.wins += d.won;
    r.losses += d.lost;
    if (d.won) win_s.push_back(d.seconds);
  }
  r.win_rate = r.fights ? double(r.wins) / r.fights : 0.0;
  if (!win_s.empty()) {
    std::sort(win_s.begin(), win_s.end());
    const size_t n = win_s.size();
    r.median_win_s = n % 2 ? win_s[n / 2] : 0.5 * (win_s[n / 2 - 1] + win_s[n / 2]);
  }
  return r;
}

}  // namespace arc
