// game/sim/mission_state.h — the simulated state of a level's events and objectives (World::mission).
//
// Included by game/sim/world.h after its hash words and reference tags; everything here is in
// the state pass, under World's word 15, and only in levels with "objectives" or "events".
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace arc {

// An event: the tick its trigger first held (−1: not yet) and the tick it ran its actions (−1: not yet).
struct EventProgress {
  int64_t armed_tick = -1;
  int64_t fired_tick = -1;
};

template <fields::MaybeConst<EventProgress> E, class V>
void visit_fields(E& e, V&& v) {
  v("armed_tick", e.armed_tick, fields::saved, state_hash<0>);
  v("fired_tick", e.fired_tick, fields::saved, state_hash<1>);
}

// An objective's state; a hidden one shows on the HUD once an action has touched it.
struct ObjectiveProgress {
  ObjectiveStatus status = ObjectiveStatus::Pending;
  bool revealed = false;
  int64_t changed_tick = -1;
};

template <fields::MaybeConst<ObjectiveProgress> O, class V>
void visit_fields(O& o, V&& v) {
  v("status", o.status, fields::saved, state_hash<0>);
  v("revealed", o.revealed, fields::saved, state_hash<1>);
  v("changed_tick", o.changed_tick, fields::saved, state_hash<2>);
}

// The order an event gave one ship (Engage: none, the AI fights as it sees fit). A route's
// waypoints are copied here, so a snapshot carries the ship's whole order.
struct ShipOrder {
  OrderKind kind = OrderKind::Engage;
  ShipId target;
  std::vector<glm::dvec3> waypoints;
  int32_t next = 0;  // the waypoint flown to
  bool loop = false;
  double speed = 1.0;
};

template <fields::MaybeConst<ShipOrder> O, class V>
void visit_fields(O& o, V&& v) {
  v("kind", o.kind, fields::saved, state_hash<0>);
  v("target", o.target, ship_ref, state_hash<1>);
  v("waypoints", o.waypoints, fields::saved, state_hash<2>);
  v("next", o.next, fields::saved, state_hash<3>);
  v("loop", o.loop, fields::saved, state_hash<4>);
  v("speed", o.speed, fields::saved, state_hash<5>);
}

// A ship an event moved to another team (Ship::team itself is the level's and unhashed).
struct TeamChange {
  ShipId ship;
  TeamId team;
};

template <fields::MaybeConst<TeamChange> T, class V>
void visit_fields(T& t, V&& v) {
  v("ship", t.ship, ship_ref, state_hash<0>);
  v("team", t.team, team_ref, state_hash<1>);
}

struct MissionProgress {
  std::vector<EventProgress> events;          // one per EventsDef::events entry
  std::vector<ObjectiveProgress> objectives;  // one per EventsDef::objectives entry
  std::vector<ShipOrder> orders;              // one per ship
  std::vector<TeamChange> team_changes;       // in the order they happened
  std::string cue;                            // the last cue played ("" for none) and its tick
  int64_t cue_tick = -1;
};

template <fields::MaybeConst<MissionProgress> M, class V>
void visit_fields(M& m, V&& v) {
  v("events", m.events, fields::checked, state_hash<0>);
  v("objectives", m.objectives, fields::checked, state_hash<1>);
  v("orders", m.orders, fields::checked, state_hash<2>);
  v("team_changes", m.team_changes, fields::saved, state_hash<3>);
  v("cue", m.cue, fields::saved, state_hash<4>);
  v("cue_tick", m.cue_tick, fields::saved, state_hash<5>);
}

}  // namespace arc
