// assets/codec/png_codec.cpp — a PNG-only image codec module for machines without OpenImageIO,
// behind the same C interface (image_codec_abi.h) as oiio_codec.cpp. Built on stb_image and
// stb_image_write (Debian's libstb, which tinygltf already brings), it needs three libraries
// instead of OpenImageIO's ~270, so the benchmark can be carried to a bare GPU machine
// (tools/gpu/pack.sh puts it beside arcfire-bench as libarcfire_image_codec.so).
//
// It decodes to the same bytes as the OpenImageIO module for every PNG the game reads
// (tests/unit/assets/test_png_codec.cpp compares them): 8-bit samples as stored, straight
// alpha kept, 16-bit samples rounded to nearest (OpenImageIO's conversion, not stb's >> 8).
// Any other format is refused with a message naming what this module reads.
#include <cstdlib>
#include <cstring>
#include <string>

#include <stb_image.h>
#include <stb_image_write.h>

#include "assets/codec/image_codec_abi.h"

struct ArcCodecReader {
  const unsigned char* data = nullptr;
  int size = 0;
  int width = 0, height = 0, channels = 0;
  bool sixteen = false;
};

namespace {

char* copy_message(const std::string& text) {
  char* s = static_cast<char*>(std::malloc(text.size() + 1));
  if (s) std::memcpy(s, text.c_str(), text.size() + 1);
  return s;
}

void set_error(char** err, const std::string& text) {
  if (err) *err = copy_message(text);
}

std::string stb_reason() {
  const char* r = stbi_failure_reason();
  return r ? r : "unknown reason";
}

bool is_png_extension(const char* ext) {
  if (!ext) return false;
  std::string e(ext);
  for (char& c : e) c = char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return e == "png";
}

bool has_png_signature(const unsigned char* data, size_t size) {
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  return size >= 8 && std::memcmp(data, kSignature, 8) == 0;
}

void append(void* context, void* bytes, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(bytes), size_t(size));
}

}  // namespace

extern "C" {

ARC_CODEC_EXPORT int arc_codec_abi_version(void) { return ARC_CODEC_ABI_VERSION; }

ARC_CODEC_EXPORT ArcCodecReader* arc_codec_open(const unsigned char* data, size_t size, const char* format,
                                                const char* name, int* width, int* height, int* channels,
                                                char** err) {
  const std::string who = name ? name : "image";
  if (!is_png_extension(format)) {
    set_error(err, who + ": this image codec module (stb_image) reads PNG only, not ." + (format ? format : "?"));
    return nullptr;
  }
  // stb_image picks the format from the bytes; only PNG bytes are accepted here, as OIIO's
  // PNG reader would.
  if (!has_png_signature(data, size)) {
    set_error(err, who + ": not a PNG file (no PNG signature)");
    return nullptr;
  }
  if (size > size_t(0x7fffffff)) {
    set_error(err, who + ": larger than 2 GiB");
    return nullptr;
  }
  auto* r = new ArcCodecReader;
  r->data = data;
  r->size = int(size);
  if (!stbi_info_from_memory(data, r->size, &r->width, &r->height, &r->channels)) {
    set_error(err, who + ": " + stb_reason());
    delete r;
    return nullptr;
  }
  r->sixteen = stbi_is_16_bit_from_memory(data, r->size) != 0;
  *width = r->width;
  *height = r->height;
  *channels = r->channels;
  return r;
}

ARC_CODEC_EXPORT int arc_codec_read(ArcCodecReader* reader, int channels, unsigned char* pixels, char** err) {
  int w = 0, h = 0, stored = 0;
  const size_t count = size_t(reader->width) * size_t(reader->height) * size_t(channels);
  if (reader->sixteen) {
    stbi_us* wide = stbi_load_16_from_memory(reader->data, reader->size, &w, &h, &stored, channels);
    if (!wide) {
      set_error(err, stb_reason());
      return 0;
    }
    // Rounded to nearest: v * 255 / 65535 = v / 257.
    for (size_t i = 0; i < count; ++i) pixels[i] = static_cast<unsigned char>((unsigned(wide[i]) + 128u) / 257u);
    stbi_image_free(wide);
    return 1;
  }
  stbi_uc* narrow = stbi_load_from_memory(reader->data, reader->size, &w, &h, &stored, channels);
  if (!narrow) {
    set_error(err, stb_reason());
    return 0;
  }
  std::memcpy(pixels, narrow, count);
  stbi_image_free(narrow);
  return 1;
}

ARC_CODEC_EXPORT void arc_codec_close(ArcCodecReader* reader, int /*ok*/) { delete reader; }

ARC_CODEC_EXPORT int arc_codec_encode(const char* path, int width, int height, const unsigned char* rgba,
                                      unsigned char** bytes, size_t* size, char** err) {
  const char* dot = path ? std::strrchr(path, '.') : nullptr;
  if (!dot || !is_png_extension(dot + 1)) return 1;
  std::string out;
  if (!stbi_write_png_to_func(append, &out, width, height, 4, rgba, width * 4)) {
    set_error(err, std::string(path) + ": PNG encoding failed");
    return 2;
  }
  *bytes = static_cast<unsigned char*>(std::malloc(out.empty() ? 1 : out.size()));
  if (!*bytes) {
    set_error(err, "out of memory for the encoded image");
    return 2;
  }
  std::memcpy(*bytes, out.data(), out.size());
  *size = out.size();
  return 0;
}

ARC_CODEC_EXPORT void arc_codec_free(void* p) { std::free(p); }

}  // extern "C"
