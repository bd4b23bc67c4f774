// Level files (levels/*.json) as the game loads them: ship classes, the AI table and the
// effects the level names come from the repository.
#include "fuzz_target.h"
#include "game/sim/defs.h"
#include "particles/effect_library.h"
#include "core/data_root.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const arc::EffectLibrary effects = [] {
    arc::EffectLibrary fx;
    fx.load_directory(arc::data_root() + "/assets/effects");
    return fx;
  }();
  arc::fuzz::expect_clean([&] { arc::parse_level_def(arc::fuzz::text_of(data, size), "fuzz.json", arc::data_root(), &effects); });
  return 0;
}
