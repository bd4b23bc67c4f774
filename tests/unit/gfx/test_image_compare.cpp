// image_compare: the golden tolerance rule (max channel difference, fraction of pixels), size
// mismatches and the amplified difference image. No GL context needed.
#include <gtest/gtest.h>

#include "gfx/image_compare.h"

namespace arc {
namespace {

Image flat(int w, int h, uint8_t v) {
  Image img;
  img.width = w;
  img.height = h;
  img.rgba.assign(size_t(w) * h * 4, v);
  return img;
}

TEST(ImageCompare, IdenticalImagesMatch) {
  ImageDiff d = compare_images(flat(10, 10, 40), flat(10, 10, 40));
  EXPECT_TRUE(d.passed);
  EXPECT_EQ(d.max_diff, 0);
}

TEST(ImageCompare, ToleranceAndFractionRule) {
  Image a = flat(100, 10, 100), b = a;  // 1000 pixels: one may be off, two may not
  b.rgba[0] = 106;
  EXPECT_TRUE(compare_images(a, b).passed);
  b.rgba[4] = 106;
  ImageDiff d = compare_images(a, b);
  EXPECT_FALSE(d.passed);
  EXPECT_EQ(d.max_diff, 6);
  Image c = a;
  for (size_t i = 0; i < c.rgba.size(); i += 4) c.rgba[i] = 105;  // within 5/255 everywhere
  EXPECT_TRUE(compare_images(a, c).passed);
}

TEST(ImageCompare, SizeMismatchFails) {
  ImageDiff d = compare_images(flat(4, 4, 0), flat(4, 5, 0));
  EXPECT_FALSE(d.passed);
  EXPECT_TRUE(d.size_mismatch);
}

TEST(ImageCompare, DifferenceImageAmplifies) {
  Image a = flat(2, 1, 10), b = flat(2, 1, 12);
  Image d = difference_image(a, b);
  EXPECT_EQ(d.rgba[0], 16);
  EXPECT_EQ(d.rgba[3], 255);
}

}  // namespace
}  // namespace arc
