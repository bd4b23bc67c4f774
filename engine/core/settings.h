// core/settings.h — every speed-against-accuracy trade is a named runtime setting.
//
// Settings are typed (number, integer, choice, flag), each with a default, an allowed range
// and a one-line doc. Presets (low / medium / high / reference) come from
// assets/settings/quality.json; `--quality NAME` applies one and `--set key=value` overrides
// single keys. "reference" is the most accurate and the one other presets are measured against.
//
//   Settings s = Settings::defaults();
//   s.apply_preset_file("assets/settings/quality.json", "high");
//   s.set_from_text("render.sorting=full", "--set");
//   std::string m = s.choice("render.soft_edges");
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
  // All settings the game knows, at their documented defaults.
  static Settings defaults();

  void define_number(const std::string& key, double def, double min, double max, const std::string& doc);
  void define_integer(const std::string& key, int64_t def, int64_t min, int64_t max, const std::string& doc);
  void define_choice(const std::string& key, const std::string& def, std::vector<std::string> choices,
                     const std::string& doc);
  void define_flag(const std::string& key, bool def, const std::string& doc);

  // Sets one key from text; `where` prefixes the error ("--set", "quality.json:4:9").
  void set(const std::string& key, const std::string& value, const std::string& where);
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
  void apply_preset_doc(const std::shared_ptr<const JsonDoc>& doc, const std::string& preset);
  std::vector<SettingDef> defs_;
};

}  // namespace arc
