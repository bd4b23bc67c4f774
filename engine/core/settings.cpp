#include "core/settings.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

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

Settings Settings::defaults() {
  Settings s;
  // Rendering. Each doc ends with the setting's cost class; docs/performance.md has the figures.
  s.define_choice("render.soft_edges", "effect",
                  {"effect", "off", "linear", "contrast", "average_density", "density_extent"},
                  "soft-edge method: 'effect' uses each effect's own, others override all effects; cheap");
  s.define_choice("render.sorting", "full", {"off", "cluster", "full"},
                  "back-to-front order of non-additive particles: none, by cluster, or per particle;"
                  " cheap (CPU time, full the most)");
  s.define_choice("render.depth_mode", "reversed", {"reversed", "standard"},
                  "reversed-Z float depth (needs clip control) or standard depth; no cost");
  s.define_flag("render.infinite_far", true, "infinite far plane; no cost");
  s.define_choice("render.texture_filter", "mipmap_nearest", {"nearest", "linear", "mipmap_nearest", "mipmap"},
                  "sprite and model texture filtering: mipmap_nearest is bilinear within one mip level, mipmap"
                  " trilinear (between two levels: twice the texel reads, costly on a software rasteriser)");
  s.define_number("render.scale", 1.0, 0.25, 2.0,
                  "render resolution relative to the window; costs fill rate with its square");
  s.define_number("render.particle_size_clamp", 0.5, 0.01, 4.0,
                  "largest particle size on screen, as a fraction of screen height; larger costs fill rate up close");
  s.define_number("render.near_fade", 2.0, 0.0, 100.0,
                  "distance in world units over which particles fade out toward the camera; no cost");
  s.define_number("render.contrast_power", 2.0, 0.5, 8.0, "exponent of the contrast soft-edge curve; no cost");
  s.define_choice("render.sky", "baked", {"baked", "exact"},
                  "nebula background: baked once per level into a cube map, or evaluated per pixel every frame;"
                  " exact is costly on a software rasteriser");
  s.define_integer("render.sky_resolution", 256, 16, 1024,
                   "texels along each face of the baked nebula cube map; costs memory and level-load time");
  s.define_integer("render.sky_grid", 32, 0, 64,
                   "baked nebula looked up every N pixels and interpolated between (0: at every pixel);"
                   " a finer grid costs fill rate");
  s.define_number("render.overdraw_budget", 3.0, 0.0, 64.0,
                  "screen layers of particle blending per frame before the nearest, largest particles are shrunk,"
                  " faded and dropped (low screen priority first); 0: no budget; caps the particles' fill rate");
  s.define_choice("render.particle_resolution", "auto", {"full", "half", "auto"},
                  "particles blended at the scene's resolution, or at half its width and height and put over it"
                  " (a quarter of the blending, softer particles), or auto: half while they blend more than one"
                  " screen layer, full again under 0.6; half saves fill rate");
  s.define_number("render.overdraw_near", 40.0, 1.0, 1e6,
                  "distance in world units within which the overdraw budget reduces particles at full strength;"
                  " no cost");
  // HDR, bloom and the edge filter are the look of the high and reference presets and of the
  // attract demo; the default keeps the 8-bit scene because a software rasteriser cannot afford
  // them at 60 Hz (docs/performance.md).
  s.define_flag("render.hdr", false,
                "linear-light float scene with a filmic tone curve (on), or 8-bit display colours (off);"
                " costs fill rate, costly on a software rasteriser");
  s.define_number("render.exposure", 1.0, 0.05, 16.0,
                  "scene brightness scale before the tone curve (render.hdr on); no cost");
  s.define_choice("render.bloom", "off", {"off", "low", "high"},
                  "glow around light brighter than white (render.hdr on): none, soft or strong;"
                  " costs fill rate, costly on a software rasteriser");
  s.define_choice("render.antialias", "off", {"off", "fxaa", "msaa2", "msaa4"},
                  "edge anti-aliasing: FXAA filter on the final image, or 2x/4x multisampling of the opaque pass;"
                  " costs fill rate and memory, costly on a software rasteriser");
  // Particles
  s.define_integer("particles.budget", 200000, 1000, 4000000,
                   "largest number of live particles; costs memory, and CPU time with the particles alive");
  s.define_integer("particles.lightning_interval", 0, 0, 60,
                   "re-evaluate lightning every n ticks; 0 keeps each effect's own interval;"
                   " a longer one saves CPU time");
  s.define_number("particles.cull_distance", 20000.0, 100.0, 1e12,
                  "clusters farther than this from the camera are not animated until needed;"
                  " a shorter one saves CPU time");
  // Simulation
  s.define_integer("sim.substeps", 1, 1, 16, "physics sub-steps per tick; each costs CPU time");
  // Audio (engine/audio): never part of the simulation or its hash.
  s.define_number("audio.volume", 0.8, 0.0, 1.0, "master volume; no cost");
  s.define_number("audio.effects_volume", 1.0, 0.0, 1.0,
                  "volume of the game's positional sounds, under the master; no cost");
  s.define_flag("audio.mute", false, "no sound at all (M toggles it in the game); no cost");
  s.define_integer("audio.voices", 32, 4, 128,
                   "sounds playing at once; beyond it the lowest priority (sparks before explosions) fades out;"
                   " cheap (mixing CPU time per voice)");
  return s;
}

void Settings::define_number(const std::string& key, double def, double min, double max, const std::string& doc) {
  defs_.push_back({key, SettingDef::Kind::Number, min, max, {}, num_text(def), doc});
}
void Settings::define_integer(const std::string& key, int64_t def, int64_t min, int64_t max,
                              const std::string& doc) {
  defs_.push_back({key, SettingDef::Kind::Integer, double(min), double(max), {}, std::to_string(def), doc});
}
void Settings::define_choice(const std::string& key, const std::string& def, std::vector<std::string> choices,
                             const std::string& doc) {
  defs_.push_back({key, SettingDef::Kind::Choice, 0, 0, std::move(choices), def, doc});
}
void Settings::define_flag(const std::string& key, bool def, const std::string& doc) {
  defs_.push_back({key, SettingDef::Kind::Flag, 0, 0, {}, def ? "true" : "false", doc});
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
  SettingDef* d = find_mut(key);
  if (!d) {
    std::vector<std::string> keys;
    for (auto& e : defs_) keys.push_back(e.key);
    throw InputError(where + ": unknown setting '" + key + "'; known: " + join_allowed(keys));
  }
  auto bad = [&]() {
    throw InputError(where + ": setting '" + key + "' must be " + allowed_text(*d) + ", got '" + value + "'");
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
      char* end = nullptr;
      long long v = std::strtoll(value.c_str(), &end, 10);
      if (value.empty() || *end || double(v) < d->min || double(v) > d->max) bad();
      d->value = std::to_string(v);
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
    else v.fail("setting '" + it.key() + "' must be a string, number or boolean");
    try {
      set(it.key(), text, doc->where(obj.pointer() + "/" + json_pointer_escape(it.key())));
    } catch (const InputError&) {
      throw;
    }
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
