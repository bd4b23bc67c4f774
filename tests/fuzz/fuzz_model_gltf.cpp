// Text glTF models (.gltf with embedded base64 buffers and images).
#include "assets/model.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  arc::fuzz::expect_clean([&] { arc::parse_model(arc::fuzz::text_of(data, size), "fuzz.gltf"); });
  return 0;
}
