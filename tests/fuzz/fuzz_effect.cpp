// Effect files (assets/effects/*.json), as hot reload parses them.
#include "fuzz_target.h"
#include "particles/effect_library.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  arc::fuzz::expect_clean([&] {
    arc::EffectLibrary fx;
    fx.load_text(arc::fuzz::text_of(data, size), "fuzz.json");
  });
  return 0;
}
