// particles/effect_schema.h — every key of the effect file format, with its kind, range and default.
//
// One table is the single source of truth for the format's numbers: the loader
// (effect_library.cpp) reads each key's range, allowed values and default from it, and the
// effect workbench's panel picks a widget and a slider range from the same entry, so the range a
// tweaker can drag to is the range the validator accepts, by construction.
//
// Keys live in blocks: the file's root, a cluster, its "animation", "emitter", "particles" and
// "curves" objects. A key may apply only under a condition the loader enforces (e.g. "growth"
// only for a sphere with "radius_animation": "exploding"); `applies` says so in words.
//
// Example, compiled as EffectSchemaExample.LookUpAKey in tests/unit/particles/test_examples.cpp:
//   const EffectField& rate = effect_field(EffectBlock::Emitter, "rate");    // kind Number, [0, 1e7]
//   const EffectField* f = effect_field_at("/clusters/0/curves/alpha");       // kind Curve, [0, 1]
#pragma once
#include <string>
#include <string_view>
#include <vector>
#include <nlohmann/json.hpp>

namespace arc {

enum class EffectBlock { Root, Cluster, Animation, Emitter, Particles, Curves };

enum class FieldKind {
  Number,       // a finite number in [min, max]
  Integer,      // a whole number in [min, max]
  Enum,         // one of `choices`
  String,       // free text (names, descriptions)
  Sprite,       // a sprite name (particles/sprites.h: kSpriteNames)
  Vec3,         // [x, y, z], each in [min, max]
  Range,        // a number or [min, max] (a uniform distribution), values in [min, max]
  Curve,        // a number or [[t, value], ...] with t in [0, 1] rising, values in [min, max]
  ColourCurve,  // [[t, [r, g, b]], ...], components in [min, max]
  Vec3List,     // [[x, y, z], ...] (mesh triangles: 3 vertices each)
  Object,       // a nested block (animation, emitter, particles, curves)
  ObjectList,   // the clusters array
};

struct EffectField {
  EffectBlock block;
  const char* key;
  FieldKind kind;
  double min = 0.0;                  // Number, Integer, Vec3, Range, Curve, ColourCurve
  double max = 0.0;
  std::vector<const char*> choices;  // Enum: the allowed values, in the order the panel lists them
  nlohmann::json fallback;           // the value used when the key is absent (null: required or none)
  bool required = false;             // required when it applies
  const char* applies = "";          // when the key is allowed, in words ("" = always)
  const char* unit = "";             // "m", "s", "deg", "1/s", ... for labels
};

// The whole table, grouped by block in file order.
const std::vector<EffectField>& effect_schema();
// The entry of a key in a block; throws std::out_of_range for a key the format does not have.
const EffectField& effect_field(EffectBlock block, std::string_view key);
// The entry for a value of an effect document by JSON pointer ("/clusters/1/emitter/rate",
// "/clusters/0/curves/color"); nullptr for pointers inside a value (a keyframe) or unknown keys.
const EffectField* effect_field_at(const std::string& pointer);
// The block an object at a pointer is ("" → Root, "/clusters/2" → Cluster, ".../emitter" → Emitter).
bool effect_block_at(const std::string& pointer, EffectBlock& block);
// Whether a key has an effect in a cluster as it stands (its JSON object): "growth" only for an
// exploding sphere, "angle_deg" only for a cone emitter, "stretch" only for velocity billboards,
// and so on; root keys always apply. The panel hides the keys that do not. `applies` says the
// same in words.
bool effect_field_applies(const EffectField& field, const nlohmann::json& cluster);
// The keys of one block, in table order.
std::vector<const EffectField*> effect_fields(EffectBlock block);
const char* effect_block_name(EffectBlock block);  // "root", "cluster", "animation", ...

}  // namespace arc
