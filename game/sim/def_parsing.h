// game/sim/def_parsing.h — what the definition loaders share (internal to game/sim).
//
// Value limits, point lists and orientations read alike by ship_class_defs.cpp and
// level_defs.cpp, and the mission block reader (mission_defs.cpp) the level loader calls.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/input_limits.h"
#include "core/json.h"
#include "game/sim/defs.h"

namespace arc::defs_internal {

constexpr double kHuge = 1.0e6;
constexpr double kSpace = 1.0e12;  // positions: world space is big but bounded (doubles stay exact to 0.1 mm)

inline std::vector<glm::dvec3> points(JsonObject& o, const std::string& key, double limit) {
  std::vector<glm::dvec3> out;
  o.check_list_length(key, kMaxShipPoints);
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

// The optional "mission" block of a level (game/sim/mission_defs.cpp).
void parse_mission(JsonObject& r, LevelDef& L);
// The optional "training" block (game/sim/training_defs.cpp), read after the ships it names,
// and the checks across it and the rest of the level.
void parse_training(JsonObject& r, LevelDef& L);
void check_training(JsonObject& r, const LevelDef& L);

}  // namespace arc::defs_internal
