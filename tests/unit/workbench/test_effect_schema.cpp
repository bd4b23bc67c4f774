// The panel's field table is the loader's: every numeric range and enumeration the schema gives
// is the one the loader enforces (one value past either end is refused for its range, and
// neither end is), and the schema's defaults are what the loader uses.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstring>
#include <sstream>

#include "game/workbench/effect_document.h"
#include "tests/unit/workbench/workbench_files.h"
#include "core/data_root.h"

namespace arc {
namespace {

using nlohmann::json;

// One cluster of each animation type and emitter shape with keys of its own; each key of the
// schema is probed in the cluster it applies to, so the loader reads it (and does not refuse
// it as a key that does not apply).
const char* kProbe = R"({
  "clusters": [
    { "sprite": "glow", "billboard": "velocity", "animation": { "type": "linear" }, "emitter": { "rate": 10 }, "particles": {}, "curves": {} },
    { "sprite": "glow", "lifetime": 1, "animation": { "type": "sphere", "radius": 1 }, "emitter": { "burst": 5 } },
    { "sprite": "glow", "animation": { "type": "lightning", "seed_length": 1, "max_length": 10 } },
    { "sprite": "glow", "animation": {}, "emitter": { "shape": "cone", "angle_deg": 30, "rate": 1 } },
    { "sprite": "glow", "animation": {}, "emitter": { "shape": "box", "half_extents": [1, 1, 1], "rate": 1 } },
    { "sprite": "glow", "animation": {}, "emitter": { "shape": "line", "length": 1, "rate": 1 } }
  ]
})";

std::string probe_pointer(const EffectField& f) {
  const std::string applies = f.applies;
  std::string cluster = "/clusters/0";
  const char* owners[] = {"", "sphere", "lightning", "cone", "box", "line"};
  for (int i = 1; i < 6; ++i)
    if (applies.rfind(owners[i], 0) == 0 && !std::isalpha(static_cast<unsigned char>(applies[std::strlen(owners[i])])))
      cluster = "/clusters/" + std::to_string(i);
  switch (f.block) {
    case EffectBlock::Root: return std::string("/") + f.key;
    case EffectBlock::Cluster: return cluster + "/" + f.key;
    default: return cluster + "/" + effect_block_name(f.block) + "/" + f.key;
  }
}

// A value of the field's kind with every number set to x.
json value_of(const EffectField& f, double x) {
  switch (f.kind) {
    case FieldKind::Vec3: return json::array({x, x, x});
    case FieldKind::Range: return json::array({x, x});
    case FieldKind::Curve: return json::array({json::array({0, x})});
    case FieldKind::ColourCurve: return json::array({json::array({0, json::array({x, x, x})})});
    case FieldKind::Integer: return json(static_cast<int64_t>(x));
    default: return json(x);
  }
}

// A range end as the loader's messages write it.
std::string bound(const EffectField& f, double x) {
  if (f.kind == FieldKind::Integer) return std::to_string(static_cast<int64_t>(x));
  std::ostringstream s;
  s << x;
  return s.str();
}

bool numeric(const EffectField& f) {
  return f.kind == FieldKind::Number || f.kind == FieldKind::Integer || f.kind == FieldKind::Range ||
         f.kind == FieldKind::Curve || f.kind == FieldKind::ColourCurve || f.kind == FieldKind::Vec3;
}

TEST(EffectSchema, TheLoaderRefusesValuesJustOutsideEverySchemaRange) {
  test::ScratchDir dir("schema_range");
  std::string error;
  auto doc = EffectDocument::open(dir.write("probe.json", kProbe), error);
  ASSERT_TRUE(doc) << error;
  int probed = 0;
  for (const EffectField& f : effect_schema()) {
    if (!numeric(f) || std::string(f.key) == "triangles") continue;
    const std::string at = probe_pointer(f);
    const double step = f.kind == FieldKind::Integer ? 1.0 : std::max(1e-6, std::abs(f.max) * 1e-3);
    for (double outside : {f.max + step, f.min - (f.kind == FieldKind::Integer ? 1.0 : std::max(1e-6, std::abs(f.min) * 1e-3))}) {
      const EditResult r = doc->set(at, value_of(f, outside));
      EXPECT_FALSE(r.ok) << at << " = " << outside << " was accepted; the schema says [" << f.min << ", " << f.max << "]";
      // Named by the whole key path: 'clusters[1].animation.radius'.
      const std::string path = at.rfind("/clusters/", 0) == 0 ? "'clusters[" + at.substr(10, 1) + "]." : "'";
      EXPECT_NE(r.message.find(path), std::string::npos) << at << ": " << r.message;
      EXPECT_NE(r.message.find(std::string(f.key)), std::string::npos) << at << ": " << r.message;
      EXPECT_NE(r.message.find(" in [" + bound(f, f.min) + ", " + bound(f, f.max) + "]"), std::string::npos)
          << at << " refused, but not for the schema's range: " << r.message;
    }
    ++probed;
  }
  EXPECT_GE(probed, 40);
}

TEST(EffectSchema, TheLoaderAcceptsBothEndsOfEverySchemaRange) {
  test::ScratchDir dir("schema_ends");
  std::string error;
  auto doc = EffectDocument::open(dir.write("probe.json", kProbe), error);
  ASSERT_TRUE(doc) << error;
  for (const EffectField& f : effect_schema()) {
    if (!numeric(f) || std::string(f.key) == "triangles") continue;
    const std::string at = probe_pointer(f);
    for (double end : {f.min, f.max}) {
      const EditResult r = doc->set(at, value_of(f, end));
      // Another rule of the key may refuse an end ("seed_length" above zero), never its range.
      EXPECT_EQ(r.message.find(" in ["), std::string::npos) << at << " = " << end << ": " << r.message;
      if (r.ok) doc->undo();
    }
  }
}

TEST(EffectSchema, EnumerationsAreTheLoadersChoices) {
  for (const EffectField& f : effect_schema()) {
    if (f.kind != FieldKind::Enum) continue;
    ASSERT_FALSE(f.choices.empty()) << f.key;
    bool has_fallback = false;
    for (const char* c : f.choices) has_fallback = has_fallback || f.fallback == c;
    EXPECT_TRUE(has_fallback) << f.key;
  }
  test::ScratchDir dir("schema_enum");
  std::string error;
  auto doc = EffectDocument::open(dir.write("probe.json", kProbe), error);
  ASSERT_TRUE(doc) << error;
  const EditResult r = doc->set("/clusters/0/soft_edge", "fuzzy");
  EXPECT_NE(r.message.find("\"off\", \"linear\", \"contrast\", \"average_density\" or \"density_extent\""), std::string::npos)
      << r.message;
  for (const char* c : effect_field(EffectBlock::Cluster, "soft_edge").choices) EXPECT_TRUE(doc->set("/clusters/0/soft_edge", c).ok) << c;
}

TEST(EffectSchema, DefaultsAreWhatTheLoaderUses) {
  test::ScratchDir dir("schema_default");
  std::string error;
  auto doc = EffectDocument::open(dir.write("probe.json", kProbe), error);
  ASSERT_TRUE(doc) << error;
  const ClusterDef& linear = doc->def().clusters[0];
  const ClusterDef& sphere = doc->def().clusters[1];
  const ClusterDef& bolt = doc->def().clusters[2];
  auto fallback = [](EffectBlock b, const char* key) { return effect_field(b, key).fallback.get<double>(); };
  EXPECT_EQ(linear.particles.lifetime.max, fallback(EffectBlock::Particles, "lifetime"));
  EXPECT_EQ(linear.particles.size.min, fallback(EffectBlock::Particles, "size"));
  EXPECT_EQ(linear.particles.inherit_velocity, fallback(EffectBlock::Particles, "inherit_velocity"));
  EXPECT_EQ(linear.priority, effect_field(EffectBlock::Cluster, "priority").fallback.get<int>());
  EXPECT_EQ(sphere.sphere.ramp, fallback(EffectBlock::Animation, "ramp"));
  EXPECT_EQ(bolt.lightning.length_jitter, fallback(EffectBlock::Animation, "length_jitter"));
  EXPECT_EQ(bolt.lightning.sizzle_ticks, effect_field(EffectBlock::Animation, "sizzle_ticks").fallback.get<int>());
  EXPECT_EQ(bolt.lightning.free_lifetime, fallback(EffectBlock::Animation, "free_lifetime"));
  EXPECT_EQ(linear.screen_priority, ScreenPriority::Normal);
  EXPECT_EQ(effect_field(EffectBlock::Cluster, "screen_priority").fallback, "normal");
}

TEST(EffectSchema, PointersFindTheirFields) {
  const EffectField* f = effect_field_at("/clusters/3/emitter/rate");
  ASSERT_TRUE(f);
  EXPECT_EQ(f->kind, FieldKind::Number);
  EXPECT_EQ(f->max, 1e7);
  ASSERT_TRUE(effect_field_at("/clusters/0/curves/color"));
  EXPECT_EQ(effect_field_at("/clusters/0/curves/color")->kind, FieldKind::ColourCurve);
  EXPECT_EQ(effect_field_at("/clusters/0/sprite")->kind, FieldKind::Sprite);
  EXPECT_EQ(effect_field_at("/description")->kind, FieldKind::String);
  EXPECT_EQ(effect_field_at("/clusters/0/curves/alpha/0/1"), nullptr);
  EXPECT_EQ(effect_field_at("/clusters/0/emitter/nope"), nullptr);
  EffectBlock b;
  ASSERT_TRUE(effect_block_at("/clusters/2/animation", b));
  EXPECT_EQ(b, EffectBlock::Animation);
  EXPECT_FALSE(effect_block_at("/clusters/x", b));
  EXPECT_THROW(effect_field(EffectBlock::Emitter, "nope"), std::out_of_range);
}

TEST(EffectSchema, KeysApplyOnlyWhereTheyHaveAnEffect) {
  auto applies = [](EffectBlock b, const char* key, const char* cluster) {
    return effect_field_applies(effect_field(b, key), json::parse(cluster));
  };
  EXPECT_TRUE(applies(EffectBlock::Animation, "growth", R"({"animation": {"type": "sphere", "radius_animation": "exploding"}})"));
  EXPECT_FALSE(applies(EffectBlock::Animation, "growth", R"({"animation": {"type": "sphere"}})"));
  EXPECT_FALSE(applies(EffectBlock::Animation, "drag", R"({"animation": {"type": "sphere"}})"));
  EXPECT_TRUE(applies(EffectBlock::Animation, "drag", R"({"animation": {}})"));
  EXPECT_TRUE(applies(EffectBlock::Emitter, "angle_deg", R"({"animation": {}, "emitter": {"shape": "cone"}})"));
  EXPECT_FALSE(applies(EffectBlock::Emitter, "angle_deg", R"({"animation": {}, "emitter": {}})"));
  EXPECT_FALSE(applies(EffectBlock::Emitter, "rate", R"({"animation": {"type": "lightning"}})"));
  EXPECT_FALSE(applies(EffectBlock::Emitter, "spacing", R"({"space": "owner", "animation": {}})"));
  EXPECT_TRUE(applies(EffectBlock::Cluster, "stretch", R"({"billboard": "velocity"})"));
  EXPECT_FALSE(applies(EffectBlock::Cluster, "stretch", R"({})"));
}

// Every key the game's effect files use is in the schema, and applies where it is used.
TEST(EffectSchema, CoversEveryKeyOfTheGamesEffects) {
  for (const auto& e : std::filesystem::directory_iterator(arc::data_root() + "/assets/effects")) {
    if (e.path().extension() != ".json") continue;
    const json j = json::parse(test::ScratchDir::read(e.path().string()), nullptr, true, true);
    for (const auto& [k, v] : j.items()) EXPECT_TRUE(effect_field_at("/" + k)) << e.path() << " " << k;
    for (size_t i = 0; i < j["clusters"].size(); ++i) {
      const std::string c = "/clusters/" + std::to_string(i);
      const json& cluster = j["clusters"][i];
      for (const auto& [k, v] : cluster.items()) {
        const EffectField* f = effect_field_at(c + "/" + k);
        ASSERT_TRUE(f) << e.path() << " " << c << "/" << k;
        EXPECT_TRUE(effect_field_applies(*f, cluster)) << e.path() << " " << c << "/" << k;
        if (!v.is_object()) continue;
        for (const auto& [k2, v2] : v.items()) {
          const EffectField* f2 = effect_field_at(c + "/" + k + "/" + k2);
          ASSERT_TRUE(f2) << e.path() << " " << k << "/" << k2;
          EXPECT_TRUE(effect_field_applies(*f2, cluster)) << e.path() << " " << c << "/" << k << "/" << k2;
        }
      }
    }
  }
}

}  // namespace
}  // namespace arc
