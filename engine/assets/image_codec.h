// assets/image_codec.h — internal: the image codec module (assets/codec/), loaded on first use.
//
// image_codec() loads libarcfire_image_codec.so with dlopen the first time an image is decoded
// or encoded, looking next to the running executable first (build/, or wherever the game was
// copied with its module), then in ../lib/arcfire beside it (an installed game), then at the
// module's path in the build tree (programs built elsewhere in it). The executables themselves
// never link OpenImageIO: a start that reads no image does not pay for its 270 libraries. A module that cannot be loaded is an InputError
// naming its path and the loader's reason (ImageCodecUnavailable), thrown again at every
// later use.
//
// Example, compiled as AssetExamples.DecodeThroughTheModule in tests/unit/assets/test_asset_examples.cpp:
//   const ImageCodec& codec = image_codec();
//   char* err = nullptr;
//   ArcCodecReader* r = codec.open(data, size, "png", name.c_str(), &w, &h, &channels, &err);
//   if (!r) throw InputError(name + ": not a readable image: " + take_codec_message(codec, err));
#pragma once
#include <string>
#include "assets/codec/image_codec_abi.h"
#include "core/error.h"

namespace arc {

struct ImageCodec {
  decltype(&arc_codec_open) open = nullptr;
  decltype(&arc_codec_read) read = nullptr;
  decltype(&arc_codec_close) close = nullptr;
  decltype(&arc_codec_encode) encode = nullptr;
  decltype(&arc_codec_free) free = nullptr;
};

// The module could not be loaded: an InputError like any other, told apart only where a
// decode failure would otherwise be blamed on the file (a model's embedded images).
struct ImageCodecUnavailable : InputError {
  using InputError::InputError;
};

// The module's file name, as it lies next to the executables.
inline constexpr const char* kImageCodecModule = "libarcfire_image_codec.so";

const ImageCodec& image_codec();
// A message the module handed out, copied and freed ("" for none).
std::string take_codec_message(const ImageCodec& codec, char* message);

}  // namespace arc
