#include "particles/effect_schema.h"

#include <cstdlib>
#include <stdexcept>

namespace arc {
namespace {

using B = EffectBlock;
using K = FieldKind;
using J = nlohmann::json;

constexpr double kBig = 1e6;  // m: the largest distance or extent an effect may name

EffectField field(B block, const char* key, K kind, double min, double max, J fallback, const char* unit = "",
                  const char* applies = "", bool required = false) {
  EffectField f{};
  f.block = block;
  f.key = key;
  f.kind = kind;
  f.min = min;
  f.max = max;
  f.fallback = std::move(fallback);
  f.unit = unit;
  f.applies = applies;
  f.required = required;
  return f;
}

EffectField choice(B block, const char* key, std::vector<const char*> choices, const char* applies = "",
                   int fallback = 0) {
  EffectField f{};
  f.block = block;
  f.key = key;
  f.kind = K::Enum;
  f.fallback = choices[size_t(fallback)];
  f.choices = std::move(choices);
  f.applies = applies;
  return f;
}

EffectField other(B block, const char* key, K kind, J fallback, bool required = false, const char* applies = "") {
  EffectField f{};
  f.block = block;
  f.key = key;
  f.kind = kind;
  f.fallback = std::move(fallback);
  f.required = required;
  f.applies = applies;
  return f;
}

// The table of the whole format, one entry per key, in file order.
std::vector<EffectField> build() {
  const J zero3 = J::array({0, 0, 0});
  return {
      other(B::Root, "description", K::String, ""),
      other(B::Root, "clusters", K::ObjectList, nullptr, true),

      other(B::Cluster, "name", K::String, nullptr),
      other(B::Cluster, "sprite", K::Sprite, nullptr, true),
      choice(B::Cluster, "soft_edge", {"off", "linear", "contrast", "average_density", "density_extent"}),
      field(B::Cluster, "soft_extent", K::Number, 0.0, kBig, 0.0, "m", "0 = the particle size"),
      choice(B::Cluster, "billboard", {"camera", "velocity"}),
      field(B::Cluster, "stretch", K::Number, 0.0, 10.0, 0.03, "s", "\"billboard\": \"velocity\""),
      choice(B::Cluster, "space", {"world", "owner"}),
      field(B::Cluster, "lifetime", K::Number, 0.0, 3600.0, 0.0, "s", "0 = until empty"),
      field(B::Cluster, "priority", K::Integer, -1.0, 100.0, -1, "", "-1 = the spawn's priority"),
      choice(B::Cluster, "screen_priority", {"low", "normal", "high"}, "", 1),
      other(B::Cluster, "animation", K::Object, nullptr, true),
      other(B::Cluster, "emitter", K::Object, nullptr, true, "not for lightning"),
      other(B::Cluster, "particles", K::Object, J::object()),
      other(B::Cluster, "curves", K::Object, J::object()),

      choice(B::Animation, "type", {"linear", "sphere", "lightning"}),
      field(B::Animation, "drag", K::Number, 0.0, 1e4, 0.0, "1/s", "linear"),
      field(B::Animation, "acceleration", K::Vec3, -1e5, 1e5, zero3, "m/s^2", "linear"),
      choice(B::Animation, "motion", {"static", "stochastic", "rotational"}, "sphere"),
      field(B::Animation, "radius", K::Number, 0.0, kBig, nullptr, "m", "sphere", true),
      field(B::Animation, "rotation_deg", K::Vec3, -1e5, 1e5, zero3, "deg/s", "sphere, rotational"),
      choice(B::Animation, "radius_animation", {"constant", "pulsating", "contracting", "exploding"}, "sphere"),
      field(B::Animation, "amplitude", K::Number, 0.0, 1.0, 0.0, "", "sphere, pulsating"),
      field(B::Animation, "frequency_hz", K::Number, 0.0, 1000.0, 0.0, "Hz", "sphere, pulsating"),
      field(B::Animation, "ramp", K::Number, 1e-3, 0.5, 0.2, "", "sphere, contracting"),
      field(B::Animation, "growth", K::Number, 0.0, 1e5, 0.0, "m/s", "sphere, exploding"),
      field(B::Animation, "seed_length", K::Number, 0.0, kBig, nullptr, "m", "lightning; above zero", true),
      field(B::Animation, "max_length", K::Number, 0.0, kBig, nullptr, "m", "lightning; at least seed_length", true),
      field(B::Animation, "max_angle_deg", K::Number, 0.0, 89.0, 20.0, "deg", "lightning"),
      field(B::Animation, "length_jitter", K::Number, 0.0, 0.9, 0.3, "", "lightning"),
      field(B::Animation, "guide_distance", K::Number, 0.0, kBig, 0.0, "m", "lightning"),
      field(B::Animation, "sizzle_ticks", K::Integer, 1.0, 600.0, 3, "ticks", "lightning"),
      field(B::Animation, "width", K::Number, 1e-3, kBig, 1.0, "m", "lightning"),
      field(B::Animation, "free_lifetime", K::Number, 0.01, 3600.0, 2.0, "s", "lightning"),

      choice(B::Emitter, "shape", {"point", "sphere", "sphere_surface", "cone", "box", "line", "mesh"},
             "not for sphere clusters"),
      field(B::Emitter, "offset", K::Vec3, -kBig, kBig, zero3, "m"),
      field(B::Emitter, "axis", K::Vec3, -1.0, 1.0, J::array({0, 0, -1}), "", "non-zero"),
      field(B::Emitter, "radius", K::Number, 0.0, kBig, 0.0, "m", "required for sphere and sphere_surface"),
      field(B::Emitter, "angle_deg", K::Number, 0.0, 180.0, nullptr, "deg", "cone", true),
      field(B::Emitter, "half_extents", K::Vec3, 0.0, kBig, nullptr, "m", "box", true),
      field(B::Emitter, "length", K::Number, 0.0, kBig, nullptr, "m", "line", true),
      field(B::Emitter, "triangles", K::Vec3List, -kBig, kBig, nullptr, "m", "mesh", true),
      field(B::Emitter, "rate", K::Number, 0.0, 1e7, 0.0, "1/s"),
      field(B::Emitter, "spacing", K::Number, 0.0, kBig, 0.0, "m", "0 or at least 0.01; world-space linear"),
      field(B::Emitter, "burst", K::Integer, 0.0, 1e6, 0, "particles"),
      field(B::Emitter, "duration", K::Number, 0.0, 1e6, 0.0, "s", "0 = until stopped"),
      choice(B::Emitter, "direction", {"shape", "random", "forward"}),

      field(B::Particles, "speed", K::Range, 0.0, 1e5, 0.0, "m/s"),
      field(B::Particles, "lifetime", K::Range, 0.0, 3600.0, 1.0, "s", "linear: in (0, 600]"),
      field(B::Particles, "size", K::Range, 0.0, 1e5, 1.0, "m", "max above zero"),
      field(B::Particles, "rotation_deg", K::Range, -3600.0, 3600.0, 0.0, "deg"),
      field(B::Particles, "spin_deg", K::Range, -1e5, 1e5, 0.0, "deg/s"),
      field(B::Particles, "inherit_velocity", K::Number, 0.0, 1.0, 1.0),

      field(B::Curves, "size", K::Curve, 0.0, 1000.0, 1.0, "x size"),
      field(B::Curves, "alpha", K::Curve, 0.0, 1.0, 1.0),
      field(B::Curves, "burn", K::Curve, 0.0, 1.0, 0.0, "", "0 blended ... 1 additive"),
      field(B::Curves, "color", K::ColourCurve, 0.0, 8.0, J::array({J::array({0, J::array({1, 1, 1})})}), "rgb"),
  };
}

bool is_index(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

std::vector<std::string> split_pointer(const std::string& pointer) {
  std::vector<std::string> parts;
  size_t i = 0;
  while (i < pointer.size() && pointer[i] == '/') {
    size_t e = pointer.find('/', i + 1);
    if (e == std::string::npos) e = pointer.size();
    parts.push_back(pointer.substr(i + 1, e - i - 1));
    i = e;
  }
  return parts;
}

// The block of the object named by the first `n` parts of a pointer.
bool block_of(const std::vector<std::string>& parts, size_t n, EffectBlock& block) {
  if (n == 0) return block = B::Root, true;
  if (parts[0] != "clusters" || n < 2 || !is_index(parts[1])) return false;
  if (n == 2) return block = B::Cluster, true;
  if (n != 3) return false;
  for (B b : {B::Animation, B::Emitter, B::Particles, B::Curves})
    if (parts[2] == effect_block_name(b)) return block = b, true;
  return false;
}

}  // namespace

const std::vector<EffectField>& effect_schema() {
  static const std::vector<EffectField> table = build();
  return table;
}

const EffectField& effect_field(EffectBlock block, std::string_view key) {
  for (const EffectField& f : effect_schema())
    if (f.block == block && key == f.key) return f;
  throw std::out_of_range("effect schema has no key '" + std::string(key) + "' in block " + effect_block_name(block));
}

std::vector<const EffectField*> effect_fields(EffectBlock block) {
  std::vector<const EffectField*> out;
  for (const EffectField& f : effect_schema())
    if (f.block == block) out.push_back(&f);
  return out;
}

bool effect_block_at(const std::string& pointer, EffectBlock& block) {
  const std::vector<std::string> parts = split_pointer(pointer);
  if (!pointer.empty() && parts.empty()) return false;
  return block_of(parts, parts.size(), block);
}

const EffectField* effect_field_at(const std::string& pointer) {
  const std::vector<std::string> parts = split_pointer(pointer);
  if (parts.empty()) return nullptr;
  EffectBlock block;
  if (!block_of(parts, parts.size() - 1, block)) return nullptr;
  for (const EffectField& f : effect_schema())
    if (f.block == block && parts.back() == f.key) return &f;
  return nullptr;
}

namespace {

std::string text_or(const nlohmann::json& object, const char* key, const char* fallback) {
  if (!object.is_object()) return fallback;
  auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : std::string(fallback);
}

bool animation_key_applies(const std::string& key, const nlohmann::json& animation) {
  const std::string type = text_or(animation, "type", "linear");
  if (key == "type") return true;
  if (key == "drag" || key == "acceleration") return type == "linear";
  if (type == "lightning")
    return key == "seed_length" || key == "max_length" || key == "max_angle_deg" || key == "length_jitter" ||
           key == "guide_distance" || key == "sizzle_ticks" || key == "width" || key == "free_lifetime";
  if (type != "sphere") return false;
  const std::string radius_animation = text_or(animation, "radius_animation", "constant");
  if (key == "rotation_deg") return text_or(animation, "motion", "static") == "rotational";
  if (key == "amplitude" || key == "frequency_hz") return radius_animation == "pulsating";
  if (key == "ramp") return radius_animation == "contracting";
  if (key == "growth") return radius_animation == "exploding";
  return key == "motion" || key == "radius" || key == "radius_animation";
}

bool emitter_key_applies(const std::string& key, const nlohmann::json& cluster, const std::string& type) {
  const std::string shape = text_or(cluster.value("emitter", nlohmann::json::object()), "shape", "point");
  if (key == "shape") return type != "sphere";
  if (key == "angle_deg") return shape == "cone";
  if (key == "half_extents") return shape == "box";
  if (key == "length") return shape == "line";
  if (key == "triangles") return shape == "mesh";
  if (key == "radius") return shape == "sphere" || shape == "sphere_surface" || shape == "cone";
  if (key == "spacing") return type == "linear" && text_or(cluster, "space", "world") == "world";
  return true;
}

}  // namespace

bool effect_field_applies(const EffectField& f, const nlohmann::json& cluster) {
  const nlohmann::json animation = cluster.is_object() ? cluster.value("animation", nlohmann::json::object()) : nlohmann::json::object();
  const std::string type = text_or(animation, "type", "linear");
  const std::string key = f.key;
  switch (f.block) {
    case B::Root: return true;
    case B::Cluster:
      if (key == "stretch") return text_or(cluster, "billboard", "camera") == "velocity";
      if (key == "emitter") return type != "lightning";
      return true;
    case B::Animation: return animation_key_applies(key, animation);
    case B::Emitter: return type != "lightning" && emitter_key_applies(key, cluster, type);
    case B::Particles:
    case B::Curves: return true;
  }
  return false;
}

const char* effect_block_name(EffectBlock block) {
  switch (block) {
    case B::Root: return "root";
    case B::Cluster: return "cluster";
    case B::Animation: return "animation";
    case B::Emitter: return "emitter";
    case B::Particles: return "particles";
    case B::Curves: return "curves";
  }
  return "?";
}

}  // namespace arc
