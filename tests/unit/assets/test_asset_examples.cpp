// The usage examples of engine/assets' header banners as tests (HeaderExamples.MatchTheirTests
// keeps each banner and its test the same text).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "assets/gltf_claims.h"
#include "assets/image.h"
#include "assets/image_codec.h"
#include "assets/model.h"
#include "assets/screenshot_writer.h"
#include "core/json.h"

namespace arc {
namespace {

std::string scratch(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

TEST(AssetExamples, LoadAndSaveAnImage) {
  const std::string out_dir = scratch("asset_examples_image");
  arc::Image smoke = arc::load_sprite("assets/textures/sprite_smoke.png");
  arc::save_image(out_dir + "/smoke.png", smoke);
  EXPECT_TRUE(smoke.premultiplied);
  const Image back = load_image(out_dir + "/smoke.png");
  EXPECT_EQ(back.width, smoke.width);
  EXPECT_EQ(back.height, smoke.height);
}

TEST(AssetExamples, DecodeThroughTheModule) {
  const std::string name = "assets/textures/sprite_smoke.png";
  const std::string bytes = read_text_file(name);
  const unsigned char* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const size_t size = bytes.size();
  int w = 0, h = 0, channels = 0;
  const ImageCodec& codec = image_codec();
  char* err = nullptr;
  ArcCodecReader* r = codec.open(data, size, "png", name.c_str(), &w, &h, &channels, &err);
  if (!r) throw InputError(name + ": not a readable image: " + take_codec_message(codec, err));
  std::vector<unsigned char> pixels(size_t(w) * size_t(h) * 4);
  const int ok = codec.read(r, 4, pixels.data(), &err);
  codec.close(r, ok);
  EXPECT_EQ(ok, 1) << take_codec_message(codec, err);
  EXPECT_GT(w, 0);
  EXPECT_GT(h, 0);
}

TEST(AssetExamples, LoadAModel) {
  arc::ModelData ship = arc::load_model("assets/models/viper.glb");
  EXPECT_FALSE(ship.primitives.empty());
  EXPECT_GT(ship.radius, 0.0f);
}

TEST(AssetExamples, CheckGltfClaims) {
  const std::string json_text = R"({"asset": {"version": "2.0"}, "extensionsRequired": []})";
  check_gltf_claims(json_text.data(), json_text.size(), "ship.gltf");  // throws InputError
  const std::string old = R"({"asset": {"version": "1.0"}})";
  EXPECT_THROW(check_gltf_claims(old.data(), old.size(), "old.gltf"), InputError);
}

TEST(AssetExamples, ShotsInTheBackground) {
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(scratch("asset_examples_shots"));
  Image frame;
  frame.width = 4;
  frame.height = 2;
  frame.rgba.assign(4 * 2 * 4, 200);
  std::vector<std::string> notices;
  {
    ScreenshotWriter shots("out/screenshots", "arcfire");
    std::string path = shots.save(frame);            // out/screenshots/arcfire_0001.png
    EXPECT_EQ(path, "out/screenshots/arcfire_0001.png");
    while (notices.empty()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      for (const ScreenshotWriter::Done& d : shots.finished())
        notices.push_back(d.error.empty() ? "saved " + d.path : d.error);
    }
  }
  EXPECT_EQ(notices, std::vector<std::string>{"saved out/screenshots/arcfire_0001.png"});
  const bool written = std::filesystem::exists("out/screenshots/arcfire_0001.png");
  std::filesystem::current_path(cwd);
  EXPECT_TRUE(written);
}

}  // namespace
}  // namespace arc
