// The player's settings.json and progress.json: parse with positions, write atomically, keep a
// .bak of a bad file before replacing it with defaults.
#include "game/app/user_settings.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/input_file.h"
#include "core/file_writer.h"
#include "core/json.h"
#include "core/settings.h"
#include "game/app/all_settings.h"
#include "game/app/key_remap.h"
#include "platform/platform.h"

namespace arc {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSettingsFile = "settings.json";
constexpr const char* kProgressFile = "progress.json";
constexpr int kFormat = 1;
constexpr int kProgressFormat = 2;  // 2: objectives in each result

JsonObject root_object(const std::shared_ptr<const JsonDoc>& doc) { return JsonValue(doc, "", &doc->root()).object(); }

void check_format(JsonObject& r) {
  JsonValue f = r.require("format");
  if (f.integer(0, 1000000) != kFormat)
    f.fail("'" + f.name() + "' must be " + std::to_string(kFormat) + " (the format this version writes), got " + f.raw().dump());
}

std::vector<std::string> action_ids() {
  std::vector<std::string> ids;
  for (const RemapAction& a : remap_actions()) ids.push_back(a.id);
  return ids;
}

void parse_keys(JsonObject& r, UserSettings& s) {
  auto kv = r.get("keys");
  if (!kv) return;
  JsonObject k = kv->object();
  const std::vector<std::string> ids = action_ids();
  for (const auto& [id, value] : kv->raw().items()) {
    bool known = false;
    for (const std::string& a : ids) known = known || a == id;
    if (!known) k.fail_key(id, "unknown action '" + id + "'; allowed: " + join_allowed(ids));
    JsonValue v = k.require(id);
    const std::string name = v.string();
    const int code = name == "NONE" ? -1 : code_of_label(name);
    const bool pad_action = id.rfind("pad_", 0) == 0;
    if (pad_action && name != "NONE" && code < kPadButtonBase)
      v.fail("'" + v.name() + "' must be a gamepad button (PAD_A, PAD_X, PAD_LEFT_BUMPER, ...) or NONE, got \"" + name +
             "\"");
    if (!pad_action && name != "NONE" && (code < 0 || code >= kPadButtonBase))
      v.fail("'" + v.name() + "' must be a key name (A, SPACE, LEFT_SHIFT, MOUSE_LEFT, ...) or NONE, got \"" + name + "\"");
    s.keys[id] = name;
  }
  k.finish();
}

// "render": { "render.sorting": "cluster", ... }: each checked against the setting's range.
void parse_render(JsonObject& r, UserSettings& s) {
  auto rv = r.get("render");
  if (!rv) return;
  JsonObject o = rv->object();
  Settings check = all_settings();
  for (const auto& [key, value] : rv->raw().items()) {
    JsonValue v = o.require(key);
    const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
    check.set(key, text, v.where(), "'" + v.name() + "'");
    s.render[key] = text;
  }
  o.finish();
}

MissionResult parse_result(JsonObject o) {
  MissionResult m;
  m.victory = o.boolean("victory", false);
  m.seconds = o.require_number("seconds", 0.0, 1.0e9);
  m.kills = static_cast<int>(o.integer("kills", 0, 0, 1000000));
  m.damage_dealt = o.number("damage_dealt", 0.0, 0.0, 1.0e12);
  m.damage_taken = o.number("damage_taken", 0.0, 0.0, 1.0e12);
  m.beam_accuracy = o.number("beam_accuracy", 0.0, 0.0, 1.0);
  m.missile_accuracy = o.number("missile_accuracy", 0.0, 0.0, 1.0);
  m.primary_total = static_cast<int>(o.integer("primary_total", 0, 0, 1000));
  m.primary_done = static_cast<int>(o.integer("primary_done", 0, 0, m.primary_total));
  m.bonus_total = static_cast<int>(o.integer("bonus_total", 0, 0, 1000));
  m.bonus_done = static_cast<int>(o.integer("bonus_done", 0, 0, m.bonus_total));
  o.finish();
  return m;
}

template <class T, class Parse, class Write>
T load_or_default(const std::string& path, Parse parse, Write write, std::string& message) {
  if (!input_path_exists(path)) return T{};
  try {
    return parse(read_text_file(path));
  } catch (const InputError& e) {
    const std::string m = replace_bad_file(path, write(T{}), e.what());
    message += (message.empty() ? "" : "\n") + m;
    return T{};
  }
}

void write_into(const std::string& dir, const char* name, const std::string& text) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir + ": cannot make the folder (" + ec.message() + ")");
  write_file_atomic((fs::path(dir) / name).string(), text);
}

}  // namespace

std::string replace_bad_file(const std::string& path, const std::string& defaults, const std::string& error) {
  std::error_code ec;
  fs::copy_file(path, path + ".bak", fs::copy_options::overwrite_existing, ec);
  if (ec) return error + " (could not keep a copy: " + ec.message() + "; the file was left as it is, defaults used)";
  try {
    write_file_atomic(path, defaults);
  } catch (const InputError& e) {
    return error + " (kept a copy as " + path + ".bak; " + e.what() + ")";
  }
  return error + "; kept it as " + path + ".bak and started from defaults";
}

bool better_result(const MissionResult& a, const MissionResult& than) {
  if (a.victory != than.victory) return a.victory;
  if (a.victory && a.bonus_done != than.bonus_done) return a.bonus_done > than.bonus_done;
  if (a.victory) return a.seconds < than.seconds;
  return a.damage_dealt > than.damage_dealt;
}

std::string progress_key(const std::string& level_path, const std::string& difficulty) {
  return fs::path(level_path).stem().string() + "/" + difficulty;
}

bool record_result(Progress& p, const std::string& key, const MissionResult& r) {
  auto it = p.best.find(key);
  if (it != p.best.end() && !better_result(r, it->second)) return false;
  p.best[key] = r;
  return true;
}

std::string user_config_dir() {
  if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x) return (fs::path(x) / "arcfire").string();
  if (const char* h = std::getenv("HOME"); h && *h) return (fs::path(h) / ".config" / "arcfire").string();
  return ".arcfire-config";
}

UserSettings parse_settings(const std::string& text, const std::string& path,
                            const std::vector<std::string>& quality_presets) {
  auto doc = JsonDoc::parse(text, path);
  JsonObject r = root_object(doc);
  check_format(r);
  UserSettings s;
  if (auto q = r.get("quality")) {
    s.quality = q->string();
    bool known = quality_presets.empty() || s.quality == kDefaultQuality;
    for (const std::string& p : quality_presets) known = known || p == s.quality;
    if (!known) q->fail("'" + q->name() + "' must be one of " + join_allowed(quality_presets) + ", got \"" + s.quality + "\"");
  }
  s.mouse_sensitivity = r.number("mouse_sensitivity", s.mouse_sensitivity, 0.001, 10.0);
  s.invert_y = r.boolean("invert_y", s.invert_y);
  s.pad_deadzone = r.number("gamepad_deadzone", s.pad_deadzone, 0.0, 0.9);
  s.fov = r.number("fov", s.fov, 30.0, 120.0);
  s.fullscreen = r.boolean("fullscreen", s.fullscreen);
  s.vsync = r.boolean("vsync", s.vsync);
  s.developer_panel = r.boolean("developer_panel", s.developer_panel);
  parse_keys(r, s);
  parse_render(r, s);
  if (auto m = r.get("mods")) {
    const std::vector<JsonValue> list = m->array();
    if (list.size() > kMaxUserMods) m->fail("'" + m->name() + "' lists at most " + std::to_string(kMaxUserMods) + " folders");
    for (const JsonValue& v : list) s.mods.push_back(v.string());
  }
  if (auto n = r.get("net_name")) {
    s.net_name = n->string();
    bool ok = !s.net_name.empty() && s.net_name.size() <= 24;
    for (char c : s.net_name) ok = ok && c >= 0x20 && c <= 0x7e;
    if (!ok) n->fail("'" + n->name() + "' must be 1 to 24 printable ASCII characters, got \"" + s.net_name + "\"");
  }
  if (auto h = r.get("recent_hosts")) {
    const std::vector<JsonValue> list = h->array();
    if (list.size() > 5) h->fail("'" + h->name() + "' lists at most 5 addresses");
    for (const JsonValue& v : list) s.recent_hosts.push_back(v.string());
  }
  r.finish();
  return s;
}

Progress parse_progress(const std::string& text, const std::string& path) {
  auto doc = JsonDoc::parse(text, path);
  JsonObject r = root_object(doc);
  JsonValue f = r.require("format");
  const int64_t format = f.integer(0, 1000000);
  if (format != 1 && format != kProgressFormat)
    f.fail("'" + f.name() + "' must be 1 or " + std::to_string(kProgressFormat) + " (the formats this version reads), got " +
           f.raw().dump());
  Progress p;
  if (auto bv = r.get("best")) {
    JsonObject b = bv->object();
    for (const auto& [key, value] : bv->raw().items()) p.best[key] = parse_result(b.require(key).object());
    b.finish();
  }
  r.finish();
  return p;
}

std::vector<std::string> user_mods(const std::string& dir) {
  const std::string path = dir + "/settings.json";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return {};
  try {
    return parse_settings(read_text_file(path), path, {}).mods;
  } catch (const InputError&) {
    return {};  // load_user_files() reports it and keeps the file as .bak
  }
}

std::string settings_json(const UserSettings& s) {
  nlohmann::ordered_json j;
  j["format"] = kFormat;
  j["quality"] = s.quality;
  j["mouse_sensitivity"] = s.mouse_sensitivity;
  j["invert_y"] = s.invert_y;
  j["gamepad_deadzone"] = s.pad_deadzone;
  j["fov"] = s.fov;
  j["fullscreen"] = s.fullscreen;
  j["vsync"] = s.vsync;
  j["developer_panel"] = s.developer_panel;
  j["keys"] = nlohmann::ordered_json::object();
  for (const auto& [id, key] : s.keys) j["keys"][id] = key;
  j["render"] = nlohmann::ordered_json::object();
  for (const auto& [key, value] : s.render) j["render"][key] = value;
  if (!s.mods.empty()) j["mods"] = s.mods;
  if (s.net_name != "Pilot") j["net_name"] = s.net_name;
  if (!s.recent_hosts.empty()) j["recent_hosts"] = s.recent_hosts;
  return j.dump(2) + "\n";
}

std::string progress_json(const Progress& p) {
  nlohmann::ordered_json j;
  j["format"] = kProgressFormat;
  j["best"] = nlohmann::ordered_json::object();
  for (const auto& [key, m] : p.best)
    j["best"][key] = {{"victory", m.victory},           {"seconds", m.seconds},
                      {"kills", m.kills},               {"damage_dealt", m.damage_dealt},
                      {"damage_taken", m.damage_taken}, {"beam_accuracy", m.beam_accuracy},
                      {"missile_accuracy", m.missile_accuracy}, {"primary_done", m.primary_done},
                      {"primary_total", m.primary_total}, {"bonus_done", m.bonus_done},
                      {"bonus_total", m.bonus_total}};
  return j.dump(2) + "\n";
}

UserFiles load_user_files(const std::string& dir, const std::string& quality_file) {
  UserFiles f;
  f.dir = dir;
  std::vector<std::string> presets;
  try {
    presets = Settings::preset_names(quality_file);
  } catch (const InputError&) {
    presets.clear();  // the quality file's own error is reported where it is loaded
  }
  const std::string settings_path = (fs::path(dir) / kSettingsFile).string();
  const std::string progress_path = (fs::path(dir) / kProgressFile).string();
  std::error_code exists_error;
  f.settings_found = fs::exists(settings_path, exists_error);
  f.settings = load_or_default<UserSettings>(
      settings_path, [&](const std::string& t) { return parse_settings(t, settings_path, presets); }, settings_json,
      f.message);
  f.progress = load_or_default<Progress>(
      progress_path, [&](const std::string& t) { return parse_progress(t, progress_path); }, progress_json, f.message);
  return f;
}

void save_settings(const std::string& dir, const UserSettings& s) { write_into(dir, kSettingsFile, settings_json(s)); }
void save_progress(const std::string& dir, const Progress& p) { write_into(dir, kProgressFile, progress_json(p)); }

Settings user_quality_settings(const UserSettings& us, const std::string& quality_file) {
  Settings s = all_settings();
  if (us.quality != kDefaultQuality) s.apply_preset_file(quality_file, us.quality);
  for (const auto& [key, value] : us.render) s.set(key, value, "settings.json render");
  return s;
}

void apply_user_settings(const UserSettings& s, Bindings& b) {
  b.mouse_sensitivity = s.mouse_sensitivity;
  b.mouse_invert_y = s.invert_y;
  b.pad_invert_y = s.invert_y;
  b.pad_deadzone = s.pad_deadzone;
  apply_key_overrides(s.keys, b);
}

}  // namespace arc
