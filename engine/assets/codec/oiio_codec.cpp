// assets/codec/oiio_codec.cpp — the image codec module: OpenImageIO behind the C interface of
// image_codec_abi.h. The only file of Arcfire that includes OpenImageIO; built as
// libarcfire_image_codec.so and loaded on first use (assets/image_codec.cpp). Limits, messages
// and the RGBA8 conversion stay in assets/image.cpp: this file only opens, reads and writes.
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <vector>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include "assets/codec/image_codec_abi.h"

struct ArcCodecReader {
  ArcCodecReader(const unsigned char* data, size_t size)
      : proxy(const_cast<unsigned char*>(data), size) {}
  OIIO::Filesystem::IOMemReader proxy;
  std::unique_ptr<OIIO::ImageInput> in;  // declared after the proxy: destroyed (closed) first
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

// OIIO premultiplies PNG colour on read and divides it out on write unless told that alpha is
// unassociated; Arcfire keeps the stored bytes as they are and premultiplies explicitly.
const OIIO::ImageSpec& raw_alpha_config() {
  static const OIIO::ImageSpec config = [] {
    OIIO::ImageSpec s;
    s.attribute("oiio:UnassociatedAlpha", 1);
    return s;
  }();
  return config;
}

}  // namespace

extern "C" {

ARC_CODEC_EXPORT int arc_codec_abi_version(void) { return ARC_CODEC_ABI_VERSION; }

ARC_CODEC_EXPORT ArcCodecReader* arc_codec_open(const unsigned char* data, size_t size, const char* format,
                                                const char* name, int* width, int* height, int* channels,
                                                char** err) {
  try {
    auto r = std::make_unique<ArcCodecReader>(data, size);
    // The reader is made from the bare format name: given a file name, OIIO tries every other
    // format it has (JPEG 2000, OpenVDB, GDAL, video...) on bytes that are not what the
    // extension says, and one of those hung on a fuzzed PNG. The bytes come from the proxy.
    r->in = OIIO::ImageInput::create(format, false, &raw_alpha_config());
    OIIO::ImageSpec spec;
    if (!r->in || !r->in->set_ioproxy(&r->proxy) || !r->in->open(name, spec, raw_alpha_config())) {
      set_error(err, r->in ? r->in->geterror() : OIIO::geterror());
      return nullptr;
    }
    const OIIO::ImageSpec& s = r->in->spec();
    *width = s.width;
    *height = s.height;
    *channels = s.nchannels;
    return r.release();
  } catch (const std::exception& e) {
    set_error(err, std::string("image library failure: ") + e.what());
  } catch (...) {
    set_error(err, "image library failure");
  }
  return nullptr;
}

ARC_CODEC_EXPORT int arc_codec_read(ArcCodecReader* reader, int channels, unsigned char* pixels, char** err) {
  try {
    if (reader->in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels)) return 1;
    set_error(err, reader->in->geterror());
  } catch (const std::exception& e) {
    set_error(err, std::string("image library failure: ") + e.what());
  } catch (...) {
    set_error(err, "image library failure");
  }
  return 0;
}

ARC_CODEC_EXPORT void arc_codec_close(ArcCodecReader* reader, int ok) {
  if (!reader) return;
  try {
    if (ok) {
      reader->in->close();
    } else {
      // A failed read can leave a second message pending ("PNG library error"), which OIIO
      // prints to stderr when the reader is destroyed.
      reader->in->geterror();
      OIIO::geterror();
    }
  } catch (...) {
    // Closing cannot fail in a way the caller could act on; the reader is freed regardless.
  }
  delete reader;
}

ARC_CODEC_EXPORT int arc_codec_encode(const char* path, int width, int height, const unsigned char* rgba,
                                      unsigned char** bytes, size_t* size, char** err) {
  try {
    std::vector<unsigned char> out_bytes;
    OIIO::Filesystem::IOVecOutput sink(out_bytes);
    auto out = OIIO::ImageOutput::create(path, &sink);
    if (!out || !out->supports("ioproxy")) return 1;
    OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!out->set_ioproxy(&sink) || !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, rgba) ||
        !out->close()) {
      set_error(err, out->geterror());
      return 2;
    }
    *bytes = static_cast<unsigned char*>(std::malloc(out_bytes.empty() ? 1 : out_bytes.size()));
    if (!*bytes) {
      set_error(err, "out of memory for the encoded image");
      return 2;
    }
    std::memcpy(*bytes, out_bytes.data(), out_bytes.size());
    *size = out_bytes.size();
    return 0;
  } catch (const std::exception& e) {
    set_error(err, std::string("image library failure: ") + e.what());
  } catch (...) {
    set_error(err, "image library failure");
  }
  return 2;
}

ARC_CODEC_EXPORT void arc_codec_free(void* p) { std::free(p); }

}  // extern "C"
