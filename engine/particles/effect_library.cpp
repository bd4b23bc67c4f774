#include "particles/effect_library.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/data_layers.h"
#include "core/error.h"
#include "core/input_file.h"
#include "core/input_limits.h"
#include "core/json.h"
#include "particles/effect_schema.h"
#include "particles/sprites.h"

namespace arc {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kMinSpacing = 0.01;  // m: a trail of finer spacing would spend the budget on one tick

// The shortest rotation taking −Z onto the unit vector `to`.
glm::dquat rotation_from_forward(const glm::dvec3& to) {
  const glm::dvec3 from(0, 0, -1);
  const double d = from.x * to.x + from.y * to.y + from.z * to.z;
  if (d < -1.0 + 1e-12) return glm::dquat(0, 1, 0, 0);  // half turn about X
  const glm::dvec3 c(from.y * to.z - from.z * to.y, from.z * to.x - from.x * to.z, from.x * to.y - from.y * to.x);
  return glm::normalize(glm::dquat(1.0 + d, c.x, c.y, c.z));
}

// Ranges, allowed values and defaults come from the format's table (particles/effect_schema.h),
// which the workbench's panel reads too.
using B = EffectBlock;

double number(JsonObject& o, B block, const char* key) {
  const EffectField& f = effect_field(block, key);
  return o.number(key, f.fallback.get<double>(), f.min, f.max);
}
double required_number(JsonObject& o, B block, const char* key) {
  const EffectField& f = effect_field(block, key);
  return o.require_number(key, f.min, f.max);
}
int64_t integer(JsonObject& o, B block, const char* key) {
  const EffectField& f = effect_field(block, key);
  return o.integer(key, f.fallback.get<int64_t>(), int64_t(f.min), int64_t(f.max));
}
std::string pick(JsonObject& o, B block, const char* key) {
  const EffectField& f = effect_field(block, key);
  return o.choice(key, f.fallback.get<std::string>(), f.choices);
}
glm::dvec3 vec3(JsonObject& o, B block, const char* key) {
  const EffectField& f = effect_field(block, key);
  const nlohmann::json& d = f.fallback;
  return o.vec3(key, glm::dvec3(d[0].get<double>(), d[1].get<double>(), d[2].get<double>()), f.min, f.max);
}

// A distribution: a number (constant) or [min, max] with min ≤ max.
Range read_range(JsonObject& o, const std::string& key, double unit = 1.0) {
  const EffectField& f = effect_field(B::Particles, key);
  const double lo = f.min, hi = f.max;
  auto v = o.get(key);
  if (!v) return {f.fallback.get<double>() * unit, f.fallback.get<double>() * unit};
  if (v->is_number()) {
    double x = v->number(lo, hi) * unit;
    return {x, x};
  }
  if (!v->is_array() || v->raw().size() != 2)
    v->fail("'" + v->name() + "' must be a number or [min, max] with numbers in [" + std::to_string(lo) + ", " +
            std::to_string(hi) + "]");
  std::vector<double> n = v->numbers(lo, hi);
  if (n[0] > n[1]) v->fail("'" + v->name() + "' must be [min, max] with min <= max");
  return {n[0] * unit, n[1] * unit};
}

// [[t, value], ...] with t in [0, 1] increasing, or a single number.
std::vector<CurveKey> read_keys(const JsonValue& v, double lo, double hi, int component) {
  auto checked = [&](const JsonValue& x, double value) {
    if (value < lo || value > hi)
      x.fail("'" + v.name() + "' values must be in [" + std::to_string(lo).substr(0, std::to_string(lo).find('.')) + ", " +
             std::to_string(hi).substr(0, std::to_string(hi).find('.')) + "], got " + x.raw().dump());
    return value;
  };
  if (v.is_number() && component < 0) return {{0.0f, float(v.number(lo, hi))}};
  if (!v.is_array() || v.raw().empty())
    v.fail("'" + v.name() + "' must be a number or a non-empty array of [t, value] keyframes");
  v.check_list_length(kMaxCurveKeys);
  std::vector<CurveKey> keys;
  double last_t = 0.0;
  for (const JsonValue& k : v.array()) {
    if (!k.is_array() || k.raw().size() != 2)
      k.fail("a keyframe must be [t, value] with t in [0, 1]");
    std::vector<JsonValue> tv = k.array();
    const double t_file = tv[0].number(0.0, 1.0);
    const float t = float(t_file);
    if (!keys.empty() && t < keys.back().t) tv[0].fail("keyframe times must not decrease");
    // Curves are evaluated in float: two times apart in the file but equal as floats would
    // make a step the author did not write.
    if (!keys.empty() && t == keys.back().t && t_file != last_t)
      tv[0].fail("'" + tv[0].name() + "': key times " + nlohmann::json(last_t).dump() + " and " + tv[0].raw().dump() +
                 " are the same in single precision; allowed: times equal (a step) or apart as floats "
                 "(about 1e-7 near 1)");
    last_t = t_file;
    double value;
    if (component < 0) {
      value = checked(tv[1], tv[1].number(-1e300, 1e300));
    } else {
      const glm::dvec3 rgb = tv[1].vec3(-1e300, 1e300);
      for (int c = 0; c < 3; ++c) checked(tv[1].array()[size_t(c)], rgb[c]);
      value = rgb[component];
    }
    keys.push_back({t, float(value)});
  }
  return keys;
}

void read_curves(JsonObject o, ClusterDef& c) {
  auto curve = [&](const char* key, Curve& out) {
    const EffectField& f = effect_field(B::Curves, key);
    if (auto v = o.get(key)) out = Curve::from_keys(read_keys(*v, f.min, f.max, -1));
  };
  curve("size", c.size);
  curve("alpha", c.alpha);
  curve("burn", c.burn);
  if (auto v = o.get("color")) {
    const EffectField& f = effect_field(B::Curves, "color");
    if (v->is_number()) v->fail("'" + v->name() + "' must be an array of [t, [r, g, b]] keyframes");
    c.red = Curve::from_keys(read_keys(*v, f.min, f.max, 0));
    c.green = Curve::from_keys(read_keys(*v, f.min, f.max, 1));
    c.blue = Curve::from_keys(read_keys(*v, f.min, f.max, 2));
  }
  o.finish();
}

void read_emitter(JsonObject o, ClusterDef& c) {
  EmitterDef& e = c.emitter;
  if (c.animation == AnimationType::Sphere && o.has("shape"))
    o.fail_key("shape", "a sphere cluster places its particles uniformly on its sphere; 'shape' is not allowed");
  std::string shape = pick(o, B::Emitter, "shape");
  e.shape = shape == "point" ? EmitterShape::Point
            : shape == "sphere" ? EmitterShape::Sphere
            : shape == "sphere_surface" ? EmitterShape::SphereSurface
            : shape == "cone" ? EmitterShape::Cone
            : shape == "box" ? EmitterShape::Box
            : shape == "line" ? EmitterShape::Line
                              : EmitterShape::Mesh;
  e.offset = vec3(o, B::Emitter, "offset");
  if (auto axis = o.get("axis")) {
    const EffectField& f = effect_field(B::Emitter, "axis");
    const glm::dvec3 a = axis->vec3(f.min, f.max);
    const double l = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    if (l < 1e-6) axis->fail("'" + axis->name() + "' must be a non-zero direction [x, y, z]");
    e.axis_rotation = rotation_from_forward(a / l);
  }
  const bool needs_radius = e.shape == EmitterShape::Sphere || e.shape == EmitterShape::SphereSurface;
  e.radius = needs_radius ? required_number(o, B::Emitter, "radius") : number(o, B::Emitter, "radius");
  if (e.shape == EmitterShape::Cone) e.angle = required_number(o, B::Emitter, "angle_deg") * kDeg;
  if (e.shape == EmitterShape::Box) {
    const EffectField& f = effect_field(B::Emitter, "half_extents");
    e.half_extents = o.require("half_extents").vec3(f.min, f.max);
  }
  if (e.shape == EmitterShape::Line) e.length = required_number(o, B::Emitter, "length");
  if (e.shape == EmitterShape::Mesh) {
    const EffectField& f = effect_field(B::Emitter, "triangles");
    JsonValue tri = o.require("triangles");
    tri.check_list_length(3 * kMaxEmitterTriangles);
    for (const JsonValue& v : tri.array()) e.triangles.push_back(v.vec3(f.min, f.max));
    if (e.triangles.empty() || e.triangles.size() % 3 != 0)
      tri.fail("'" + tri.name() + "' must list 3 vertices [x, y, z] per triangle, got " + std::to_string(e.triangles.size()) +
               " vertices");
    double total = 0.0;
    for (size_t i = 0; i < e.triangles.size(); i += 3) {
      glm::dvec3 a = e.triangles[i + 1] - e.triangles[i], b = e.triangles[i + 2] - e.triangles[i];
      glm::dvec3 n(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
      total += 0.5 * std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
      e.area_prefix.push_back(total);
    }
    if (!(total > 0.0)) tri.fail("'" + tri.name() + "' must have a total area above zero");
  }
  e.rate = number(o, B::Emitter, "rate");
  e.spacing = number(o, B::Emitter, "spacing");
  if (e.spacing > 0.0 && e.spacing < kMinSpacing)
    o.fail_key("spacing", "'" + o.key_path("spacing") + "' must be 0 (none) or at least 0.01 m, got " + std::to_string(e.spacing));
  if (e.spacing > 0.0 && (c.animation != AnimationType::Linear || c.owner_space))
    o.fail_key("spacing", "'" + o.key_path("spacing") + "' needs a world-space linear cluster: particles are laid along the emitter's path");
  e.burst = uint32_t(integer(o, B::Emitter, "burst"));
  e.duration = number(o, B::Emitter, "duration");
  std::string dir = pick(o, B::Emitter, "direction");
  e.direction = dir == "shape" ? EmitDirection::Shape : dir == "random" ? EmitDirection::Random : EmitDirection::Forward;
  if (e.rate == 0.0 && e.burst == 0 && e.spacing == 0.0) o.fail("emitter must have 'rate', 'burst' or 'spacing' > 0");
  o.finish();
}

void read_particles(JsonObject o, ClusterDef& c) {
  ParticleInitDef& p = c.particles;
  p.speed = read_range(o, "speed");
  p.lifetime = read_range(o, "lifetime");
  p.size = read_range(o, "size");
  if (p.size.max <= 0.0) o.fail_key("size", "'" + o.key_path("size") + "' must be above zero");
  p.rotation = read_range(o, "rotation_deg", kDeg);
  p.spin = read_range(o, "spin_deg", kDeg);
  p.inherit_velocity = number(o, B::Particles, "inherit_velocity");
  o.finish();
}

void read_animation(JsonObject o, ClusterDef& c) {
  std::string type = pick(o, B::Animation, "type");
  if (type == "linear") {
    c.animation = AnimationType::Linear;
    c.linear.drag = number(o, B::Animation, "drag");
    c.linear.acceleration = vec3(o, B::Animation, "acceleration");
  } else if (type == "sphere") {
    c.animation = AnimationType::Sphere;
    SphereDef& s = c.sphere;
    std::string m = pick(o, B::Animation, "motion");
    s.motion = m == "static" ? SphereMotion::Static : m == "stochastic" ? SphereMotion::Stochastic : SphereMotion::Rotational;
    s.radius = required_number(o, B::Animation, "radius");
    s.rotation_rate = vec3(o, B::Animation, "rotation_deg") * kDeg;
    std::string r = pick(o, B::Animation, "radius_animation");
    s.radius_animation = r == "constant" ? RadiusAnimation::Constant
                         : r == "pulsating" ? RadiusAnimation::Pulsating
                         : r == "contracting" ? RadiusAnimation::Contracting
                                              : RadiusAnimation::Exploding;
    s.amplitude = number(o, B::Animation, "amplitude");
    s.frequency = number(o, B::Animation, "frequency_hz");
    s.ramp = number(o, B::Animation, "ramp");
    s.growth = number(o, B::Animation, "growth");
  } else {
    c.animation = AnimationType::Lightning;
    LightningDef& l = c.lightning;
    auto seed = o.require("seed_length");
    const EffectField& sf = effect_field(B::Animation, "seed_length");
    l.seed_length = seed.number(sf.min, sf.max);
    if (l.seed_length <= 0.0) seed.fail("'" + seed.name() + "' must be above zero (a zero-length seed has no direction)");
    l.max_length = required_number(o, B::Animation, "max_length");
    if (l.max_length < l.seed_length)
      o.fail_key("max_length", "'" + o.key_path("max_length") + "' must be at least 'seed_length'");
    l.max_angle = number(o, B::Animation, "max_angle_deg") * kDeg;
    l.length_jitter = number(o, B::Animation, "length_jitter");
    l.guide_distance = number(o, B::Animation, "guide_distance");
    l.sizzle_ticks = int(integer(o, B::Animation, "sizzle_ticks"));
    l.width = number(o, B::Animation, "width");
    l.free_lifetime = number(o, B::Animation, "free_lifetime");
    if (l.max_length / (l.seed_length * (1.0 - l.length_jitter)) > 4096.0)
      o.fail_key("max_length", "'" + o.key_path("max_length") + "' allows more than 4096 segments; raise 'seed_length'");
  }
  o.finish();
}

// "billboard": "camera" (default) or "velocity" with "stretch" in seconds of motion.
void read_billboard(JsonObject& o, ClusterDef& c) {
  const bool velocity = pick(o, B::Cluster, "billboard") == "velocity";
  c.billboard = velocity ? ClusterBillboard::Velocity : ClusterBillboard::Camera;
  if (velocity) {
    c.stretch = number(o, B::Cluster, "stretch");
  } else if (o.has("stretch")) {
    o.fail_key("stretch", "'" + o.key_path("stretch") + "' applies to \"billboard\": \"velocity\" only");
  }
}

ClusterDef read_cluster(JsonObject o, int index) {
  ClusterDef c;
  c.name = o.string("name", "cluster" + std::to_string(index));
  std::string sprite = o.require_string("sprite");
  auto s = sprite_index(sprite);
  if (!s) {
    std::vector<std::string> names;
    for (auto n : kSpriteNames) names.emplace_back("\"" + std::string(n) + "\"");
    o.require("sprite").fail("'" + o.key_path("sprite") + "' must be one of " + join_allowed(names) + ", got \"" + sprite + "\"");
  }
  c.sprite = *s;
  std::string soft = pick(o, B::Cluster, "soft_edge");
  c.soft_edge = soft == "off" ? SoftEdge::Off
                : soft == "linear" ? SoftEdge::Linear
                : soft == "contrast" ? SoftEdge::Contrast
                : soft == "average_density" ? SoftEdge::AverageDensity
                                            : SoftEdge::DensityExtent;
  c.soft_extent = number(o, B::Cluster, "soft_extent");
  read_billboard(o, c);
  c.owner_space = pick(o, B::Cluster, "space") == "owner";
  c.lifetime = number(o, B::Cluster, "lifetime");
  c.priority = int(integer(o, B::Cluster, "priority"));
  const std::string screen = pick(o, B::Cluster, "screen_priority");
  c.screen_priority = screen == "low" ? ScreenPriority::Low : screen == "high" ? ScreenPriority::High : ScreenPriority::Normal;
  read_animation(o.require_object("animation"), c);
  if (c.animation == AnimationType::Sphere && c.sphere.radius_animation == RadiusAnimation::Contracting &&
      c.lifetime <= 0.0)
    o.fail_key("lifetime", "a contracting sphere needs a cluster 'lifetime' above zero (it shrinks before dying)");
  if (c.billboard == ClusterBillboard::Velocity && (c.animation != AnimationType::Linear || c.owner_space))
    o.fail_key("billboard", "\"billboard\": \"velocity\" needs a world-space linear cluster (it streaks along the particles' motion)");
  if (c.animation == AnimationType::Lightning) {
    c.owner_space = true;
    if (o.has("emitter")) o.fail_key("emitter", "a lightning cluster has no emitter: its particles are the channel");
  } else {
    read_emitter(o.require_object("emitter"), c);
  }
  if (auto p = o.get("particles")) read_particles(p->object(), c);
  if (c.animation == AnimationType::Linear && !(c.particles.lifetime.min > 0.0 && c.particles.lifetime.max <= 600.0))
    o.fail_key(o.has("particles") ? "particles" : "animation",
               "linear particles need a 'lifetime' in (0, 600] seconds, got [" + std::to_string(c.particles.lifetime.min) +
                   ", " + std::to_string(c.particles.lifetime.max) + "]");
  if (auto cv = o.get("curves")) read_curves(cv->object(), c);
  o.finish();
  return c;
}

std::shared_ptr<EffectDef> parse_effect(const std::shared_ptr<const JsonDoc>& doc, const std::string& name) {
  auto def = std::make_shared<EffectDef>();
  def->name = name;
  def->path = doc->path();
  JsonObject root(doc, "", &doc->root());
  root.string("description", "");
  auto clusters = root.require("clusters");
  clusters.check_list_length(kMaxEffectClusters);
  int i = 0;
  for (const JsonValue& v : clusters.array()) def->clusters.push_back(read_cluster(v.object(), i++));
  if (def->clusters.empty()) clusters.fail("'" + clusters.name() + "' must list at least one cluster");
  root.finish();
  return def;
}

}  // namespace

void EffectLibrary::load_directory(const std::string& dir) {
  check_input_folder(dir, "the effects");
  // With mods in use, their effects join the folder's and replace those of the same name.
  for (const std::string& f : data_files(dir, "", ".json")) load_file(f);
}

void EffectLibrary::load_file(const std::string& path) {
  auto doc = JsonDoc::load_file(path);
  put(parse_effect(doc, std::filesystem::path(path).stem().string()));
}

void EffectLibrary::load_text(const std::string& text, const std::string& path) {
  auto doc = JsonDoc::parse(text, path);
  put(parse_effect(doc, std::filesystem::path(path).stem().string()));
}

void EffectLibrary::put(std::shared_ptr<const EffectDef> def) {
  auto [it, added] = ids_.emplace(def->name, EffectId::from_index(effects_.size()));
  if (added) effects_.push_back(std::move(def));
  else effects_[it->second.index()] = std::move(def);
}

bool EffectLibrary::has(const std::string& name) const { return ids_.count(name) != 0; }

EffectId EffectLibrary::id(const std::string& name) const {
  auto it = ids_.find(name);
  if (it == ids_.end()) {
    std::vector<std::string> n = names();
    throw InputError("unknown effect '" + name + "'; known: " + (n.empty() ? std::string("none") : join_allowed(n)));
  }
  return it->second;
}

const EffectDef& EffectLibrary::get(const std::string& name) const { return get(id(name)); }

const EffectDef& EffectLibrary::get(EffectId id) const {
  if (!id || id.index() >= effects_.size())
    throw InputError("effect id " + std::to_string(id.value) + " is not one of the library's " + std::to_string(effects_.size()) + " effects");
  return *effects_[id.index()];
}

std::vector<std::string> EffectLibrary::names() const {
  std::vector<std::string> out;
  for (const auto& [n, id] : ids_) out.push_back(n);
  return out;
}

}  // namespace arc
