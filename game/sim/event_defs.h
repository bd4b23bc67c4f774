// game/sim/event_defs.h — a level's "objectives" and "events" as plain definitions (event_defs.cpp).
//
// An event waits for its trigger, then for its delay, then runs its actions once, inside the
// tick (game/sim/mission_events.h). Names in the file are resolved to indices at load: ships to
// their index in LevelDef::ships (= World::ships), objectives and events to theirs.
#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include <glm/vec3.hpp>

namespace arc {

enum class ObjectiveKind : uint8_t { Primary = 0, Secondary = 1, Hidden = 2 };
enum class ObjectiveStatus : uint8_t { Pending = 0, Done = 1, Failed = 2 };
constexpr ObjectiveStatus last_enumerator(ObjectiveStatus) { return ObjectiveStatus::Failed; }

struct ObjectiveDef {
  std::string id;
  std::string text;
  ObjectiveKind kind = ObjectiveKind::Primary;
};

enum class TriggerKind : uint8_t {
  Time,          // `seconds` of mission time have passed
  Destroyed,     // every ship of `ships` (one ship, or a group) has been destroyed
  HullBelow,     // any ship of `ships` has less than `fraction` of its hull left (alive or not)
  AreaEntered,   // any live ship of `ships` is within `radius` of `center`
  Objective,     // objective `index` has `status` (done or failed)
  EventFired,    // event `index` has run its actions
  TeamBelow,     // team `team` has fewer than `count` ships alive
  PartDestroyed, // every part of ship `ships[0]` named `part` (a turret or subsystem) destroyed
};

struct TriggerDef {
  TriggerKind kind = TriggerKind::Time;
  double seconds = 0;
  std::vector<size_t> ships;  // indices into LevelDef::ships
  double fraction = 0;
  glm::dvec3 center{0.0};
  double radius = 0;
  size_t index = 0;  // the objective or event
  ObjectiveStatus status = ObjectiveStatus::Done;
  std::string team;
  int count = 0;
  std::vector<size_t> parts;  // subsystem_destroyed: indices into the ship's parts (capital.h)
};

enum class ActionKind : uint8_t { Spawn, Message, Radio, Objective, Order, Team, End, Cue };
// What an "order" action tells AI-flown ships: fight as they see fit, attack one ship, fly a
// route of waypoints (once, or round and round) ignoring the fight, or hold still.
enum class OrderKind : uint8_t { Engage = 0, Attack = 1, Route = 2, Hold = 3 };
constexpr OrderKind last_enumerator(OrderKind) { return OrderKind::Hold; }

struct ActionDef {
  ActionKind kind = ActionKind::Message;
  std::vector<size_t> ships;  // spawn, order, team: the ship or the group's ships
  bool has_at = false;        // spawn: moved so that its first ship arrives at `at`
  glm::dvec3 at{0.0};
  bool announce = false;      // spawn: post "Reinforcements: N hostile ships", as a wave does
  std::string speaker;        // radio
  std::string text;           // message, radio
  std::string voice;          // radio: a line id of assets/radio/lines.json ("" for none), checked by the app
  std::string where;          // radio's voice, cue: "file:line:col: 'key.path'", for the app's messages
  size_t objective = 0;
  ObjectiveStatus status = ObjectiveStatus::Done;
  OrderKind order = OrderKind::Engage;
  size_t target = 0;          // attack: the ship
  std::vector<glm::dvec3> waypoints;
  bool loop = false;
  double speed = 1.0;         // route: throttle 0..1
  std::string team;
  bool victory = true;        // end
  std::string cue;
};

struct EventDef {
  std::string id;
  TriggerDef when;
  double delay = 0;  // seconds from the trigger holding to the actions
  std::vector<ActionDef> actions;
};

struct EventsDef {
  std::vector<ObjectiveDef> objectives;
  std::vector<EventDef> events;
  bool empty() const { return objectives.empty() && events.empty(); }
};

}  // namespace arc
