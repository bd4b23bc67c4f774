// game/sim/training.cpp — the training steps: begin a step (its ships arrive, its drone fires),
// gather its condition tick by tick, advance when it holds.
#include "game/sim/training.h"

#include <algorithm>
#include <cmath>

#include "game/sim/geometry.h"
#include "game/sim/level_start.h"
#include "game/sim/world.h"

namespace arc {
namespace {

// A drone flies straight this long after it arrives, a steady first target, before it circles.
constexpr double kDroneStraightSeconds = 12.0;

Ship* ship_named(World& w, const std::string& name) {
  for (Ship& s : w.ships)
    if (s.name == name) return &s;
  return nullptr;
}

// A spawned ship's place in the level is in the player's frame at its arrival: ahead of the
// player wherever the lessons before have taken them.
void arrive(World& w, Ship& s) {
  if (!dormant(s)) return;
  if (w.player && w.ship(w.player).alive) {
    const Ship& p = w.ship(w.player);
    const ShipSpawnDef& d = w.level.ships[s.id.index()];
    s.position = p.position + p.orientation * d.position;
    s.orientation = p.orientation * orientation_from_degrees(d.orientation_deg);
    s.velocity = p.orientation * d.velocity;
  }
  s.ai_state.mode_until = w.tick + seconds_to_ticks(w, kDroneStraightSeconds);
  arrive_ship(w, s);
}

void begin_step(World& w) {
  TrainingProgress& t = *w.training;
  t.step_tick = w.tick;
  t.progress = 0;
  t.missile_hits_before = w.player ? w.ship(w.player).stats.missiles_hit : 0;
  if (t.step >= int32_t(w.level.training.steps.size())) return;
  const TrainingStepDef& d = w.level.training.steps[size_t(t.step)];
  for (const std::string& name : d.spawn)
    if (Ship* s = ship_named(w, name)) arrive(w, *s);
  // The drone takes the player as its target, fires once and forgets it (ai.cpp, drive_drone).
  if (!d.fire_at_player.empty() && w.player)
    if (Ship* s = ship_named(w, d.fire_at_player); s && s->alive) s->target = w.player;
}

// The angle between the player's nose at the previous tick and now, in degrees.
double turned_this_tick(const Ship& p) {
  const double c = glm::dot(forward_of(p.prev_orientation), forward_of(p.orientation));
  return std::acos(std::clamp(c, -1.0, 1.0)) / kDeg;
}

bool met(World& w, const TrainingStepDef& d, const std::vector<Command>& commands) {
  TrainingProgress& t = *w.training;
  const Ship* player = w.player ? &w.ship(w.player) : nullptr;
  const bool flying = player && player->alive;
  switch (d.until) {
    case TrainingCondition::TurnedDegrees:
      if (flying) t.progress += turned_this_tick(*player);
      return t.progress >= d.value;
    case TrainingCondition::SpeedAbove: return flying && safe_len(player->velocity) > d.value;
    case TrainingCondition::AfterburnerSeconds:
      if (flying && player->afterburner_on) t.progress += w.dt;
      return t.progress >= d.value - 1e-9;
    case TrainingCondition::TargetSelected:
      return flying && player->target && (d.ship.empty() || w.ship(player->target).name == d.ship);
    case TrainingCondition::ShipDestroyed: {
      const Ship* s = ship_named(w, d.ship);
      return s && !s->alive && s->death_tick >= 0;
    }
    case TrainingCondition::MissileHit: return player && player->stats.missiles_hit > t.missile_hits_before;
    case TrainingCondition::CommandIssued:
      for (Command c : commands)
        if (std::find(d.commands.begin(), d.commands.end(), c) != d.commands.end()) return flying;
      return false;
    case TrainingCondition::WaitSeconds: return double(w.tick - t.step_tick) * w.dt >= d.value - 1e-9;
  }
  return false;
}

}  // namespace

void start_training(World& w) {
  if (w.level.training.steps.empty()) return;
  w.training.emplace();
  begin_step(w);
}

void update_training(World& w, const std::vector<Command>& commands) {
  if (!w.training || training_complete(w)) return;
  const TrainingStepDef& d = w.level.training.steps[size_t(w.training->step)];
  if (!met(w, d, commands)) return;
  ++w.training->step;
  begin_step(w);
}

bool training_complete(const World& w) {
  return w.training && w.training->step >= int32_t(w.level.training.steps.size());
}

}  // namespace arc
