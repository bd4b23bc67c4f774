// Binary glTF models (assets/models/*.glb).
#include "assets/model.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  arc::fuzz::expect_clean([&] { arc::parse_model(arc::fuzz::text_of(data, size), "fuzz.glb"); });
  return 0;
}
