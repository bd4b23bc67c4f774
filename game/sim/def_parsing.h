// game/sim/def_parsing.h — what the definition loaders share (internal to game/sim).
//
// Value limits, point lists and orientations read alike by ship_class_defs.cpp and
// level_defs.cpp, and the mission block reader (mission_defs.cpp) the level loader calls.
#pragma once
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/input_limits.h"
#include "core/json.h"
#include "game/sim/defs.h"

namespace arc::defs_internal {

constexpr double kHuge = 1.0e6;
// Positions: each coordinate within ±2^30 m (1 073 741 824), the range the game is tested in end
// to end (levels/gallery_far.json sits 1e9 out on every axis) with room for a scene built
// around 1e9; doubles step 0.12 µm there, so motion and particles stay exact.
constexpr double kSpace = 1073741824.0;

inline std::vector<glm::dvec3> points(JsonObject& o, const std::string& key, double limit,
                                      size_t max_count = kMaxShipPoints) {
  std::vector<glm::dvec3> out;
  o.check_list_length(key, max_count);
  auto v = o.get(key);
  if (!v) return out;
  for (const JsonValue& p : v->array()) out.push_back(p.vec3(-limit, limit));
  return out;
}

inline JsonObject root_of(const std::shared_ptr<const JsonDoc>& doc) {
  JsonObject r(doc, "", &doc->root());
  return r;
}

inline glm::dvec3 orientation(JsonObject& o) { return o.vec3("orientation", glm::dvec3(0.0), -3600.0, 3600.0); }

// A ship class's optional "turrets", "subsystems" and "breakup" blocks (capital_defs.cpp).
void parse_capital(JsonObject& r, ShipClassDef& c);
// A level's optional "loadout" block (loadout.cpp), after its ships are loaded.
void parse_loadout_choice(JsonObject& r, LevelDef& L, const std::string& root_dir);
// The optional "mission" block of a level (game/sim/mission_defs.cpp).
void parse_mission(JsonObject& r, LevelDef& L);
// A file a data file names (`what`: "model"), found as given when absolute, else through the data
// layers of `root_dir`: InputError at the value naming the file looked for unless it is a
// regular file. Checked in every mode, so a run without rendering refuses what a window would.
void require_named_file(const JsonValue& v, const std::string& named, const std::string& root_dir, const char* what);

// One entry of "ships" (or of a wave's "ships"), its class loaded into L; `names` holds every
// ship name already in L, and the entry's is refused if taken, else added (level_defs.cpp).
ShipSpawnDef parse_ship_entry(JsonObject& s, LevelDef& L, const std::string& root_dir, std::set<std::string>& names);
// The optional "slots" list, after "ships" (game/sim/slot_defs.cpp).
void parse_slots(JsonObject& r, LevelDef& L);
// The optional "waves" list, after "ships" (game/sim/wave_defs.cpp).
void parse_waves(JsonObject& r, LevelDef& L, const std::string& root_dir);
// The optional "training" block (game/sim/training_defs.cpp), read after the ships it names,
// and the checks across it and the rest of the level.
void parse_training(JsonObject& r, LevelDef& L);
void check_training(JsonObject& r, const LevelDef& L);
// The optional "objectives" and "events" (game/sim/event_defs.cpp), after the ships, waves and
// training they name; and whether an event's spawn action brings the ship of world index `ship`.
void parse_events(JsonObject& r, LevelDef& L);
bool spawned_by_event(const LevelDef& L, size_t ship);
// A time or team_below trigger, the one an event's "when" holds, for a wave (wave_defs.cpp).
TriggerDef wave_trigger(const WaveDef& d);

}  // namespace arc::defs_internal
