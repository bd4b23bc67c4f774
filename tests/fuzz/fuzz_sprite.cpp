// Sprite images (assets/textures/sprite_*.png): decoded from memory as load_image() does, then
// premultiplied as the particle pass does. OpenImageIO itself is not instrumented: coverage is
// of Arcfire's side, crashes anywhere are still caught.
#include "assets/image.h"
#include "assets/image_decode.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  arc::fuzz::expect_clean([&] {
    arc::Image img = arc::decode_image_memory(data, size, "fuzz.png");
    arc::premultiply(img);
  });
  return 0;
}
