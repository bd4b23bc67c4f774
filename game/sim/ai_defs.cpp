// game/sim/ai_defs.cpp — the AI pilots' difficulty table from assets/settings/ai.json, validated
// like every other data file (path:line:col errors); the numbers live in the file, not here.
#include <filesystem>

#include "core/data_layers.h"
#include "core/json.h"
#include "game/sim/defs.h"
#include "game/sim/geometry.h"

namespace arc {

AiDifficultyTable load_ai_difficulties(const std::string& root_dir) {
  auto doc = JsonDoc::load_file(data_file(root_dir, "assets/settings/ai.json"));
  JsonObject root(doc, "", &doc->root());
  AiDifficultyTable table;
  const char* names[] = {"easy", "normal", "hard", "allies"};
  for (size_t i = 0; i < 4; ++i) {
    if (i == 3 && !root.has("allies")) break;
    JsonObject o = root.require_object(names[i]);
    AiDifficultyDef& d = i < 3 ? table[i] : table.allies.emplace();
    d.aim_error = o.require_number("aim_error_deg", 0.0, 45.0) * kDeg;
    d.reaction_s = o.require_number("reaction_s", 0.0, 10.0);
    d.aggression = o.require_number("aggression", 0.0, 1.0);
    d.stick_limit = o.require_number("stick_limit", 0.05, 1.0);
    d.jink = o.require_number("jink", 0.0, 1.0);
    d.tail_limit_s = o.require_number("tail_limit_s", 0.0, 600.0);
    d.tail_break_s = o.require_number("tail_break_s", 0.0, 600.0);
    if (d.tail_limit_s > 0 && d.tail_break_s <= 0)
      o.fail_key("tail_break_s", "'" + o.key_path("tail_break_s") + "' must be above zero when 'tail_limit_s' is (a break-off needs a length)");
    o.finish();
  }
  root.finish();
  return table;
}

}  // namespace arc
