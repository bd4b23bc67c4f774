// game/sim/wave_defs.cpp — a level's "waves": reinforcements that enter the fight after a time
// or when a team runs low, each with ships written like the level's "ships". A wave is sugar
// for an event: its trigger is an event trigger and its ships arrive by the events' spawn.
#include <set>
#include <string>

#include "game/sim/def_parsing.h"
#include "game/sim/defs.h"

namespace arc {
namespace defs_internal {

namespace {

constexpr size_t kMaxWaves = 32;

bool team_in_level(const LevelDef& L, const std::string& team) {
  for (const ShipSpawnDef& s : L.ships)
    if (s.team == team) return true;
  return false;
}

// "after_seconds": N, or "when_team_below": { "team": T, "count": N } — exactly one of them.
void parse_trigger(JsonObject& o, const LevelDef& L, WaveDef& d) {
  const bool timed = o.has("after_seconds"), losses = o.has("when_team_below");
  if (timed == losses)
    o.fail("a wave needs exactly one trigger: 'after_seconds' (0..36000) or 'when_team_below' "
           "({ \"team\": NAME, \"count\": N })");
  if (timed) {
    d.after_seconds = o.require_number("after_seconds", 0.0, 36000.0);
    d.when = wave_trigger(d);
    return;
  }
  JsonObject t = o.require_object("when_team_below");
  JsonValue team = t.require("team");
  d.team = team.string();
  if (!team_in_level(L, d.team)) team.fail("'team' names no team of the level's 'ships': \"" + d.team + "\"");
  d.below = static_cast<int>(t.require("count").integer(1, int64_t(kMaxLevelShips)));
  t.finish();
  d.when = wave_trigger(d);
}

}  // namespace

TriggerDef wave_trigger(const WaveDef& d) {
  TriggerDef t;
  if (d.after_seconds >= 0) {
    t.kind = TriggerKind::Time;
    t.seconds = d.after_seconds;
  } else {
    t.kind = TriggerKind::TeamBelow;
    t.team = d.team;
    t.count = d.below;
  }
  return t;
}

void parse_waves(JsonObject& r, LevelDef& L, const std::string& root_dir) {
  r.check_list_length("waves", kMaxWaves);
  size_t total = L.ships.size();
  std::set<std::string> names;
  for (const ShipSpawnDef& d : L.ships) names.insert(d.name);
  for (JsonObject o : r.objects("waves")) {
    WaveDef d;
    parse_trigger(o, L, d);
    o.check_list_length("ships", kMaxLevelShips);
    std::vector<JsonObject> entries = o.objects("ships");
    if (entries.empty()) {
      if (o.has("ships")) o.fail_key("ships", "a wave needs at least one ship in 'ships'");
      o.fail("a wave needs at least one ship in 'ships'");
    }
    for (JsonObject s : entries) {
      if (s.has("player")) s.fail_key("player", "the player starts in 'ships', not in a wave");
      if (s.has("wing")) s.fail_key("wing", "wingmen start in 'ships', not in a wave");
      if (++total > kMaxLevelShips)
        s.fail("too many ships: a level and its waves hold at most " + std::to_string(kMaxLevelShips));
      d.ships.push_back(parse_ship_entry(s, L, root_dir, names));
    }
    o.finish();
    L.waves.push_back(std::move(d));
  }
}

}  // namespace defs_internal
}  // namespace arc
