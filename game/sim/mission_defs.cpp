// game/sim/mission_defs.cpp — a level's "mission" block: how the menu lists it and its briefing.
#include <string>

#include "game/sim/def_parsing.h"
#include "game/sim/defs.h"

namespace arc {
namespace defs_internal {

// "mission": { "title", "briefing", "objective", "order", "category" }.
void parse_mission(JsonObject& r, LevelDef& L) {
  auto m = r.get("mission");
  if (!m) return;
  JsonObject o = m->object();
  MissionDef& d = L.mission;
  d.present = true;
  auto text = [&](const char* key, size_t longest) {
    JsonValue v = o.require(key);
    std::string s = v.string();
    if (s.empty() || s.size() > longest)
      v.fail("'" + v.name() + "' must be a text of 1 to " + std::to_string(longest) + " characters, got " +
             std::to_string(s.size()));
    return s;
  };
  d.title = text("title", 40);
  d.briefing = text("briefing", 600);
  d.objective = text("objective", 120);
  JsonValue order = o.require("order");
  d.order = static_cast<int>(order.integer(1, 1000));
  d.order_where = order.where();
  const std::string c = o.choice("category", "mission", {"mission", "effects", "demo"});
  d.category = c == "mission"   ? MissionCategory::Mission
               : c == "effects" ? MissionCategory::Effects
                                : MissionCategory::Demo;
  o.finish();
}

}  // namespace defs_internal
}  // namespace arc
