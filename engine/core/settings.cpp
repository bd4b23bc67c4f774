#include "core/settings.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/json.h"

namespace arc {
namespace {

std::string num_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string allowed_text(const SettingDef& d) {
  switch (d.kind) {
    case SettingDef::Kind::Number: return "a number in [" + num_text(d.min) + ", " + num_text(d.max) + "]";
    case SettingDef::Kind::Integer:
      return "an integer in [" + num_text(d.min) + ", " + num_text(d.max) + "]";
    case SettingDef::Kind::Flag: return "true or false (or on/off, 1/0)";
    case SettingDef::Kind::Choice: {
      std::vector<std::string> q;
      for (auto& c : d.choices) q.push_back(c);
      return "one of " + join_allowed(q);
    }
  }
  return "";
}

}  // namespace

void Settings::add(SettingDef def) {
  if (find_mut(def.key)) throw std::logic_error("setting '" + def.key + "' is defined twice");
  defs_.push_back(std::move(def));
}

void Settings::define_number(const std::string& key, double def, double min, double max, const std::string& doc) {
  add({key, SettingDef::Kind::Number, min, max, {}, num_text(def), doc});
}
void Settings::define_integer(const std::string& key, int64_t def, int64_t min, int64_t max,
                              const std::string& doc) {
  add({key, SettingDef::Kind::Integer, double(min), double(max), {}, std::to_string(def), doc});
}
void Settings::define_choice(const std::string& key, const std::string& def, std::vector<std::string> choices,
                             const std::string& doc) {
  add({key, SettingDef::Kind::Choice, 0, 0, std::move(choices), def, doc});
}
void Settings::define_flag(const std::string& key, bool def, const std::string& doc) {
  add({key, SettingDef::Kind::Flag, 0, 0, {}, def ? "true" : "false", doc});
}

const SettingDef& Settings::find(const std::string& key) const {
  for (auto& d : defs_)
    if (d.key == key) return d;
  throw InputError("internal: unknown setting '" + key + "'");
}

SettingDef* Settings::find_mut(const std::string& key) {
  for (auto& d : defs_)
    if (d.key == key) return &d;
  return nullptr;
}

void Settings::set(const std::string& key, const std::string& value, const std::string& where) {
  set(key, value, where, "setting '" + key + "'");
}

void Settings::set(const std::string& key, const std::string& value, const std::string& where, const std::string& what) {
  SettingDef* d = find_mut(key);
  if (!d) {
    std::vector<std::string> keys;
    for (auto& e : defs_) keys.push_back(e.key);
    throw InputError(where + ": unknown setting '" + key + "'; known: " + join_allowed(keys));
  }
  auto bad = [&]() {
    throw InputError(where + ": " + what + " must be " + allowed_text(*d) + ", got '" + value + "'");
  };
  switch (d->kind) {
    case SettingDef::Kind::Number: {
      char* end = nullptr;
      double v = std::strtod(value.c_str(), &end);
      if (value.empty() || *end || !std::isfinite(v) || v < d->min || v > d->max) bad();
      d->value = num_text(v);
      break;
    }
    case SettingDef::Kind::Integer: {
      // A whole number written with a fraction of zero ("50000.0", "5e4", as JSON writers put
      // it) is that integer; a non-zero fraction is refused.
      char* end = nullptr;
      const double v = std::strtod(value.c_str(), &end);
      const bool decimal = value.find_first_not_of("0123456789+-.eE") == std::string::npos;
      if (value.empty() || *end || !decimal || !std::isfinite(v) || std::floor(v) != v || v < d->min || v > d->max)
        bad();
      d->value = std::to_string(static_cast<long long>(v));
      break;
    }
    case SettingDef::Kind::Flag:
      if (value == "true" || value == "1" || value == "on") d->value = "true";
      else if (value == "false" || value == "0" || value == "off") d->value = "false";
      else bad();
      break;
    case SettingDef::Kind::Choice: {
      bool ok = false;
      for (auto& c : d->choices) ok = ok || c == value;
      if (!ok) bad();
      d->value = value;
      break;
    }
  }
}

void Settings::set_from_text(const std::string& assignment, const std::string& where) {
  auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(where + ": expected key=value, got '" + assignment + "'");
  set(assignment.substr(0, eq), assignment.substr(eq + 1), where);
}

void Settings::apply_preset_file(const std::string& path, const std::string& preset) {
  apply_preset_doc(JsonDoc::load_file(path), preset);
}

void Settings::apply_preset_text(const std::string& text, const std::string& path, const std::string& preset) {
  apply_preset_doc(JsonDoc::parse(text, path), preset);
}

void Settings::apply_preset_doc(const std::shared_ptr<const JsonDoc>& doc, const std::string& preset) {
  const std::string& path = doc->path();
  JsonObject root = doc->root().is_object() ? JsonObject(doc, "", &doc->root())
                                            : (JsonValue(doc, "", &doc->root()).object());
  JsonObject presets = root.require_object("presets");
  root.allow({"doc"});
  root.finish();
  auto p = presets.get(preset);
  if (!p) {
    std::vector<std::string> names;
    for (auto it = presets.raw().begin(); it != presets.raw().end(); ++it) names.push_back(it.key());
    throw InputError("--quality: unknown preset '" + preset + "' in " + path + "; allowed: " + join_allowed(names));
  }
  JsonObject obj = p->object();
  for (auto it = obj.raw().begin(); it != obj.raw().end(); ++it) {
    auto v = *obj.get(it.key());
    std::string text;
    if (v.raw().is_string()) text = v.raw().get<std::string>();
    else if (v.raw().is_boolean()) text = v.raw().get<bool>() ? "true" : "false";
    else if (v.raw().is_number()) text = v.raw().dump();
    else v.fail("'" + v.name() + "' must be a string, number or boolean");
    set(it.key(), text, doc->where(obj.pointer() + "/" + json_pointer_escape(it.key())), "'" + v.name() + "'");
  }
}

static std::vector<std::string> preset_names_of(const std::shared_ptr<const JsonDoc>& doc) {
  JsonObject root = JsonValue(doc, "", &doc->root()).object();
  JsonObject presets = root.require_object("presets");
  std::vector<std::string> names;
  for (auto it = presets.raw().begin(); it != presets.raw().end(); ++it) names.push_back(it.key());
  return names;
}

std::vector<std::string> Settings::preset_names(const std::string& path) { return preset_names_of(JsonDoc::load_file(path)); }

std::vector<std::string> Settings::preset_names_text(const std::string& text, const std::string& path) {
  return preset_names_of(JsonDoc::parse(text, path));
}

double Settings::number(const std::string& key) const { return std::strtod(find(key).value.c_str(), nullptr); }
int64_t Settings::integer(const std::string& key) const { return std::strtoll(find(key).value.c_str(), nullptr, 10); }
const std::string& Settings::choice(const std::string& key) const { return find(key).value; }
bool Settings::flag(const std::string& key) const { return find(key).value == "true"; }

std::string Settings::describe() const {
  std::string out;
  for (auto& d : defs_) out += "  " + d.key + " = " + d.value + "  (" + allowed_text(d) + ")  " + d.doc + "\n";
  return out;
}

}  // namespace arc
