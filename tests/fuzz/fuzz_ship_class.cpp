// Ship class files (assets/ships/*.json).
#include "fuzz_target.h"
#include "game/sim/defs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  arc::fuzz::expect_clean([&] { arc::parse_ship_class(arc::fuzz::text_of(data, size), "fuzz.json", "fuzz"); });
  return 0;
}
