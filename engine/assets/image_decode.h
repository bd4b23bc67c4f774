// assets/image_decode.h — internal: decodes an encoded image held in memory (glTF embedded
// images) into RGBA8 through OpenImageIO. `name` is used for format detection and messages.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include "assets/image.h"

namespace arc {

Image decode_image_memory(const uint8_t* data, size_t size, const std::string& name);

}  // namespace arc
