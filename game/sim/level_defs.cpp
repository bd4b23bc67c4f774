// game/sim/level_defs.cpp — levels from levels/*.json: rules, ships (loading their classes),
// props, effect spawns, camera and team colours; the mission block is mission_defs.cpp's.
#include <filesystem>
#include <set>

#include <glm/geometric.hpp>

#include "core/data_layers.h"
#include "core/error.h"
#include "core/input_file.h"
#include "game/sim/def_parsing.h"
#include "game/sim/defs.h"
#include "particles/effect_def.h"
#include "particles/effect_library.h"

namespace arc {
using namespace defs_internal;

namespace {

// "team_colors": { "TEAM": [r, g, b], ... } over the defaults for blue and red.
void parse_team_colors(JsonObject& r, LevelDef& L) {
  L.team_colors = {{"blue", {0.22, 0.5, 1.0}}, {"red", {1.0, 0.2, 0.12}}};
  auto table = r.get("team_colors");
  if (!table) return;
  JsonObject o = table->object();
  for (const auto& [team, value] : table->raw().items()) L.team_colors[team] = o.vec3(team, glm::dvec3(0.0), 0.0, 1.0);
  o.finish();
}

void parse_rules(JsonObject& r, LevelDef& L) {
  JsonObject win = r.require_object("win");
  std::string wk = win.choice("type", "destroy_all_hostiles",
                              {"destroy_all_hostiles", "survive_ticks", "last_team_standing", "training_complete", "objectives"});
  L.win = wk == "destroy_all_hostiles" ? WinKind::DestroyAllHostiles
          : wk == "survive_ticks"      ? WinKind::SurviveTicks
          : wk == "training_complete"  ? WinKind::TrainingComplete
          : wk == "objectives"         ? WinKind::Objectives
                                       : WinKind::LastTeamStanding;
  if (L.win == WinKind::SurviveTicks) L.win_ticks = win.require("ticks").integer(1, 100000000);
  win.finish();
  JsonObject lose = r.require_object("lose");
  std::string lk = lose.choice("type", "player_destroyed", {"player_destroyed", "protect", "none"});
  L.lose = lk == "player_destroyed" ? LoseKind::PlayerDestroyed : lk == "protect" ? LoseKind::Protect : LoseKind::None;
  if (L.lose == LoseKind::Protect) L.protect_ship = lose.require_string("ship");
  lose.finish();

  if (auto s = r.get("splash")) {
    JsonObject o = s->object();
    L.splash = o.boolean("enabled", true);
    L.splash_radius = o.number("radius", 60.0, 0.0, 1.0e5);
    L.splash_damage = o.number("damage", 40.0, 0.0, kHuge);
    o.finish();
  }
}

// Loads the class a ship names the first time a ship of the level names it.
void load_class_of(LevelDef& L, const ShipSpawnDef& d, const JsonValue& cls, const std::string& root_dir) {
  if (L.classes.count(d.ship_class)) return;
  if (d.ship_class.empty() || d.ship_class.find_first_of("/\\.") != std::string::npos)
    cls.fail("'" + cls.name() + "' must be a ship class name (a file stem in assets/ships/), got \"" + d.ship_class + "\"");
  std::string file = data_file(root_dir, "assets/ships/" + d.ship_class + ".json");  // a mod's class first
  if (!input_path_exists(file))
    cls.fail("ship class '" + d.ship_class + "' not found: no file " + file);
  L.classes.emplace(d.ship_class, std::make_shared<const ShipClassDef>(load_ship_class(file, d.ship_class, root_dir)));
}

// "wing": a wingman flies on the player's team and is not the player.
void check_wing(JsonObject& r, const LevelDef& L) {
  const ShipSpawnDef* player = nullptr;
  for (const ShipSpawnDef& d : L.ships)
    if (d.player) player = &d;
  std::vector<JsonObject> entries = r.objects("ships");
  for (size_t i = 0; i < L.ships.size() && i < entries.size(); ++i) {
    const ShipSpawnDef& d = L.ships[i];
    if (!d.wing) continue;
    if (d.player) entries[i].fail_key("wing", "the player leads the wing: 'wing' is for the player's wingmen");
    if (!player) entries[i].fail_key("wing", "a wingman needs a player ship to follow ('player': true on one ship)");
    if (d.team != player->team)
      entries[i].fail_key("wing", "a wingman flies on the player's team \"" + player->team + "\", not \"" + d.team + "\"");
    if (d.ai != AiKind::Fighter) entries[i].fail_key("wing", "a wingman needs 'ai': \"fighter\"");
  }
}

void parse_ships(JsonObject& r, LevelDef& L, const std::string& root_dir) {
  std::set<std::string> names;  // a set, so a generated fleet of thousands loads in linear-log time
  bool have_player = false;
  r.check_list_length("ships", kMaxLevelShips);
  for (JsonObject s : r.objects("ships")) {
    ShipSpawnDef d = parse_ship_entry(s, L, root_dir, names);
    if (d.player && have_player) s.fail_key("player", "only one ship may be the player");
    have_player = have_player || d.player;
    L.ships.push_back(std::move(d));
  }
  if (L.ships.empty()) r.fail_key(r.has("ships") ? "ships" : "name", "a level needs at least one ship in 'ships'");
  check_wing(r, L);
}

void parse_props(JsonObject& r, LevelDef& L, const std::string& root_dir) {
  r.check_list_length("props", kMaxLevelProps);
  for (JsonObject p : r.objects("props")) {
    PropDef d;
    d.model = p.require_string("model");
    require_named_file(p.require("model"), d.model, root_dir, "model");
    d.label = p.string("label", "");
    d.position = p.vec3("position", glm::dvec3(0.0), -kSpace, kSpace);
    d.orientation_deg = orientation(p);
    d.scale = p.number("scale", 1.0, 1.0e-3, 1.0e4);
    d.radius = p.number("radius", 0.0, 0.0, 1.0e6);
    p.finish();
    L.props.push_back(std::move(d));
  }
}

bool has_lightning(const EffectLibrary& fx, const std::string& effect) {
  for (const ClusterDef& c : fx.get(fx.id(effect)).clusters)
    if (c.animation == AnimationType::Lightning) return true;
  return false;
}

// "to" and "velocity" of an effect spawn, after its position and repeat_ticks.
void parse_effect_motion(JsonObject& e, EffectSpawnDef& d, const EffectLibrary* fx) {
  if (auto to = e.get("to")) {
    d.has_target = true;
    d.target = to->vec3(-kSpace, kSpace);
    if (e.has("orientation")) e.fail_key("orientation", "give 'orientation' or 'to' (which aims the channel), not both");
    if (!(glm::length(d.target - d.position) > 1.0e-3))
      to->fail("'" + to->name() + "' must lie away from 'position' (at least 1 mm): the channel runs from one to the other");
    if (fx && !has_lightning(*fx, d.effect))
      to->fail("'" + to->name() + "' aims a lightning channel, and effect \"" + d.effect + "\" has no lightning cluster");
  }
  if (auto v = e.get("velocity")) {
    d.velocity = v->vec3(-1.0e5, 1.0e5);
    if (d.repeat_ticks == 0 && d.velocity != glm::dvec3(0.0))
      v->fail("a moving effect needs 'repeat_ticks' above 0 (each spawn restarts at 'position'); allowed: [x, y, z] m/s");
  }
}

void parse_effects(JsonObject& r, LevelDef& L, const EffectLibrary* fx, const std::string& root_dir) {
  r.check_list_length("effects", kMaxLevelEffects);
  for (JsonObject e : r.objects("effects")) {
    EffectSpawnDef d;
    JsonValue name = e.require("effect");
    d.effect = name.string();
    if (fx && !fx->has(d.effect)) {
      // The library holds every file of assets/effects: an effect it lacks is a missing file.
      std::vector<std::string> known = fx->names();
      name.fail("'" + name.name() + "' names effect file " + data_file(root_dir, "assets/effects/" + d.effect + ".json") +
                ": no such file; effects: " + join_allowed(known));
    }
    d.label = e.string("label", "");
    d.position = e.vec3("position", glm::dvec3(0.0), -kSpace, kSpace);
    d.orientation_deg = orientation(e);
    d.scale = e.number("scale", 1.0, 1.0e-3, 1.0e4);
    d.repeat_ticks = static_cast<int>(e.integer("repeat_ticks", 0, 0, 1000000));
    parse_effect_motion(e, d, fx);
    d.has_label_at = e.has("label_at");
    d.label_at = e.vec3("label_at", glm::dvec3(0.0), -kSpace, kSpace);
    e.finish();
    L.effects.push_back(std::move(d));
  }
}

void parse_camera(JsonObject& r, LevelDef& L) {
  if (auto c = r.get("camera")) {
    JsonObject o = c->object();
    L.camera.mode = o.choice("mode", "chase", {"chase", "cockpit", "fixed"});
    L.camera.position = o.vec3("position", L.camera.position, -kSpace, kSpace);
    L.camera.look_at = o.vec3("look_at", L.camera.look_at, -kSpace, kSpace);
    L.camera.fov_deg = o.number("fov", 60.0, 10.0, 150.0);
    o.finish();
  }
}

void check_protected_ship(JsonObject& r, const LevelDef& L) {
  if (L.lose != LoseKind::Protect) return;
  bool found = false;
  for (const ShipSpawnDef& s : L.ships) found = found || s.name == L.protect_ship;
  if (!found) {
    JsonObject lose2 = r.require_object("lose");
    lose2.fail_key("ship", "'" + lose2.key_path("ship") + "' names no ship of this level: \"" + L.protect_ship + "\"");
  }
}

}  // namespace

ShipSpawnDef defs_internal::parse_ship_entry(JsonObject& s, LevelDef& L, const std::string& root_dir,
                                            std::set<std::string>& names) {
  ShipSpawnDef d;
  d.name = s.require_string("name");
  d.has_label = s.has("label");
  d.label = s.string("label", "");
  JsonValue cls = s.require("class");
  d.ship_class = cls.string();
  d.team = s.require_string("team");
  d.player = s.boolean("player", false);
  d.wing = s.boolean("wing", false);
  std::string ai = s.choice("ai", d.player ? "none" : "fighter", {"none", "fighter", "gunner", "drone", "capital"});
  d.ai = ai == "none"      ? AiKind::None
         : ai == "fighter" ? AiKind::Fighter
         : ai == "gunner"  ? AiKind::Gunner
         : ai == "drone"   ? AiKind::Drone
                           : AiKind::Capital;
  d.position = s.vec3("position", glm::dvec3(0.0), -kSpace, kSpace);
  d.orientation_deg = orientation(s);
  d.velocity = s.vec3("velocity", glm::dvec3(0.0), -1.0e5, 1.0e5);
  d.inactive = s.boolean("inactive", false);
  if (auto g = s.get("group")) {
    d.group = g->string();
    if (d.group.empty() || d.group.size() > 40) g->fail("'" + g->name() + "' must be a group name of 1 to 40 characters");
  }
  s.finish();
  if (!names.insert(d.name).second) s.fail_key("name", "ship name '" + d.name + "' is used twice");
  load_class_of(L, d, cls, root_dir);
  return d;
}

LevelDef parse_level_doc(std::shared_ptr<const JsonDoc> doc, const std::string& root_dir, const EffectLibrary* fx) {
  JsonObject r = root_of(doc);
  LevelDef L;
  L.path = doc->path();
  L.name = r.require_string("name");
  L.seed = static_cast<uint64_t>(r.integer("seed", 1, 0, 0xFFFFFFFFll));
  L.tick_rate = static_cast<int>(r.integer("tick_rate", 60, 10, 480));
  std::string diff = r.choice("difficulty", "normal", {"easy", "normal", "hard"});
  L.difficulty = diff == "easy" ? 0 : diff == "normal" ? 1 : 2;
  L.objective = r.require_string("objective");
  parse_rules(r, L);
  parse_ships(r, L, root_dir);
  parse_slots(r, L);
  parse_waves(r, L, root_dir);
  parse_props(r, L, root_dir);
  parse_effects(r, L, fx, root_dir);
  parse_camera(r, L);
  parse_team_colors(r, L);
  parse_mission(r, L);
  parse_loadout_choice(r, L, root_dir);
  parse_training(r, L);
  parse_events(r, L);
  check_training(r, L);
  check_protected_ship(r, L);
  r.finish();
  L.ai = load_ai_difficulties(root_dir);
  return L;
}

LevelDef load_level_def(const std::string& path, const std::string& root_dir, const EffectLibrary* effects) {
  return parse_level_doc(JsonDoc::load_file(path), root_dir, effects);
}

LevelDef parse_level_def(const std::string& text, const std::string& path, const std::string& root_dir,
                         const EffectLibrary* effects) {
  return parse_level_doc(JsonDoc::parse(text, path), root_dir, effects);
}

}  // namespace arc
