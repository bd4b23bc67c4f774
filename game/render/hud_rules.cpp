// Loading assets/settings/hud.json into HudRules, every key validated with its position.
#include "game/render/hud_rules.h"

#include "core/json.h"

namespace arc {
namespace {

// An optional block: absent, its keys keep their defaults.
std::optional<JsonObject> block(JsonObject& root, const std::string& key) {
  if (!root.has(key)) return std::nullopt;
  return root.require_object(key);
}

}  // namespace

HudRules load_hud_rules(const std::string& path) {
  auto doc = JsonDoc::load_file(path);
  if (!doc->root().is_object()) JsonValue(doc, "", &doc->root()).fail("the HUD settings must be a JSON object");
  JsonObject root(doc, "", &doc->root());
  HudRules r;
  if (auto o = block(root, "own_view")) {
    OwnViewRules& v = r.own_view;
    v.clear_radius = o->number("clear_radius", v.clear_radius, 0.0, 2.0);
    v.clear_fade = o->number("clear_fade", v.clear_fade, 0.0, 2.0);
    v.beam_half_width = o->number("beam_half_width", v.beam_half_width, 0.0001, 1.0);
    v.beam_near_fade = o->number("beam_near_fade", v.beam_near_fade, 0.0, 1000.0);
    v.other_beam_half_width = o->number("other_beam_half_width", v.other_beam_half_width, 0.0001, 1.0);
    o->finish();
  }
  if (auto o = block(root, "radar")) {
    r.radar_min_range = o->number("min_range", r.radar_min_range, 10.0, 1e7);
    r.radar_max_range = o->number("max_range", r.radar_max_range, 10.0, 1e7);
    if (r.radar_max_range < r.radar_min_range)
      o->fail_key("max_range", "'" + o->key_path("max_range") + "' must be at least 'min_range' (" + std::to_string(r.radar_min_range) + ")");
    r.radar_margin = o->number("margin", r.radar_margin, 1.0, 10.0);
    r.radar_threats = int(o->integer("threats", r.radar_threats, 1, 64));
    o->finish();
  }
  r.hit_marker_seconds = root.number("hit_marker_seconds", r.hit_marker_seconds, 0.0, 10.0);
  r.damage_seconds = root.number("damage_seconds", r.damage_seconds, 0.0, 60.0);
  if (auto o = block(root, "kill_feed")) {
    r.kill_feed_seconds = o->number("seconds", r.kill_feed_seconds, 0.0, 600.0);
    r.kill_feed_lines = int(o->integer("lines", r.kill_feed_lines, 0, 20));
    o->finish();
  }
  root.finish();
  return r;
}

}  // namespace arc
