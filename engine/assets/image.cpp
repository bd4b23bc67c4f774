// assets/image.cpp — images through the codec module (OpenImageIO, loaded on first use:
// assets/image_codec.h), always handed out as RGBA8. Limits and messages are checked here.
#include <algorithm>
#include <cstdio>
#include <fcntl.h>
#include <unistd.h>
#include <filesystem>
#include <memory>
#include <string>
#include "assets/image_codec.h"
#include "assets/image_decode.h"
#include "assets/image.h"
#include "core/error.h"
#include "core/file_writer.h"
#include "core/input_file.h"
#include "core/input_limits.h"

namespace arc {
namespace {

// The decoded pixels, `channels` bytes each, widened to RGBA8.
Image to_rgba8(const std::vector<uint8_t>& pixels, int width, int height, int channels) {
  Image img;
  img.width = width;
  img.height = height;
  img.rgba.resize(size_t(width) * size_t(height) * 4);
  const size_t n = size_t(width) * size_t(height);
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* s = &pixels[i * size_t(channels)];
    uint8_t* d = &img.rgba[i * 4];
    switch (channels) {
      case 1: d[0] = d[1] = d[2] = s[0]; d[3] = 255; break;
      case 2: d[0] = d[1] = d[2] = s[0]; d[3] = s[1]; break;
      case 3: d[0] = s[0]; d[1] = s[1]; d[2] = s[2]; d[3] = 255; break;
      default: d[0] = s[0]; d[1] = s[1]; d[2] = s[2]; d[3] = s[3]; break;
    }
  }
  return img;
}

// Refuses sizes and channel counts before any pixel is decoded.
void check_image_shape(int width, int height, int channels, const std::string& path) {
  if (width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide)
    throw InputError(path + ": image size " + std::to_string(width) + "x" + std::to_string(height) +
                     " is not allowed (1 to " + std::to_string(kMaxImageSide) + " pixels per side)");
  // Larger images are certainly a mistake for a game asset and would only exhaust memory.
  if (size_t(width) * size_t(height) * 4 > kMaxImageDecodedBytes)
    throw InputError(path + ": image size " + std::to_string(width) + "x" + std::to_string(height) +
                     " decodes to more than " + std::to_string(kMaxImageDecodedBytes >> 20) + " MiB of RGBA8, the limit");
  if (channels < 1 || channels > 4)
    throw InputError(path + ": image has " + std::to_string(channels) + " channels; 1 to 4 are supported");
}

// An open reader of the codec module, closed (and its pending messages dropped unless the
// decode succeeded) when it goes out of scope.
class OpenReader {
 public:
  OpenReader(const ImageCodec& codec, ArcCodecReader* reader) : codec_(codec), reader_(reader) {}
  ~OpenReader() { codec_.close(reader_, ok_ ? 1 : 0); }
  OpenReader(const OpenReader&) = delete;
  OpenReader& operator=(const OpenReader&) = delete;
  ArcCodecReader* get() const { return reader_; }
  void succeeded() { ok_ = true; }

 private:
  const ImageCodec& codec_;
  ArcCodecReader* reader_;
  bool ok_ = false;
};

// libpng and OpenImageIO's PNG reader print their own "libpng error: ..." lines to stderr
// before OIIO hands back the same text; a bad file must answer with one line (ours, which
// carries that text), so stderr goes to /dev/null while a library decodes. Images are decoded
// on the main thread at load and hot reload, when nothing else is printing.
class QuietStderr {
 public:
  QuietStderr() {
    std::fflush(stderr);
    saved_ = ::dup(2);
    const int null = ::open("/dev/null", O_WRONLY);
    if (saved_ >= 0 && null >= 0) ::dup2(null, 2);
    if (null >= 0) ::close(null);
  }
  ~QuietStderr() {
    std::fflush(stderr);
    if (saved_ < 0) return;
    ::dup2(saved_, 2);
    ::close(saved_);
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_ = -1;
};

}  // namespace

Image load_image(const std::string& path) {
  // Decoded from memory, exactly as the fuzz target feeds it (tests/fuzz/fuzz_sprite.cpp).
  const std::string bytes = read_input_file(path, kMaxImageFileBytes, "an image");
  return decode_image_memory(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), path);
}

Image decode_image_memory(const uint8_t* data, size_t size, const std::string& name) {
  check_text_size(size, name, kMaxImageFileBytes, "an image");
  const ImageCodec& codec = image_codec();
  // The module opens a reader for the name's extension only, from the bytes (oiio_codec.cpp).
  const std::string ext = std::filesystem::path(name).extension().string();
  if (ext.size() < 2) throw InputError(name + ": an image name needs an extension saying its format (.png, .jpg...)");
  const QuietStderr quiet;
  int width = 0, height = 0, channels = 0;
  char* err = nullptr;
  ArcCodecReader* opened = codec.open(data, size, ext.c_str() + 1, name.c_str(), &width, &height, &channels, &err);
  if (!opened) throw InputError(name + ": not a readable image: " + take_codec_message(codec, err));
  OpenReader reader(codec, opened);
  check_image_shape(width, height, channels, name);
  std::vector<uint8_t> pixels(size_t(width) * size_t(height) * size_t(channels));
  if (!codec.read(reader.get(), channels, pixels.data(), &err))
    throw InputError(name + ": cannot decode image: " + take_codec_message(codec, err));
  reader.succeeded();
  return to_rgba8(pixels, width, height, channels);
}

void flip_rows(Image& image) {
  const size_t row = size_t(image.width) * 4;
  for (int y = 0; y < image.height / 2; ++y)
    std::swap_ranges(image.rgba.begin() + std::ptrdiff_t(size_t(y) * row),
                     image.rgba.begin() + std::ptrdiff_t(size_t(y + 1) * row),
                     image.rgba.begin() + std::ptrdiff_t(size_t(image.height - 1 - y) * row));
}

void premultiply(Image& image) {
  if (image.premultiplied) return;
  for (size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
    const unsigned a = image.rgba[i + 3];
    // Round to nearest: c·a/255 can never be exactly k + 0.5 because 255 is odd.
    for (int c = 0; c < 3; ++c) image.rgba[i + size_t(c)] = uint8_t((image.rgba[i + size_t(c)] * a + 127u) / 255u);
  }
  image.premultiplied = true;
}

Image load_sprite(const std::string& path) {
  Image img = load_image(path);
  premultiply(img);
  return img;
}

std::vector<uint8_t> encode_image(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.rgba.size() != size_t(image.width) * size_t(image.height) * 4)
    throw InputError(path + ": cannot save an image whose size does not match its pixel data");
  // Encoded in memory: the library's own file writes (libpng's fwrite) go unchecked, so the
  // bytes reach the disk through core/file_writer.h instead. The encoder is chosen by extension.
  const ImageCodec& codec = image_codec();
  unsigned char* encoded = nullptr;
  size_t size = 0;
  char* err = nullptr;
  const int rc = codec.encode(path.c_str(), image.width, image.height, image.rgba.data(), &encoded, &size, &err);
  if (rc == 1) throw InputError(path + ": no image writer for this file extension that can encode in memory (use .png)");
  if (rc != 0) throw InputError(path + ": cannot encode image: " + take_codec_message(codec, err));
  std::vector<uint8_t> bytes(encoded, encoded + size);
  codec.free(encoded);
  return bytes;
}

void save_image(const std::string& path, const Image& image) {
  const std::vector<uint8_t> bytes = encode_image(path, image);
  FileWriter file(path);
  file.write(bytes.data(), bytes.size());
  file.commit();
}

}  // namespace arc
