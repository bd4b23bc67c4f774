// particles/effect_library.h — loads and validates effect files (assets/effects/*.json).
//
// Each file is one composite effect named by its file stem; assets/effects/README.md documents
// every key. Loading checks everything (unknown keys, wrong types, ranges, NaN and infinity are
// not JSON, zero-length lightning seeds, unknown sprites) and throws InputError with
// `path:line:col: message`. A library is immutable once the game starts: ParticleWorld keeps
// pointers to its definitions. Each effect has an EffectId from its first load (a reloaded
// file keeps its id), so the game resolves its names once and spawns by id.
//
// Example, compiled as EffectLibraryExample.LoadsTheGameEffects in tests/unit/particles/test_examples.cpp:
//   EffectLibrary fx;
//   fx.load_directory("assets/effects");
//   const EffectDef& boom = fx.get("ship_explosion");
//   const EffectId explosion = fx.id("ship_explosion");   // fx.get(explosion) is the same definition
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "particles/effect_def.h"
#include "particles/particle_ids.h"

namespace arc {

class EffectLibrary {
 public:
  // Every *.json in the folder, in name order; a missing folder is an InputError.
  void load_directory(const std::string& dir);
  // One file; a file with the same stem replaces the earlier definition.
  void load_file(const std::string& path);
  // Parses effect text as if it were the file `path` (tests, hot reload).
  void load_text(const std::string& text, const std::string& path);

  bool has(const std::string& name) const;
  // InputError naming the known effects when the name is unknown.
  EffectId id(const std::string& name) const;
  const EffectDef& get(const std::string& name) const;
  // InputError when the id is not one of this library's.
  const EffectDef& get(EffectId id) const;
  std::vector<std::string> names() const;

 private:
  void put(std::shared_ptr<const EffectDef> def);

  std::map<std::string, EffectId> ids_;                   // by name
  std::vector<std::shared_ptr<const EffectDef>> effects_;  // by id, in order of first load
};

}  // namespace arc
