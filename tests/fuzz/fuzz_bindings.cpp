// Key binding files (assets/settings/bindings.json, the user's own copy).
#include "fuzz_target.h"
#include "game/app/input_bindings.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  arc::fuzz::expect_clean([&] { arc::parse_bindings(arc::fuzz::text_of(data, size), "fuzz.json"); });
  return 0;
}
