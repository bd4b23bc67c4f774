// A test image written with OpenImageIO directly (straight alpha kept), so the loaders and codec
// modules are tested against files they did not write themselves. Shared by the asset tests.
#pragma once
#include <filesystem>
#include <string>
#include <vector>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

namespace arc::test {

// Writes w×h pixels of `channels` samples of `type` to `path` (its extension picks the format)
// and returns the path.
template <typename T>
std::string write_raw(const std::filesystem::path& path, int w, int h, int channels, OIIO::TypeDesc type,
                      const std::vector<T>& pixels) {
  auto out = OIIO::ImageOutput::create(path.string());
  EXPECT_TRUE(out);
  OIIO::ImageSpec spec(w, h, channels, type);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  EXPECT_TRUE(out->open(path.string(), spec)) << out->geterror();
  EXPECT_TRUE(out->write_image(type, pixels.data())) << out->geterror();
  EXPECT_TRUE(out->close());
  return path.string();
}

}  // namespace arc::test
