// game/sim/mission_events.cpp — events: triggers checked, delays waited, actions run; the
// objectives' states; ships flying the orders events give; the one spawn of waiting ships.
#include "game/sim/mission_events.h"

#include <algorithm>
#include <string>

#include "game/sim/ai.h"
#include "game/sim/capital.h"
#include "game/sim/geometry.h"
#include "game/sim/level_start.h"
#include "game/sim/wing.h"

namespace arc {
namespace {

bool destroyed(const Ship& s) { return !s.alive && s.death_tick >= 0; }

int alive_in_team(const World& w, const std::string& team) {
  int n = 0;
  for (const Ship& s : w.ships) n += s.alive && w.team_name(s.team) == team ? 1 : 0;
  return n;
}

TeamId team_named(const World& w, const std::string& name) {
  for (size_t i = 0; i < w.team_names.size(); ++i)
    if (w.team_names[i] == name) return TeamId::from_index(i);
  return {};
}

TeamId player_side(const World& w) { return w.player ? w.ship(w.player).team : w.ships.front().team; }

TeamId other_team(const World& w, TeamId side) {
  for (const Ship& s : w.ships)
    if (in_fight(s) && s.team != side) return s.team;
  return {};
}

void end_mission(World& w, bool victory) {
  if (w.outcome != Outcome::Undecided) return;
  const TeamId side = player_side(w);
  w.outcome = !w.player ? Outcome::TeamWon : victory ? Outcome::Victory : Outcome::Defeat;
  w.winner = victory ? side : other_team(w, side);
  w.outcome_tick = w.tick;
}

void set_objective(World& w, size_t index, ObjectiveStatus status) {
  ObjectiveProgress& o = w.mission->objectives[index];
  o.revealed = true;
  // Done and failed are final: of two events that decide one objective, the first wins.
  if (o.status != ObjectiveStatus::Pending || status == ObjectiveStatus::Pending) return;
  o.status = status;
  o.changed_tick = w.tick;
}

void give_order(World& w, const ActionDef& a) {
  for (size_t i : a.ships) {
    ShipOrder o;
    o.kind = a.order;
    if (a.order == OrderKind::Attack) o.target = ShipId::from_index(a.target);
    o.waypoints = a.waypoints;
    o.loop = a.loop;
    o.speed = a.speed;
    w.mission->orders[i] = std::move(o);
    if (a.order == OrderKind::Attack) w.ships[i].ai_state.next_think = w.tick;  // takes the target at once
  }
}

void change_team(World& w, const ActionDef& a) {
  const TeamId team = team_named(w, a.team);
  for (size_t i : a.ships) {
    Ship& s = w.ships[i];
    if (s.team == team) continue;
    s.team = team;
    s.target = s.ai_state.target = {};
    s.ai_state.next_think = w.tick;
    w.mission->team_changes.push_back({s.id, team});
  }
}

// One case per action kind.
void run_action(World& w, const ActionDef& a) {
  switch (a.kind) {
    case ActionKind::Spawn: {
      spawn_ships(w, a.ships, a.has_at ? &a.at : nullptr);
      if (a.announce) announce_reinforcements(w, a.ships);
      break;
    }
    case ActionKind::Message: post_message(w, MessageKind::Friendly, a.text); break;
    case ActionKind::Radio: post_message(w, MessageKind::Radio, a.speaker + ": " + a.text); break;
    case ActionKind::Objective: set_objective(w, a.objective, a.status); break;
    case ActionKind::Order: give_order(w, a); break;
    case ActionKind::Team: change_team(w, a); break;
    case ActionKind::End: end_mission(w, a.victory); break;
    case ActionKind::Cue:
      w.mission->cue = a.cue;
      w.mission->cue_tick = w.tick;
      break;
  }
}

// Within this distance of a waypoint a ship turns for the next: its size plus a few seconds' flight.
double arrive_radius(const Ship& s) { return std::max(60.0, 4.0 * s.cls->collision_radius); }

}  // namespace

MissionProgress new_mission_progress(const World& w) {
  MissionProgress m;
  m.events.resize(w.level.events.events.size());
  m.objectives.resize(w.level.events.objectives.size());
  for (size_t i = 0; i < m.objectives.size(); ++i)
    m.objectives[i].revealed = w.level.events.objectives[i].kind != ObjectiveKind::Hidden;
  m.orders.resize(w.ships.size());
  return m;
}

void start_mission(World& w) {
  if (!w.level.events.empty()) w.mission.emplace(new_mission_progress(w));
}

bool trigger_holds(const World& w, const TriggerDef& t) {
  switch (t.kind) {
    case TriggerKind::Time: return w.tick >= seconds_to_ticks(w, t.seconds);
    case TriggerKind::Destroyed:
      return std::all_of(t.ships.begin(), t.ships.end(), [&](size_t i) { return destroyed(w.ships[i]); });
    case TriggerKind::HullBelow:
      return std::any_of(t.ships.begin(), t.ships.end(), [&](size_t i) {
        const Ship& s = w.ships[i];
        return !dormant(s) && s.hull < t.fraction * s.cls->hull;
      });
    case TriggerKind::AreaEntered:
      return std::any_of(t.ships.begin(), t.ships.end(), [&](size_t i) {
        const Ship& s = w.ships[i];
        return s.alive && safe_len(s.position - t.center) <= t.radius;
      });
    case TriggerKind::Objective: return w.mission && w.mission->objectives[t.index].status == t.status;
    case TriggerKind::EventFired: return w.mission && w.mission->events[t.index].fired_tick >= 0;
    case TriggerKind::TeamBelow: return alive_in_team(w, t.team) < t.count;
    case TriggerKind::PartDestroyed: {
      const Ship& s = w.ships[t.ships[0]];
      return !dormant(s) && std::all_of(t.parts.begin(), t.parts.end(), [&](size_t i) { return !part_alive(s, i); });
    }
  }
  return false;
}

void spawn_ships(World& w, const std::vector<size_t>& ships, const glm::dvec3* at) {
  if (ships.empty()) return;
  const glm::dvec3 shift = at ? *at - w.ships[ships.front()].position : glm::dvec3(0.0);
  for (size_t i : ships) {
    Ship& s = w.ships[i];
    if (!dormant(s)) continue;
    s.position += shift;
    arrive_ship(w, s);
  }
}

void announce_reinforcements(World& w, const std::vector<size_t>& ships) {
  if (ships.empty()) return;
  const Ship& lead = w.ships[ships.front()];
  const bool friendly = w.player && w.ship(w.player).team == lead.team;
  const size_t n = ships.size();
  post_message(w, friendly ? MessageKind::Friendly : MessageKind::Hostile,
               std::string("Reinforcements: ") + std::to_string(n) + (friendly ? " friendly" : " hostile") +
                   (n == 1 ? " ship" : " ships"));
}

void update_events(World& w) {
  if (!w.mission || w.outcome != Outcome::Undecided) return;
  const std::vector<EventDef>& defs = w.level.events.events;
  for (size_t i = 0; i < defs.size(); ++i) {
    EventProgress& e = w.mission->events[i];
    if (e.fired_tick >= 0) continue;
    if (e.armed_tick < 0 && trigger_holds(w, defs[i].when)) e.armed_tick = w.tick;
    if (e.armed_tick < 0 || w.tick < e.armed_tick + seconds_to_ticks(w, defs[i].delay)) continue;
    e.fired_tick = w.tick;
    for (const ActionDef& a : defs[i].actions) run_action(w, a);
  }
}

const ShipOrder* order_of(const World& w, ShipId ship) {
  if (!w.mission || ship.index() >= w.mission->orders.size()) return nullptr;
  return &w.mission->orders[ship.index()];
}

ShipId ordered_target(const World& w, ShipId ship) {
  const ShipOrder* o = order_of(w, ship);
  if (!o || o->kind != OrderKind::Attack || !o->target || !w.ship(o->target).alive) return {};
  return o->target;
}

bool fly_order(World& w, Ship& s) {
  if (!w.mission) return false;
  ShipOrder& o = w.mission->orders[s.id.index()];
  if (o.kind == OrderKind::Route && size_t(o.next) < o.waypoints.size() &&
      safe_len(o.waypoints[size_t(o.next)] - s.position) < arrive_radius(s)) {
    ++o.next;
    if (size_t(o.next) >= o.waypoints.size()) {
      if (o.loop) o.next = 0;
      else o.kind = OrderKind::Hold;
    }
  }
  InputFrame c;
  if (o.kind == OrderKind::Hold) {
    c.roll = quantise_axis(-0.3 * s.angular_velocity.z);
  } else if (o.kind == OrderKind::Route) {
    const glm::dvec3 dir = safe_norm(o.waypoints[size_t(o.next)] - s.position, forward_of(s.orientation));
    steer_toward(s, dir, 1.0, c);
    c.throttle = quantise_axis(o.speed);
  } else {
    return false;
  }
  s.controls = c;
  return true;
}

bool primary_objectives_done(const World& w) {
  if (!w.mission) return false;
  bool any = false;
  for (size_t i = 0; i < w.mission->objectives.size(); ++i) {
    if (w.level.events.objectives[i].kind != ObjectiveKind::Primary) continue;
    any = true;
    if (w.mission->objectives[i].status != ObjectiveStatus::Done) return false;
  }
  return any;
}

bool primary_objective_failed(const World& w) {
  if (!w.mission) return false;
  for (size_t i = 0; i < w.mission->objectives.size(); ++i)
    if (w.level.events.objectives[i].kind == ObjectiveKind::Primary &&
        w.mission->objectives[i].status == ObjectiveStatus::Failed)
      return true;
  return false;
}

}  // namespace arc
