// game/sim/training_defs.cpp — a level's "training" block: the steps a training mission walks
// the player through, each with its prompt, its completion condition and what arrives with it.
#include <algorithm>
#include <string>
#include <vector>

#include "game/sim/def_parsing.h"
#include "game/sim/defs.h"

namespace arc {
namespace defs_internal {
namespace {

constexpr size_t kMaxTrainingSteps = 64;
constexpr size_t kMaxPrompt = 200;

struct ConditionName {
  const char* name;
  TrainingCondition condition;
};
constexpr ConditionName kConditions[] = {
    {"turned_degrees", TrainingCondition::TurnedDegrees},
    {"speed_above", TrainingCondition::SpeedAbove},
    {"afterburner_seconds", TrainingCondition::AfterburnerSeconds},
    {"target_selected", TrainingCondition::TargetSelected},
    {"ship_destroyed", TrainingCondition::ShipDestroyed},
    {"missile_hit", TrainingCondition::MissileHit},
    {"command_issued", TrainingCondition::CommandIssued},
    {"wait_seconds", TrainingCondition::WaitSeconds},
};

// The names replay scripts give the player's commands (tests/replays/README.md).
struct CommandName {
  const char* name;
  Command command;
};
constexpr CommandName kCommands[] = {
    {"target_next", Command::TargetNext},       {"target_nearest", Command::TargetNearest},
    {"target_next_hostile", Command::TargetNextHostile}, {"switch_weapon", Command::SwitchWeapon},
    {"camera", Command::CameraToggle},          {"camera_padlock", Command::CameraPadlock},
    {"countermeasure", Command::Countermeasure}, {"order_attack", Command::OrderAttack},
    {"order_cover", Command::OrderCover},       {"order_form_up", Command::OrderFormUp},
    {"order_engage", Command::OrderEngage}, {"target_subsystem", Command::TargetSubsystem},
};

const ShipSpawnDef* find_ship(const LevelDef& L, const std::string& name) {
  for (const ShipSpawnDef& s : L.ships)
    if (s.name == name) return &s;
  return nullptr;
}

// A ship name of the level at `v`'s position, or a positioned error.
std::string ship_name(const LevelDef& L, const JsonValue& v) {
  const std::string name = v.string();
  if (!find_ship(L, name)) {
    std::vector<std::string> names;
    for (const ShipSpawnDef& s : L.ships) names.push_back("\"" + s.name + "\"");
    v.fail("no ship of this level is named \"" + name + "\"; ships: " + join_allowed(names));
  }
  return name;
}

// Placeholders are {action} with a key action's id (letters, digits, '_'); braces pair up.
void check_prompt(const JsonValue& v, const std::string& s) {
  if (s.empty() || s.size() > kMaxPrompt)
    v.fail("'prompt' must be a text of 1 to " + std::to_string(kMaxPrompt) + " characters, got " +
           std::to_string(s.size()));
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '}') v.fail("'prompt' has a '}' without its '{'; a placeholder is {action}, e.g. {target_nearest}");
    if (s[i] != '{') continue;
    const size_t end = s.find('}', i);
    const std::string id = end == std::string::npos ? "" : s.substr(i + 1, end - i - 1);
    const bool ok = !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
    if (!ok) v.fail("'prompt' placeholders are {action} with a key action's id (a-z, 0-9, _), e.g. {target_nearest}");
    i = end;
  }
}

std::vector<Command> parse_commands(JsonObject& o) {
  std::vector<const char*> allowed;
  for (const CommandName& c : kCommands) allowed.push_back(c.name);
  JsonValue list = o.require("commands");
  if (!list.is_array() || list.array().empty())
    list.fail("'commands' must be a list of command names, any of which completes the step: " +
              join_allowed(std::vector<std::string>(allowed.begin(), allowed.end())));
  list.check_list_length(std::size(kCommands));
  std::vector<Command> out;
  for (const JsonValue& v : list.array()) {
    const std::string name = v.choice(allowed);
    for (const CommandName& c : kCommands)
      if (name == c.name) out.push_back(c.command);
  }
  return out;
}

// What the step's condition needs: a value, a ship or commands, and nothing it does not use.
void parse_condition(JsonObject& o, const LevelDef& L, TrainingStepDef& d) {
  std::vector<const char*> names;
  for (const ConditionName& c : kConditions) names.push_back(c.name);
  const std::string until = o.require("until").choice(names);
  for (const ConditionName& c : kConditions)
    if (until == c.name) d.until = c.condition;
  using C = TrainingCondition;
  const bool valued = d.until == C::TurnedDegrees || d.until == C::SpeedAbove || d.until == C::AfterburnerSeconds ||
                      d.until == C::WaitSeconds;
  if (valued) d.value = o.require_number("value", 0.0, kHuge);
  else if (o.has("value")) o.fail_key("value", "'value' is only for turned_degrees, speed_above, afterburner_seconds and wait_seconds");
  if (d.until == C::ShipDestroyed || d.until == C::TargetSelected) {
    if (auto s = o.get("ship")) d.ship = ship_name(L, *s);
    else if (d.until == C::ShipDestroyed) o.require("ship");
  } else if (o.has("ship")) {
    o.fail_key("ship", "'ship' is only for ship_destroyed and target_selected");
  }
  if (d.until == C::CommandIssued) d.commands = parse_commands(o);
  else if (o.has("commands")) o.fail_key("commands", "'commands' is only for command_issued");
}

// "spawn" names inactive ships, each spawned by one step only.
void parse_spawns(JsonObject& o, const LevelDef& L, const std::vector<TrainingStepDef>& before, TrainingStepDef& d) {
  o.check_list_length("spawn", kMaxLevelShips);
  auto list = o.get("spawn");
  if (!list) return;
  if (!list->is_array()) list->fail("'spawn' must be a list of ship names (ships with \"inactive\": true)");
  for (const JsonValue& v : list->array()) {
    const std::string name = ship_name(L, v);
    if (!find_ship(L, name)->inactive)
      v.fail("ship \"" + name + "\" is in the level from the start; only ships with \"inactive\": true can be spawned");
    bool twice = std::count(d.spawn.begin(), d.spawn.end(), name) > 0;
    for (const TrainingStepDef& s : before) twice = twice || std::count(s.spawn.begin(), s.spawn.end(), name) > 0;
    if (twice) v.fail("ship \"" + name + "\" is spawned by an earlier step already");
    d.spawn.push_back(name);
  }
}

}  // namespace

// "training": { "steps": [ { "prompt", "until", "value" | "ship" | "commands", "spawn", "fire_at_player" } ] }.
void parse_training(JsonObject& r, LevelDef& L) {
  auto t = r.get("training");
  if (!t) return;
  JsonObject o = t->object();
  o.require("steps");
  o.check_list_length("steps", kMaxTrainingSteps);
  for (JsonObject s : o.objects("steps")) {
    TrainingStepDef d;
    JsonValue prompt = s.require("prompt");
    d.prompt = prompt.string();
    check_prompt(prompt, d.prompt);
    parse_condition(s, L, d);
    parse_spawns(s, L, L.training.steps, d);
    if (auto f = s.get("fire_at_player")) {
      d.fire_at_player = ship_name(L, *f);
      const ShipSpawnDef* ship = find_ship(L, d.fire_at_player);
      if (ship->ai != AiKind::Drone || !L.classes.at(ship->ship_class)->missile.present)
        f->fail("'fire_at_player' names a drone (\"ai\": \"drone\") whose class carries missiles");
    }
    s.finish();
    L.training.steps.push_back(std::move(d));
  }
  if (L.training.steps.empty()) o.fail_key("steps", "'steps' must list at least one step");
  o.finish();
}

// Every inactive ship arrives at some step or event, and a training_complete win needs the steps.
void check_training(JsonObject& r, const LevelDef& L) {
  if (L.win == WinKind::TrainingComplete && L.training.steps.empty()) {
    JsonObject win = r.require_object("win");
    win.fail_key("type", "'training_complete' needs a \"training\" block with its steps");
  }
  for (const ShipSpawnDef& s : L.ships) {
    if (!s.inactive) continue;
    bool spawned = false;
    for (const TrainingStepDef& t : L.training.steps)
      spawned = spawned || std::count(t.spawn.begin(), t.spawn.end(), s.name) > 0;
    spawned = spawned || spawned_by_event(L, size_t(&s - L.ships.data()));
    if (!spawned)
      r.fail_key(L.training.steps.empty() ? (L.events.events.empty() ? "ships" : "events") : "training",
                 "ship \"" + s.name + "\" is inactive and no training step spawns it (\"spawn\": [\"" + s.name +
                     "\"]), nor does an event's spawn action");
    if (s.player) r.fail_key("ships", "the player's ship \"" + s.name + "\" cannot be inactive");
  }
}

}  // namespace defs_internal
}  // namespace arc
