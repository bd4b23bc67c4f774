// Hot reload (game/app/hot_reload.h) without a window: files in a temporary folder are
// changed, and the next poll calls the action of their group and keeps its error on screen.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "game/app/hot_reload.h"
#include "game/render/hud_layout.h"

namespace arc {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// A change the watcher sees whatever the file system's time resolution.
void touch(const fs::path& p) { fs::last_write_time(p, fs::last_write_time(p) + std::chrono::seconds(5)); }

TEST(HotReload, ReloadsChangedGroups) {
  const std::string dir = (fs::temp_directory_path() / ("arcfire_hot_reload_" + std::to_string(::getpid()))).string();
  fs::remove_all(dir);
  fs::create_directories(dir + "/shaders");
  fs::create_directories(dir + "/levels");
  write(dir + "/shaders/hud.frag", "void main() {}");
  write(dir + "/levels/duel.json", "{}");
  write(dir + "/sounds.json", "{}");
  int shaders = 0, sounds = 0, levels = 0;
  std::string level_error;
  auto reload_shaders = [&] { ++shaders; return std::string(); };
  auto reload_sounds = [&] { ++sounds; return std::string(); };
  auto restart_level = [&] { ++levels; return level_error; };
  double now = 0;
  HudState hud;

  HotReload reload({reload_shaders, reload_sounds, restart_level});  // each returns "" or its error
  reload.watch(dir + "/shaders", HotReload::Group::Shaders);
  reload.watch(dir + "/sounds.json", HotReload::Group::Sounds);
  reload.watch(dir + "/levels", HotReload::Group::Data);
  reload.update(now);  // every frame: polls at most every half second
  hud.error_banner = reload.banner();

  EXPECT_EQ(shaders + sounds + levels, 0) << "the first poll only notes the files";
  touch(dir + "/shaders/hud.frag");
  now = 0.2;
  reload.update(now);
  EXPECT_EQ(shaders, 0) << "polled again only after half a second";
  testing::internal::CaptureStdout();
  now = 0.5;
  reload.update(now);
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "arcfire: shaders reloaded\n");
  EXPECT_EQ(shaders, 1);
  EXPECT_EQ(sounds + levels, 0);

  // A level that fails to load: its error stays until a reload succeeds.
  level_error = "duel.json:1:1: expected an object";
  write(dir + "/levels/skirmish.json", "[]");  // a new file counts as a change too
  now = 1.0;
  reload.update(now);
  EXPECT_EQ(levels, 1);
  EXPECT_EQ(reload.banner(), "reload failed: duel.json:1:1: expected an object");
  touch(dir + "/sounds.json");
  now = 1.5;
  testing::internal::CaptureStdout();
  reload.update(now);
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "arcfire: sounds reloaded\n");
  EXPECT_EQ(sounds, 1);
  EXPECT_EQ(reload.banner(), "");
  level_error.clear();
  fs::remove(dir + "/levels/skirmish.json");
  now = 2.0;
  testing::internal::CaptureStdout();
  reload.update(now);
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "arcfire: data changed, level restarted\n");
  EXPECT_EQ(levels, 2);
  now = 2.5;
  reload.update(now);
  EXPECT_EQ(shaders + sounds + levels, 4) << "nothing changed";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace arc
