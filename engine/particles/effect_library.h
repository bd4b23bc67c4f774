// particles/effect_library.h — loads and validates effect files (assets/effects/*.json).
//
// Each file is one composite effect named by its file stem; assets/effects/README.md documents
// every key. Loading checks everything (unknown keys, wrong types, ranges, NaN and infinity are
// not JSON, zero-length lightning seeds, unknown sprites) and throws InputError with
// `path:line:col: message`. A library is immutable once the game starts: ParticleWorld keeps
// pointers to its definitions.
//
// Example, compiled as EffectLibraryExample.LoadsTheGameEffects in tests/unit/particles/test_examples.cpp:
//   EffectLibrary fx;
//   fx.load_directory("assets/effects");
//   const EffectDef& boom = fx.get("ship_explosion");
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "particles/effect_def.h"

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
  const EffectDef& get(const std::string& name) const;
  std::vector<std::string> names() const;

 private:
  std::map<std::string, std::shared_ptr<const EffectDef>> effects_;
};

}  // namespace arc
