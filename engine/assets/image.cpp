// assets/image.cpp — images through OpenImageIO, always handed out as RGBA8.
#include <algorithm>
#include <cstdio>
#include <fcntl.h>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include "assets/image_decode.h"
#include "assets/image.h"
#include "core/error.h"
#include "core/file_writer.h"
#include "core/input_limits.h"

namespace arc {
namespace {

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

Image read_rgba8(OIIO::ImageInput& in, const std::string& path) {
  const OIIO::ImageSpec& spec = in.spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.width > kMaxImageSide || spec.height > kMaxImageSide)
    throw InputError(path + ": image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                     " is not allowed (1 to " + std::to_string(kMaxImageSide) + " pixels per side)");
  // Larger images are certainly a mistake for a game asset and would only exhaust memory.
  if (size_t(spec.width) * size_t(spec.height) * 4 > kMaxImageDecodedBytes)
    throw InputError(path + ": image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                     " decodes to more than " + std::to_string(kMaxImageDecodedBytes >> 20) + " MiB of RGBA8, the limit");
  const int channels = spec.nchannels;
  if (channels < 1 || channels > 4)
    throw InputError(path + ": image has " + std::to_string(channels) + " channels; 1 to 4 are supported");
  std::vector<uint8_t> pixels(size_t(spec.width) * size_t(spec.height) * size_t(channels));
  // OIIO converts 16-bit, half and float data to UINT8 itself (clamped, rounded).
  if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data()))
    throw InputError(path + ": cannot decode image: " + in.geterror());
  Image img;
  img.width = spec.width;
  img.height = spec.height;
  img.rgba.resize(size_t(spec.width) * size_t(spec.height) * 4);
  const size_t n = size_t(spec.width) * size_t(spec.height);
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
  if (!std::filesystem::is_regular_file(path)) throw InputError(path + ": cannot read file (missing or not a file)");
  check_file_size(path, kMaxImageFileBytes, "an image");
  // Decoded from memory, exactly as the fuzz target feeds it (tests/fuzz/fuzz_sprite.cpp).
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw InputError(path + ": cannot read file");
  return decode_image_memory(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), path);
}

Image decode_image_memory(const uint8_t* data, size_t size, const std::string& name) {
  check_text_size(size, name, kMaxImageFileBytes, "an image");
  const QuietStderr quiet;
  OIIO::Filesystem::IOMemReader reader(const_cast<uint8_t*>(data), size);
  // The reader is the one for the name's extension, made from the bare extension: given a name,
  // OIIO tries every other format it has (JPEG 2000, OpenVDB, GDAL, video...) on bytes that are
  // not what the extension says, and one of those hung on a fuzzed PNG. The bytes come from the
  // proxy, never a file.
  const std::string ext = std::filesystem::path(name).extension().string();
  if (ext.size() < 2) throw InputError(name + ": an image name needs an extension saying its format (.png, .jpg...)");
  auto in = OIIO::ImageInput::create(ext.substr(1), false, &raw_alpha_config());
  OIIO::ImageSpec spec;
  if (!in || !in->set_ioproxy(&reader) || !in->open(name, spec, raw_alpha_config()))
    throw InputError(name + ": not a readable image: " + (in ? in->geterror() : OIIO::geterror()));
  try {
    Image img = read_rgba8(*in, name);
    in->close();
    return img;
  } catch (const InputError&) {
    // A failed read can leave a second message pending ("PNG library error"), which OIIO
    // prints to stderr when the reader is destroyed; it is in our message already.
    in->geterror();
    OIIO::geterror();
    throw;
  }
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
  // Encoded in memory: OIIO's own file writes (libpng's fwrite) go unchecked, so the bytes
  // reach the disk through core/file_writer.h instead. The encoder is chosen by extension.
  std::vector<uint8_t> bytes;
  OIIO::Filesystem::IOVecOutput sink(bytes);
  auto out = OIIO::ImageOutput::create(path, &sink);
  if (!out || !out->supports("ioproxy"))
    throw InputError(path + ": no image writer for this file extension that can encode in memory (use .png)");
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->set_ioproxy(&sink) || !out->open(path, spec) ||
      !out->write_image(OIIO::TypeDesc::UINT8, image.rgba.data()) || !out->close())
    throw InputError(path + ": cannot encode image: " + out->geterror());
  return bytes;
}

void save_image(const std::string& path, const Image& image) {
  const std::vector<uint8_t> bytes = encode_image(path, image);
  FileWriter file(path);
  file.write(bytes.data(), bytes.size());
  file.commit();
}

}  // namespace arc
