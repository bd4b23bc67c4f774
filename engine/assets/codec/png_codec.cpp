// assets/codec/png_codec.cpp — a PNG-only image codec module for machines without OpenImageIO,
// behind the same C interface (image_codec_abi.h) as oiio_codec.cpp. Built on stb_image and
// stb_image_write (Debian's libstb, which tinygltf already brings), it needs three libraries
// instead of OpenImageIO's ~270, so the benchmark can be carried to a bare GPU machine
// (tools/gpu/pack.sh puts it beside arcfire-bench as libarcfire_image_codec.so).
//
// It decodes to the same bytes as the OpenImageIO module for every PNG the game reads
// (tests/unit/assets/test_png_codec.cpp compares them): 8-bit samples as stored, straight
// alpha kept, 16-bit samples rounded to nearest (OpenImageIO's conversion, not stb's >> 8).
// Any other format is refused with a message naming what this module reads. As with the other
// module, no exception crosses the interface: nothing here throws (malloc, nothrow new).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

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

void set_error(char** err, const char* text) {
  if (!err) return;
  const size_t n = std::strlen(text);
  *err = static_cast<char*>(std::malloc(n + 1));
  if (*err) std::memcpy(*err, text, n + 1);
}

const char* stb_reason() {
  const char* r = stbi_failure_reason();
  return r ? r : "unknown reason";
}

bool is_png_extension(const char* ext) {
  if (!ext) return false;
  const char* png = "png";
  for (int i = 0; i < 4; ++i) {
    const char c = ext[i] >= 'A' && ext[i] <= 'Z' ? char(ext[i] - 'A' + 'a') : ext[i];
    if (c != png[i]) return false;  // the terminating zeros compare too
  }
  return true;
}

bool has_png_signature(const unsigned char* data, size_t size) {
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  return size >= 8 && std::memcmp(data, kSignature, 8) == 0;
}

// Where stb_image_write puts the encoded bytes. Called from C: it must not throw, so it grows
// a malloc'ed buffer and remembers a failure instead.
struct Sink {
  unsigned char* data = nullptr;
  size_t size = 0, capacity = 0;
  bool failed = false;
};

void append(void* context, void* bytes, int size) {
  Sink& s = *static_cast<Sink*>(context);
  if (s.failed || size <= 0) return;
  if (s.size + size_t(size) > s.capacity) {
    const size_t capacity = std::max(s.capacity * 2, s.size + size_t(size));
    auto* grown = static_cast<unsigned char*>(std::realloc(s.data, capacity));
    if (!grown) {
      s.failed = true;
      return;
    }
    s.data = grown;
    s.capacity = capacity;
  }
  std::memcpy(s.data + s.size, bytes, size_t(size));
  s.size += size_t(size);
}

}  // namespace

extern "C" {

ARC_CODEC_EXPORT int arc_codec_abi_version(void) { return ARC_CODEC_ABI_VERSION; }

ARC_CODEC_EXPORT ArcCodecReader* arc_codec_open(const unsigned char* data, size_t size, const char* format,
                                                const char* /*name*/, int* width, int* height, int* channels,
                                                char** err) {
  // The caller's message names the file; these say what is wrong with it.
  if (!is_png_extension(format)) {
    char message[160];
    std::snprintf(message, sizeof message, "this image codec module (stb_image) reads PNG only, not .%.40s",
                  format ? format : "?");
    set_error(err, message);
    return nullptr;
  }
  // stb_image picks the format from the bytes; only PNG bytes are accepted here, as OIIO's
  // PNG reader would.
  if (!has_png_signature(data, size)) {
    set_error(err, "not a PNG file (no PNG signature)");
    return nullptr;
  }
  if (size > size_t(0x7fffffff)) {
    set_error(err, "larger than 2 GiB");
    return nullptr;
  }
  ArcCodecReader* r = new (std::nothrow) ArcCodecReader;
  if (!r) {
    set_error(err, "out of memory");
    return nullptr;
  }
  r->data = data;
  r->size = int(size);
  if (!stbi_info_from_memory(data, r->size, &r->width, &r->height, &r->channels)) {
    set_error(err, stb_reason());
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
    if (!wide || w != reader->width || h != reader->height) {
      set_error(err, wide ? "the decoded size differs from the header's" : stb_reason());
      stbi_image_free(wide);
      return 0;
    }
    // Rounded to nearest: v * 255 / 65535 = v / 257, which never falls halfway for whole v.
    for (size_t i = 0; i < count; ++i) pixels[i] = static_cast<unsigned char>((unsigned(wide[i]) + 128u) / 257u);
    stbi_image_free(wide);
    return 1;
  }
  stbi_uc* narrow = stbi_load_from_memory(reader->data, reader->size, &w, &h, &stored, channels);
  if (!narrow || w != reader->width || h != reader->height) {
    set_error(err, narrow ? "the decoded size differs from the header's" : stb_reason());
    stbi_image_free(narrow);
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
  Sink sink;
  if (!stbi_write_png_to_func(append, &sink, width, height, 4, rgba, width * 4) || sink.failed) {
    std::free(sink.data);
    set_error(err, sink.failed ? "out of memory for the encoded image" : "PNG encoding failed");
    return 2;
  }
  *bytes = sink.data;
  *size = sink.size;
  return 0;
}

ARC_CODEC_EXPORT void arc_codec_free(void* p) { std::free(p); }

}  // extern "C"
