// ScreenshotWriter (assets/screenshot_writer.h): shots taken faster than they are written get
// distinct numbers after the ones already in the folder, every one is on disk with its pixels
// once the writer is gone, finished() reports each exactly once without blocking, and a shot
// that cannot be written comes back as one line naming its file instead of an exception.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "assets/image.h"
#include "assets/screenshot_writer.h"
#include "core/file_writer.h"

namespace arc {
namespace {

namespace fs = std::filesystem;

Image gradient(int w, int h, uint8_t seed) {
  Image img;
  img.width = w;
  img.height = h;
  img.rgba.resize(size_t(w) * size_t(h) * 4);
  for (size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = uint8_t(i * 7 + seed);
  for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
  return img;
}

fs::path scratch(const char* name) {
  const fs::path dir = fs::temp_directory_path() / ("arcfire_screenshot_writer_" + std::string(name));
  fs::remove_all(dir);
  return dir;
}

TEST(ScreenshotWriter, QuickShotsTakeTheNextFreeNumbersAndAllReachTheDisk) {
  const fs::path dir = scratch("numbers");
  fs::create_directories(dir);
  write_file_checked((dir / "arcfire_0001.png").string(), "taken");  // a shot from an earlier run of the game
  std::set<std::string> paths;
  std::vector<Image> images;
  {
    ScreenshotWriter shots(dir.string(), "arcfire");
    for (int i = 0; i < 4; ++i) {
      images.push_back(gradient(320, 180, uint8_t(i * 40)));
      paths.insert(shots.save(images.back()));  // one after the other, before any is written
    }
    EXPECT_LE(shots.pending(), 4);
  }  // the destructor waits for them
  const std::set<std::string> expected = {(dir / "arcfire_0002.png").string(), (dir / "arcfire_0003.png").string(),
                                          (dir / "arcfire_0004.png").string(), (dir / "arcfire_0005.png").string()};
  EXPECT_EQ(paths, expected);
  for (int i = 0; i < 4; ++i) {
    const Image back = load_image((dir / ("arcfire_000" + std::to_string(i + 2) + ".png")).string());
    ASSERT_EQ(back.width, 320);
    EXPECT_EQ(back.rgba, images[size_t(i)].rgba) << "shot " << i;
  }
  fs::remove_all(dir);
}

TEST(ScreenshotWriter, FinishedReportsEachShotOnceAndWaitReturnsTheRest) {
  const fs::path dir = scratch("finished");
  ScreenshotWriter shots(dir.string(), "workbench");  // the folder is made by the first shot
  const std::string first = shots.save(gradient(64, 32, 1));
  const std::string second = shots.save(gradient(64, 32, 2));
  EXPECT_NE(first, second);
  std::vector<std::string> reported;
  for (const ScreenshotWriter::Done& d : shots.wait()) {
    EXPECT_TRUE(d.error.empty()) << d.error;
    reported.push_back(d.path);
  }
  EXPECT_EQ(reported, (std::vector<std::string>{first, second}));
  EXPECT_EQ(shots.pending(), 0);
  EXPECT_TRUE(shots.finished().empty());
  EXPECT_TRUE(fs::exists(first) && fs::exists(second));
  fs::remove_all(dir);
}

TEST(ScreenshotWriter, AShotThatCannotBeWrittenIsOneLineNamingItsFile) {
  const fs::path dir = scratch("blocked");
  fs::create_directories(dir.parent_path());
  write_file_checked(dir.string(), "a file where the folder should be");
  ScreenshotWriter shots(dir.string(), "arcfire");
  const std::string path = shots.save(gradient(16, 16, 3));
  const std::vector<ScreenshotWriter::Done> done = shots.wait();
  ASSERT_EQ(done.size(), 1u);
  EXPECT_EQ(done[0].path, path);
  EXPECT_NE(done[0].error.find(path), std::string::npos) << done[0].error;
  EXPECT_EQ(done[0].error.find('\n'), std::string::npos) << done[0].error;
  fs::remove(dir);
}

}  // namespace
}  // namespace arc
