// The PNG-only codec module (stb_image, assets/codec/png_codec.cpp) against the OpenImageIO
// module: both are loaded with dlopen, as the game loads either, and must decode every PNG the
// game reads, and PNGs of every channel count and bit depth, to the same bytes. The GPU
// benchmark runs with the PNG module (tools/gpu/pack.sh), so its sprites must be these bytes.
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "assets/codec/image_codec_abi.h"
#include "oiio_write.h"
#include "test_util.h"

namespace arc {
namespace {

struct Module {
  explicit Module(const char* path) {
    handle = ::dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!handle) return;
    open = reinterpret_cast<decltype(open)>(::dlsym(handle, "arc_codec_open"));
    read = reinterpret_cast<decltype(read)>(::dlsym(handle, "arc_codec_read"));
    close = reinterpret_cast<decltype(close)>(::dlsym(handle, "arc_codec_close"));
    encode = reinterpret_cast<decltype(encode)>(::dlsym(handle, "arc_codec_encode"));
    release = reinterpret_cast<decltype(release)>(::dlsym(handle, "arc_codec_free"));
    version = reinterpret_cast<decltype(version)>(::dlsym(handle, "arc_codec_abi_version"));
  }
  bool ok() const { return handle && open && read && close && encode && release && version; }

  struct Decoded {
    bool ok = false;
    int w = 0, h = 0, channels = 0;
    std::vector<unsigned char> pixels;
    std::string error;
  };
  Decoded decode(const std::string& bytes, const char* format, const std::string& name) const {
    Decoded d;
    char* err = nullptr;
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    ArcCodecReader* r = open(data, bytes.size(), format, name.c_str(), &d.w, &d.h, &d.channels, &err);
    if (!r) {
      d.error = err ? err : "";
      release(err);
      return d;
    }
    d.pixels.assign(size_t(d.w) * size_t(d.h) * size_t(d.channels), 0);
    d.ok = read(r, d.channels, d.pixels.data(), &err) != 0;
    if (!d.ok) d.error = err ? err : "";
    release(err);
    close(r, d.ok ? 1 : 0);
    return d;
  }

  void* handle = nullptr;
  ArcCodecReader* (*open)(const unsigned char*, size_t, const char*, const char*, int*, int*, int*, char**) = nullptr;
  int (*read)(ArcCodecReader*, int, unsigned char*, char**) = nullptr;
  void (*close)(ArcCodecReader*, int) = nullptr;
  int (*encode)(const char*, int, int, const unsigned char*, unsigned char**, size_t*, char**) = nullptr;
  void (*release)(void*) = nullptr;
  int (*version)() = nullptr;
};

const Module& oiio() {
  static const Module m(ARCFIRE_OIIO_CODEC_PATH);
  return m;
}
const Module& png() {
  static const Module m(ARCFIRE_PNG_CODEC_PATH);
  return m;
}

std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

template <typename T>
std::string write_png(const std::filesystem::path& path, int w, int h, int channels, OIIO::TypeDesc type,
                      const std::vector<T>& pixels) {
  return file_bytes(test::write_raw(path, w, h, channels, type, pixels));
}

void expect_same_decoding(const std::string& bytes, const std::string& name) {
  const Module::Decoded a = oiio().decode(bytes, "png", name);
  const Module::Decoded b = png().decode(bytes, "png", name);
  ASSERT_TRUE(a.ok) << name << ": " << a.error;
  ASSERT_TRUE(b.ok) << name << ": " << b.error;
  EXPECT_EQ(b.w, a.w) << name;
  EXPECT_EQ(b.h, a.h) << name;
  EXPECT_EQ(b.channels, a.channels) << name;
  ASSERT_EQ(b.pixels.size(), a.pixels.size()) << name;
  size_t differ = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) differ += a.pixels[i] != b.pixels[i];
  EXPECT_EQ(differ, 0u) << name << ": " << differ << " of " << a.pixels.size() << " samples differ";
}

TEST(PngCodec, BothModulesLoadWithTheSameInterface) {
  ASSERT_TRUE(oiio().ok()) << ARCFIRE_OIIO_CODEC_PATH << ": " << ::dlerror();
  ASSERT_TRUE(png().ok()) << ARCFIRE_PNG_CODEC_PATH << ": " << ::dlerror();
  EXPECT_EQ(png().version(), ARC_CODEC_ABI_VERSION);
}

TEST(PngCodec, EveryGamePngDecodesToTheOpenImageIoBytes) {
  ASSERT_TRUE(oiio().ok() && png().ok());
  int files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator("assets")) {
    if (e.path().extension() != ".png") continue;
    expect_same_decoding(file_bytes(e.path()), e.path().string());
    ++files;
  }
  EXPECT_GE(files, 7);  // the hull textures and the sprites
}

TEST(PngCodec, EveryChannelCountAndSixteenBitsDecodeAlike) {
  ASSERT_TRUE(oiio().ok() && png().ok());
  const auto dir = test::scratch_dir();
  std::vector<uint8_t> narrow;
  std::vector<uint16_t> wide;
  for (int i = 0; i < 7 * 5 * 4; ++i) {
    narrow.push_back(uint8_t((i * 37 + 11) & 255));
    wide.push_back(uint16_t((i * 40503u + 7u) & 0xffffu));  // low bytes that round up and down
  }
  for (int c = 1; c <= 4; ++c) {
    const std::vector<uint8_t> n8(narrow.begin(), narrow.begin() + 7 * 5 * c);
    const std::vector<uint16_t> n16(wide.begin(), wide.begin() + 7 * 5 * c);
    const std::string tag = std::to_string(c) + "ch";
    expect_same_decoding(write_png(dir / (tag + "8.png"), 7, 5, c, OIIO::TypeDesc::UINT8, n8), tag + " 8-bit");
    expect_same_decoding(write_png(dir / (tag + "16.png"), 7, 5, c, OIIO::TypeDesc::UINT16, n16), tag + " 16-bit");
  }
}

TEST(PngCodec, EncodedPngReadsBackExactlyThroughOpenImageIo) {
  ASSERT_TRUE(oiio().ok() && png().ok());
  std::vector<unsigned char> rgba;
  for (int i = 0; i < 9 * 4 * 4; ++i) rgba.push_back((unsigned char)((i * 53 + 5) & 255));
  unsigned char* bytes = nullptr;
  size_t size = 0;
  char* err = nullptr;
  ASSERT_EQ(png().encode("frame.png", 9, 4, rgba.data(), &bytes, &size, &err), 0) << (err ? err : "");
  const std::string encoded(reinterpret_cast<char*>(bytes), size);
  png().release(bytes);
  const Module::Decoded d = oiio().decode(encoded, "png", "frame.png");
  ASSERT_TRUE(d.ok) << d.error;
  EXPECT_EQ(d.w, 9);
  EXPECT_EQ(d.h, 4);
  EXPECT_EQ(d.channels, 4);
  EXPECT_EQ(d.pixels, rgba);
  // No writer for another format: the caller says so, as with OpenImageIO's in-memory writers.
  EXPECT_EQ(png().encode("frame.exr", 9, 4, rgba.data(), &bytes, &size, &err), 1);
}

TEST(PngCodec, OtherFormatsAndDamagedBytesAreRefusedWithAMessage) {
  ASSERT_TRUE(png().ok());
  const std::string good = file_bytes("assets/textures/sprite_glow.png");
  Module::Decoded d = png().decode(good, "jpg", "a.jpg");
  EXPECT_FALSE(d.ok);
  EXPECT_NE(d.error.find("PNG only"), std::string::npos) << d.error;
  d = png().decode("GIF89a not a png", "png", "b.png");
  EXPECT_FALSE(d.ok);
  EXPECT_NE(d.error.find("no PNG signature"), std::string::npos) << d.error;
  std::string cut = good.substr(0, good.size() / 2);
  d = png().decode(cut, "png", "c.png");
  EXPECT_FALSE(d.ok);
  EXPECT_FALSE(d.error.empty());
}

}  // namespace
}  // namespace arc
