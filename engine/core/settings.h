// core/settings.h — every speed-against-accuracy trade is a named runtime setting.
//
// Settings are typed (number, integer, choice, flag), each with a default, an allowed range
// and a one-line doc. Core keeps the mechanism, not the list: each module registers its own
// keys (gfx/render_settings.h, particles/particle_settings.h, game/sim/sim_settings.h,
// audio/audio_settings.h), as Quake III's renderer registers its cvars, and
// game/app/all_settings.h assembles them. Presets (low / medium / high / reference) come from
// assets/settings/quality.json; `--quality NAME` applies one and `--set key=value` overrides
// single keys. "reference" is the most accurate and the one other presets are measured against.
//
// Example, compiled as SettingsExample.DefineSetAndRead in tests/unit/core/test_settings.cpp:
//   Settings s;
//   s.define_choice("render.sorting", "full", {"off", "cluster", "full"}, "particle order; cheap");
//   s.set_from_text("render.sorting=cluster", "--set");
//   std::string m = s.choice("render.sorting");
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace arc {

class JsonDoc;

struct SettingDef {
  enum class Kind { Number, Integer, Choice, Flag };
  std::string key;
  Kind kind = Kind::Number;
  double min = 0, max = 0;
  std::vector<std::string> choices;
  std::string value;  // current value as text, always valid
  std::string doc;
};

class Settings {
 public:
  // Each key is defined once, by the module that reads it; a second definition of a key is a
  // programming error (std::logic_error).
  void define_number(const std::string& key, double def, double min, double max, const std::string& doc);
  void define_integer(const std::string& key, int64_t def, int64_t min, int64_t max, const std::string& doc);
  void define_choice(const std::string& key, const std::string& def, std::vector<std::string> choices,
                     const std::string& doc);
  void define_flag(const std::string& key, bool def, const std::string& doc);

  // Sets one key from text; `where` prefixes the error ("--set", "quality.json:4:9").
  void set(const std::string& key, const std::string& value, const std::string& where);
  // The same, the value named `what` in the message (a file's key path: "'presets.low.sim.substeps'").
  void set(const std::string& key, const std::string& value, const std::string& where, const std::string& what);
  // "key=value" form of --set.
  void set_from_text(const std::string& assignment, const std::string& where);
  // Applies a named preset from a quality file; unknown preset or bad values → InputError.
  void apply_preset_file(const std::string& path, const std::string& preset);
  // The same from text, named `path` in messages (fuzz targets, tests).
  void apply_preset_text(const std::string& text, const std::string& path, const std::string& preset);
  static std::vector<std::string> preset_names(const std::string& path);
  static std::vector<std::string> preset_names_text(const std::string& text, const std::string& path);

  double number(const std::string& key) const;
  int64_t integer(const std::string& key) const;
  const std::string& choice(const std::string& key) const;
  bool flag(const std::string& key) const;
  const std::vector<SettingDef>& all() const { return defs_; }
  // One line per setting: "key = value  (allowed)  doc".
  std::string describe() const;

 private:
  const SettingDef& find(const std::string& key) const;
  SettingDef* find_mut(const std::string& key);
  void add(SettingDef def);
  void apply_preset_doc(const std::shared_ptr<const JsonDoc>& doc, const std::string& preset);
  std::vector<SettingDef> defs_;
};

}  // namespace arc
