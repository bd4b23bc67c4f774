#include <gtest/gtest.h>

#include "core/error.h"
#include "replay/hash_log.h"
#include "replay/image_diff.h"

using namespace arc::replay;

TEST(HashLog, RoundTrip) {
  HashLog log{{1, 0xffffffffffffffffULL, 0x1234}};
  HashLog back = parse_hash_log(write_hash_log(log), "h.txt");
  EXPECT_EQ(back.hashes, log.hashes);
}

TEST(HashLog, BadLinesArePositioned) {
  auto err = [](const std::string& t) {
    try {
      parse_hash_log(t, "h.txt");
    } catch (const arc::InputError& e) {
      return std::string(e.what());
    }
    return std::string("(none)");
  };
  EXPECT_EQ(err("nope\n").rfind("h.txt:1:1: a hash log starts with", 0), 0u);
  EXPECT_EQ(err("arcfire-hashlog 1\n0 1\n2 3\n").rfind("h.txt:3:1: expected tick 1, got 2", 0), 0u);
  EXPECT_EQ(err("arcfire-hashlog 1\n0 zz\n").rfind("h.txt:2:3: hash must be", 0), 0u);
}

namespace {
std::vector<uint8_t> flat(int w, int h, uint8_t v) { return std::vector<uint8_t>(size_t(w) * h * 4, v); }
}  // namespace

TEST(ImageDiff, WithinToleranceEverywherePasses) {
  auto a = flat(100, 100, 100), b = flat(100, 100, 105);
  ImageDiff d = compare_rgba8(a, b, 100, 100);
  EXPECT_TRUE(d.passed);
  EXPECT_EQ(d.failing_pixels, 0u);
  EXPECT_EQ(d.max_diff, 5);
}

TEST(ImageDiff, TenFailingPixelsOfTenThousandPassOnlyAtTheLimit) {
  auto a = flat(100, 100, 100), b = flat(100, 100, 100);
  for (int i = 0; i < 10; ++i) b[size_t(i) * 4 + 1] = 200;  // 0.1% of pixels
  EXPECT_TRUE(compare_rgba8(a, b, 100, 100).passed);
  b[10 * 4 + 2] = 0;  // one more: 0.11%
  ImageDiff d = compare_rgba8(a, b, 100, 100);
  EXPECT_FALSE(d.passed);
  EXPECT_EQ(d.failing_pixels, 11u);
  EXPECT_EQ(d.max_diff, 100);
  EXPECT_EQ(d.diff_rgba[0], 255);       // failing pixels are red
  EXPECT_EQ(d.diff_rgba[1], 0);
  EXPECT_NE(d.describe().find("11 of 10000 pixels"), std::string::npos) << d.describe();
}

TEST(ImageDiff, SixOffFailsEveryPixel) {
  ImageDiff d = compare_rgba8(flat(4, 4, 0), flat(4, 4, 6), 4, 4);
  EXPECT_FALSE(d.passed);
  EXPECT_EQ(d.failing_pixels, 16u);
}

TEST(ImageDiff, SizeMismatchThrows) {
  EXPECT_THROW(compare_rgba8(flat(4, 4, 0), flat(4, 5, 0), 4, 4), std::invalid_argument);
}
