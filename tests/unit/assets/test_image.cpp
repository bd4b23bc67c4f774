// Images: channel and bit-depth conversion to RGBA8, exact premultiplication (Ilmonen eq. 10),
// atomic PNG save and round trip, errors, and the generated sprites.
#include <cmath>
#include <string>
#include <vector>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include "assets/image.h"
#include "core/error.h"
#include "oiio_write.h"
#include "test_util.h"
#include "core/data_root.h"

namespace arc {
namespace {

using test::write_raw;

std::vector<uint8_t> pixel(const Image& img, int x, int y) {
  const size_t at = (size_t(y) * size_t(img.width) + size_t(x)) * 4;
  return {img.rgba[at], img.rgba[at + 1], img.rgba[at + 2], img.rgba[at + 3]};
}

using Px = std::vector<uint8_t>;

TEST(LoadImage, OneChannelGreyBecomesOpaqueRgb) {
  const auto dir = test::scratch_dir();
  const Image img = load_image(write_raw<uint8_t>(dir / "grey.png", 2, 1, 1, OIIO::TypeDesc::UINT8, {7, 200}));
  ASSERT_EQ(img.width, 2);
  ASSERT_EQ(img.height, 1);
  EXPECT_EQ(pixel(img, 0, 0), (Px{7, 7, 7, 255}));
  EXPECT_EQ(pixel(img, 1, 0), (Px{200, 200, 200, 255}));
  EXPECT_FALSE(img.premultiplied);
}

TEST(LoadImage, TwoChannelGreyAlpha) {
  const auto dir = test::scratch_dir();
  const Image img = load_image(write_raw<uint8_t>(dir / "ga.png", 1, 1, 2, OIIO::TypeDesc::UINT8, {90, 40}));
  EXPECT_EQ(pixel(img, 0, 0), (Px{90, 90, 90, 40}));
}

TEST(LoadImage, ThreeChannelsGetOpaqueAlphaAndRowsStayTopToBottom) {
  const auto dir = test::scratch_dir();
  const Image img =
      load_image(write_raw<uint8_t>(dir / "rgb.png", 1, 2, 3, OIIO::TypeDesc::UINT8, {10, 20, 30, 40, 50, 60}));
  EXPECT_EQ(pixel(img, 0, 0), (Px{10, 20, 30, 255}));
  EXPECT_EQ(pixel(img, 0, 1), (Px{40, 50, 60, 255}));
}

TEST(LoadImage, FourChannelsKeepStraightAlphaExactly) {
  const auto dir = test::scratch_dir();
  // Colour under low and zero alpha must survive: OIIO would otherwise (un)premultiply.
  const Image img = load_image(
      write_raw<uint8_t>(dir / "rgba.png", 2, 1, 4, OIIO::TypeDesc::UINT8, {255, 128, 3, 1, 90, 80, 70, 0}));
  EXPECT_EQ(pixel(img, 0, 0), (Px{255, 128, 3, 1}));
  EXPECT_EQ(pixel(img, 1, 0), (Px{90, 80, 70, 0}));
}

TEST(LoadImage, SixteenBitIsScaledTo8Bit) {
  const auto dir = test::scratch_dir();
  const Image img = load_image(write_raw<uint16_t>(dir / "deep.png", 1, 1, 4, OIIO::TypeDesc::UINT16,
                                                   {0, 65535, 128 * 257, 257}));
  EXPECT_EQ(pixel(img, 0, 0), (Px{0, 255, 128, 1}));
}

TEST(LoadImage, FloatIsClampedAndScaled) {
  const auto dir = test::scratch_dir();
  const Image img = load_image(write_raw<float>(dir / "hdr.tif", 1, 1, 3, OIIO::TypeDesc::FLOAT, {-1.0f, 2.0f, 0.2f}));
  EXPECT_EQ(pixel(img, 0, 0), (Px{0, 255, 51, 255}));
}

TEST(LoadImage, CorruptPngAnswersWithOneLineAndPrintsNothing) {
  // Found by tests/fuzz (sprite): libpng printed its own lines to stderr beside the error.
  const std::string path = arc::build_source_tree() + "/tests/fuzz/regression/sprite/idat_bad_code_lengths.png";
  testing::internal::CaptureStderr();
  try {
    load_image(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": cannot decode image: PNG read error: IDAT", 0), 0u) << e.what();
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

// Sides up to 16384 (every current GPU's texture limit) load; the RGBA8 budget, not the side,
// bounds the area (core/input_limits.h). Narrow strips keep the files cheap.
TEST(LoadImage, SidesUpTo16384LoadWithinTheByteBudget) {
  const auto dir = test::scratch_dir();
  const Image wide = load_image(write_raw<uint8_t>(dir / "wide.png", 16384, 2, 1, OIIO::TypeDesc::UINT8,
                                                   std::vector<uint8_t>(16384 * 2, 9)));
  EXPECT_EQ(wide.width, 16384);
  EXPECT_EQ(pixel(wide, 16383, 1), (Px{9, 9, 9, 255}));
  const Image tall = load_image(write_raw<uint8_t>(dir / "tall.png", 1, 8193, 1, OIIO::TypeDesc::UINT8,
                                                   std::vector<uint8_t>(8193, 3)));
  EXPECT_EQ(tall.height, 8193);
  auto error_of = [](const std::string& path) {
    try {
      load_image(path);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  const std::string over = write_raw<uint8_t>(dir / "over.png", 16385, 1, 1, OIIO::TypeDesc::UINT8,
                                              std::vector<uint8_t>(16385, 1));
  EXPECT_EQ(error_of(over), over + ": image size 16385x1 is not allowed (1 to 16384 pixels per side)");
  const std::string big = write_raw<uint8_t>(dir / "big.png", 16384, 2049, 1, OIIO::TypeDesc::UINT8,
                                             std::vector<uint8_t>(size_t(16384) * 2049, 0));
  EXPECT_EQ(error_of(big), big + ": image size 16384x2049 decodes to more than 128 MiB of RGBA8, the limit");
}

TEST(LoadImage, BadInputThrowsNamingTheFile) {
  const auto dir = test::scratch_dir();
  const std::string missing = (dir / "missing.png").string();
  try {
    load_image(missing);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(missing + ": ", 0), 0u) << e.what();
  }
  const std::string junk = (dir / "junk.png").string();
  test::write_bytes(junk, "\x89PNG\r\n\x1a\n this is the start of a png and then nothing");
  try {
    load_image(junk);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(junk + ": ", 0), 0u) << e.what();
  }
}

TEST(Premultiply, RoundsEveryValueToNearest) {
  // Every (colour, alpha) pair: tcola = round(tcol · talpha / 255).
  Image img;
  img.width = 256;
  img.height = 256;
  img.rgba.resize(256 * 256 * 4);
  for (int a = 0; a < 256; ++a)
    for (int c = 0; c < 256; ++c) {
      uint8_t* p = &img.rgba[(size_t(a) * 256 + size_t(c)) * 4];
      p[0] = uint8_t(c);
      p[1] = uint8_t(255 - c);
      p[2] = uint8_t(c / 2);
      p[3] = uint8_t(a);
    }
  premultiply(img);
  EXPECT_TRUE(img.premultiplied);
  for (int a = 0; a < 256; ++a)
    for (int c = 0; c < 256; ++c) {
      const uint8_t* p = &img.rgba[(size_t(a) * 256 + size_t(c)) * 4];
      ASSERT_EQ(p[0], std::lround(c * a / 255.0)) << c << " " << a;
      ASSERT_EQ(p[1], std::lround((255 - c) * a / 255.0));
      ASSERT_EQ(p[2], std::lround((c / 2) * a / 255.0));
      ASSERT_EQ(p[3], a);
    }
  EXPECT_EQ(img.rgba[(size_t(128) * 256 + 255) * 4], 128);  // white at half alpha
  EXPECT_EQ(img.rgba[(size_t(128) * 256 + 1) * 4], 1);      // 0.502 rounds up
  const std::vector<uint8_t> once = img.rgba;
  premultiply(img);  // already premultiplied: must not darken twice
  EXPECT_EQ(img.rgba, once);
}

TEST(LoadSprite, PremultipliesTheStoredStraightColour) {
  const auto dir = test::scratch_dir();
  const Image img = load_sprite(
      write_raw<uint8_t>(dir / "s.png", 2, 1, 4, OIIO::TypeDesc::UINT8, {255, 100, 10, 128, 200, 200, 200, 0}));
  EXPECT_TRUE(img.premultiplied);
  EXPECT_EQ(pixel(img, 0, 0), (Px{128, 50, 5, 128}));
  EXPECT_EQ(pixel(img, 1, 0), (Px{0, 0, 0, 0}));
}

TEST(SaveImage, RoundTripIsExactAndLeavesNoTemporaryFile) {
  const auto dir = test::scratch_dir();
  Image img;
  img.width = 17;
  img.height = 9;
  for (int i = 0; i < 17 * 9 * 4; ++i) img.rgba.push_back(uint8_t((i * 37 + i / 5) & 0xFF));
  const std::string path = (dir / "out.png").string();
  save_image(path, img);
  save_image(path, img);  // replacing an existing file works too
  const Image back = load_image(path);
  EXPECT_EQ(back.width, 17);
  EXPECT_EQ(back.height, 9);
  EXPECT_EQ(back.rgba, img.rgba);
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) files += entry.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 1u);
}

TEST(SaveImage, BadTargetsThrow) {
  const auto dir = test::scratch_dir();
  Image img;
  img.width = 2;
  img.height = 2;
  img.rgba.assign(16, 255);
  EXPECT_THROW(save_image((dir / "no_such_dir" / "x.png").string(), img), InputError);
  EXPECT_THROW(save_image((dir / "x.unknownformat").string(), img), InputError);
  img.rgba.resize(15);
  EXPECT_THROW(save_image((dir / "x.png").string(), img), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

class GeneratedSprite : public ::testing::TestWithParam<const char*> {};

TEST_P(GeneratedSprite, IsStraightAlpha128WithAZeroBorder) {
  const Image img = load_image(std::string("assets/textures/") + GetParam());
  ASSERT_EQ(img.width, 128);
  ASSERT_EQ(img.height, 128);
  int max_alpha = 0;
  bool colour_above_alpha = false;
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) {
      const Px p = pixel(img, x, y);
      max_alpha = std::max<int>(max_alpha, p[3]);
      if (x == 0 || y == 0 || x == 127 || y == 127) {
        EXPECT_EQ(p[3], 0) << x << "," << y;
      }
      if (p[3] > 0 && p[3] < 128 && std::max({p[0], p[1], p[2]}) > p[3] + 20) colour_above_alpha = true;
    }
  EXPECT_GT(max_alpha, 150);
  EXPECT_TRUE(colour_above_alpha) << "faint texels should keep their full colour (straight alpha)";
}

INSTANTIATE_TEST_SUITE_P(Assets, GeneratedSprite,
                         ::testing::Values("sprite_blob.png", "sprite_flare.png", "sprite_spark.png", "sprite_smoke.png",
                                           "sprite_shield.png", "sprite_glow.png"));

TEST(GeneratedSprite, SparkIsLongAlongY) {
  const Image img = load_image("assets/textures/sprite_spark.png");
  int wide = 0, tall = 0;
  for (int i = 0; i < 128; ++i) {
    wide += pixel(img, i, 64)[3] > 64 ? 1 : 0;
    tall += pixel(img, 64, i)[3] > 64 ? 1 : 0;
  }
  EXPECT_GT(tall, 4 * wide);
}

}  // namespace
}  // namespace arc

TEST(FlipRows, ReversesRowOrderOnly) {
  arc::Image img;
  img.width = 2;
  img.height = 3;
  for (int i = 0; i < 2 * 3 * 4; ++i) img.rgba.push_back(uint8_t(i));
  arc::flip_rows(img);
  EXPECT_EQ(img.rgba[0], 16);  // first row now holds the former last row
  EXPECT_EQ(img.rgba[8], 8);   // middle row stays
  EXPECT_EQ(img.rgba[16], 0);
  EXPECT_EQ(img.rgba[7], 23);
}
