// game/sim/event_defs.cpp — a level's "objectives" and "events": triggers and actions read and
// checked, every name they hold resolved to an index, each mistake reported at its position.
#include "game/sim/event_defs.h"

#include <algorithm>
#include <string>
#include <vector>

#include "game/sim/def_parsing.h"
#include "game/sim/defs.h"

namespace arc {
namespace defs_internal {
namespace {

constexpr size_t kMaxObjectives = 32;
constexpr size_t kMaxEvents = 256;
constexpr size_t kMaxActions = 32;
constexpr size_t kMaxWaypoints = 64;
constexpr size_t kMaxText = 240;
constexpr size_t kMaxId = 40;

// The level's ships in World order: its "ships", then each wave's.
std::vector<const ShipSpawnDef*> world_ships(const LevelDef& L) {
  std::vector<const ShipSpawnDef*> out;
  for (const ShipSpawnDef& s : L.ships) out.push_back(&s);
  for (const WaveDef& w : L.waves)
    for (const ShipSpawnDef& s : w.ships) out.push_back(&s);
  return out;
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::vector<std::string> q;
  for (const std::string& n : names) {
    std::string one = "\"";
    one.append(n).append("\"");
    q.push_back(std::move(one));
  }
  return q.empty() ? "(none)" : join_allowed(q);
}

std::string text_of(const JsonValue& v, size_t longest) {
  const std::string s = v.string();
  if (s.empty() || s.size() > longest)
    v.fail("'" + v.name() + "' must be a text of 1 to " + std::to_string(longest) + " characters, got " +
           std::to_string(s.size()));
  return s;
}

std::string id_of(const JsonValue& v) {
  const std::string s = text_of(v, kMaxId);
  const bool ok = std::all_of(s.begin(), s.end(), [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; });
  if (!ok) {
    std::string message = "'";
    message.append(v.name()).append("' must be an id of a-z, 0-9 and _, got \"").append(s).append("\"");
    v.fail(message);
  }
  return s;
}

// "file:line:col: 'key.path'", for messages the app gives about the value.
std::string where_key(const JsonValue& v) {
  std::string out = v.where();
  out.append(": '").append(v.name()).append("'");
  return out;
}

struct Names {
  const LevelDef& L;
  std::vector<const ShipSpawnDef*> ships;
  std::vector<std::string> objectives, events;

  size_t ship(const JsonValue& v) const {
    const std::string name = v.string();
    for (size_t i = 0; i < ships.size(); ++i)
      if (ships[i]->name == name) return i;
    std::vector<std::string> all;
    for (const ShipSpawnDef* s : ships) all.push_back(s->name);
    v.fail("no ship of this level is named \"" + name + "\"; ships: " + quoted_list(all));
  }
  std::vector<size_t> group(const JsonValue& v) const {
    const std::string name = v.string();
    std::vector<size_t> out;
    std::vector<std::string> all;
    for (size_t i = 0; i < ships.size(); ++i) {
      if (ships[i]->group == name) out.push_back(i);
      if (!ships[i]->group.empty() && std::find(all.begin(), all.end(), ships[i]->group) == all.end())
        all.push_back(ships[i]->group);
    }
    if (out.empty()) v.fail("no ship of this level is in group \"" + name + "\"; groups: " + quoted_list(all));
    return out;
  }
  // "ship": NAME or "group": NAME, exactly one of them.
  std::vector<size_t> subject(JsonObject& o) const {
    const bool one = o.has("ship"), many = o.has("group");
    if (one == many) o.fail("give exactly one of 'ship' (a ship's name) or 'group' (a group's name)");
    if (one) return {ship(o.require("ship"))};
    return group(o.require("group"));
  }
  size_t index(const JsonValue& v, const std::vector<std::string>& ids, const char* what) const {
    const std::string id = v.string();
    const auto it = std::find(ids.begin(), ids.end(), id);
    if (it == ids.end()) v.fail("no " + std::string(what) + " has id \"" + id + "\"; ids: " + quoted_list(ids));
    return size_t(it - ids.begin());
  }
  // The parts of ship `i`'s class named like `v` (a turret's or a subsystem's "name").
  std::vector<size_t> parts(const JsonValue& v, size_t i) const {
    const std::string name = v.string();
    const auto it = L.classes.find(ships[i]->ship_class);
    std::vector<size_t> out;
    std::vector<std::string> all;
    if (it != L.classes.end()) {
      const ShipClassDef& c = *it->second;
      for (size_t k = 0; k < c.part_count(); ++k) {
        const std::string& part = k < c.turrets.size() ? c.turrets[k].name : c.subsystems[k - c.turrets.size()].name;
        if (part == name) out.push_back(k);
        if (std::find(all.begin(), all.end(), part) == all.end()) all.push_back(part);
      }
    }
    if (out.empty())
      v.fail("ship \"" + ships[i]->name + "\" (class '" + ships[i]->ship_class + "') has no turret or subsystem named \"" +
             name + "\"; parts: " + quoted_list(all));
    return out;
  }
  bool team_exists(const std::string& team) const {
    for (const ShipSpawnDef* s : ships)
      if (s->team == team) return true;
    return false;
  }
  std::string team(const JsonValue& v) const {
    const std::string t = v.string();
    if (!team_exists(t)) v.fail("'" + v.name() + "' names no team of this level's ships: \"" + t + "\"");
    return t;
  }
};

ObjectiveStatus status_of(const JsonValue& v, bool pending_allowed) {
  const std::string s = pending_allowed ? v.choice({"pending", "done", "failed"}) : v.choice({"done", "failed"});
  return s == "done" ? ObjectiveStatus::Done : s == "failed" ? ObjectiveStatus::Failed : ObjectiveStatus::Pending;
}

// One case per trigger type, each reading exactly its own keys.
TriggerDef parse_trigger(JsonObject o, const Names& n, size_t self) {
  TriggerDef t;
  const std::string type = o.require("type").choice(
      {"time", "destroyed", "hull_below", "area_entered", "objective", "event", "team_below",
       "subsystem_destroyed"});
  if (type == "time") {
    t.kind = TriggerKind::Time;
    t.seconds = o.require_number("seconds", 0.0, 36000.0);
  } else if (type == "destroyed") {
    t.kind = TriggerKind::Destroyed;
    t.ships = n.subject(o);
  } else if (type == "hull_below") {
    t.kind = TriggerKind::HullBelow;
    t.ships = n.subject(o);
    t.fraction = o.require_number("fraction", 0.0, 1.0);
  } else if (type == "area_entered") {
    t.kind = TriggerKind::AreaEntered;
    t.ships = n.subject(o);
    t.center = o.require("center").vec3(-kSpace, kSpace);
    t.radius = o.require_number("radius", 1.0, 1.0e7);
  } else if (type == "objective") {
    t.kind = TriggerKind::Objective;
    t.index = n.index(o.require("id"), n.objectives, "objective");
    t.status = status_of(o.require("state"), false);
  } else if (type == "event") {
    t.kind = TriggerKind::EventFired;
    JsonValue id = o.require("id");
    t.index = n.index(id, n.events, "event");
    if (t.index == self) id.fail("an event cannot wait for itself; name another event's id");
  } else if (type == "subsystem_destroyed") {
    t.kind = TriggerKind::PartDestroyed;
    t.ships = {n.ship(o.require("ship"))};
    t.parts = n.parts(o.require("subsystem"), t.ships[0]);
  } else {
    t.kind = TriggerKind::TeamBelow;
    t.team = n.team(o.require("team"));
    t.count = static_cast<int>(o.require("count").integer(1, int64_t(kMaxLevelShips)));
  }
  o.finish();
  return t;
}

void parse_order(JsonObject& o, const Names& n, ActionDef& a) {
  const std::string order = o.require("order").choice({"engage", "attack", "route", "hold"});
  a.order = order == "engage" ? OrderKind::Engage : order == "attack" ? OrderKind::Attack
            : order == "route" ? OrderKind::Route : OrderKind::Hold;
  if (a.order == OrderKind::Attack) a.target = n.ship(o.require("target"));
  else if (o.has("target")) o.fail_key("target", "'target' is only for the \"attack\" order");
  if (a.order != OrderKind::Route) {
    for (const char* k : {"waypoints", "loop", "speed"})
      if (o.has(k)) o.fail_key(k, "'" + std::string(k) + "' is only for the \"route\" order");
    return;
  }
  o.require("waypoints");
  a.waypoints = points(o, "waypoints", kSpace, kMaxWaypoints);
  if (a.waypoints.empty()) o.fail_key("waypoints", "a route needs at least one waypoint [x, y, z]");
  a.loop = o.boolean("loop", false);
  a.speed = o.number("speed", 1.0, 0.05, 1.0);
}

// One case per action type, each reading exactly its own keys.
ActionDef parse_action(JsonObject o, const Names& n) {
  ActionDef a;
  const std::string type =
      o.require("type").choice({"spawn", "message", "radio", "objective", "order", "team", "end", "cue"});
  if (type == "spawn") {
    a.kind = ActionKind::Spawn;
    a.ships = n.subject(o);
    for (size_t i : a.ships)
      if (!n.ships[i]->inactive)
        o.fail_key(o.has("ship") ? "ship" : "group", "ship \"" + n.ships[i]->name +
                                                         "\" is in the fight from the start; only ships with "
                                                         "\"inactive\": true can be spawned");
    if (auto at = o.get("at")) a.has_at = true, a.at = at->vec3(-kSpace, kSpace);
    a.announce = o.boolean("announce", false);
  } else if (type == "message") {
    a.kind = ActionKind::Message;
    a.text = text_of(o.require("text"), kMaxText);
  } else if (type == "radio") {
    a.kind = ActionKind::Radio;
    a.speaker = text_of(o.require("speaker"), kMaxId);
    a.text = text_of(o.require("text"), kMaxText);
    if (auto voice = o.get("voice")) {
      a.voice = id_of(*voice);
      a.where = where_key(*voice);
    }
  } else if (type == "objective") {
    a.kind = ActionKind::Objective;
    a.objective = n.index(o.require("id"), n.objectives, "objective");
    a.status = status_of(o.require("state"), true);
  } else if (type == "order") {
    a.kind = ActionKind::Order;
    a.ships = n.subject(o);
    parse_order(o, n, a);
  } else if (type == "team") {
    a.kind = ActionKind::Team;
    a.ships = n.subject(o);
    a.team = n.team(o.require("team"));
  } else if (type == "end") {
    a.kind = ActionKind::End;
    a.victory = o.require("verdict").choice({"victory", "defeat"}) == "victory";
  } else {
    a.kind = ActionKind::Cue;
    JsonValue name = o.require("name");
    a.cue = id_of(name);
    a.where = where_key(name);
  }
  o.finish();
  return a;
}

void parse_objectives(JsonObject& r, LevelDef& L, Names& n) {
  r.check_list_length("objectives", kMaxObjectives);
  for (JsonObject o : r.objects("objectives")) {
    ObjectiveDef d;
    JsonValue id = o.require("id");
    d.id = id_of(id);
    if (std::count(n.objectives.begin(), n.objectives.end(), d.id)) id.fail("objective id \"" + d.id + "\" is used twice");
    d.text = text_of(o.require("text"), 80);
    const std::string kind = o.choice("kind", "primary", {"primary", "secondary", "hidden"});
    d.kind = kind == "primary" ? ObjectiveKind::Primary : kind == "secondary" ? ObjectiveKind::Secondary
                                                                             : ObjectiveKind::Hidden;
    o.finish();
    n.objectives.push_back(d.id);
    L.events.objectives.push_back(std::move(d));
  }
}

}  // namespace

// "objectives": [ { "id", "text", "kind" } ], "events": [ { "id", "when", "delay", "do": [ ... ] } ].
void parse_events(JsonObject& r, LevelDef& L) {
  Names n{L, world_ships(L), {}, {}};
  parse_objectives(r, L, n);
  r.check_list_length("events", kMaxEvents);
  std::vector<JsonObject> entries = r.objects("events");
  for (JsonObject& e : entries) {  // every id first: a trigger may wait for a later event
    JsonValue id = e.require("id");
    const std::string s = id_of(id);
    if (std::count(n.events.begin(), n.events.end(), s)) id.fail("event id \"" + s + "\" is used twice");
    n.events.push_back(s);
  }
  for (size_t i = 0; i < entries.size(); ++i) {
    JsonObject& e = entries[i];
    EventDef d;
    d.id = n.events[i];
    d.when = parse_trigger(e.require_object("when"), n, i);
    d.delay = e.number("delay", 0.0, 0.0, 36000.0);
    e.check_list_length("do", kMaxActions);
    JsonValue list = e.require("do");
    if (!list.is_array() || list.array().empty())
      list.fail("'" + list.name() + "' must list at least one action: spawn, message, radio, objective, order, team, end or cue");
    for (JsonObject a : e.objects("do")) d.actions.push_back(parse_action(a, n));
    e.finish();
    L.events.events.push_back(std::move(d));
  }
  if (L.win == WinKind::Objectives) {
    const bool any = std::any_of(L.events.objectives.begin(), L.events.objectives.end(),
                                 [](const ObjectiveDef& o) { return o.kind == ObjectiveKind::Primary; });
    if (!any) r.require_object("win").fail_key("type", "'objectives' needs at least one primary objective in \"objectives\"");
  }
}

bool spawned_by_event(const LevelDef& L, size_t ship) {
  for (const EventDef& e : L.events.events)
    for (const ActionDef& a : e.actions)
      if (a.kind == ActionKind::Spawn && std::count(a.ships.begin(), a.ships.end(), ship)) return true;
  return false;
}

}  // namespace defs_internal
}  // namespace arc
