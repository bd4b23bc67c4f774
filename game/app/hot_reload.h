// game/app/hot_reload.h — the window's hot reload: the files tweakers edit, polled twice a
// second, each changed group reloaded by the action given for it, a failure kept on screen.
//
// Shaders and sounds reload in place, data (levels, ship classes, effects) restarts the level;
// the window loop supplies each action (FileWatcher has the groups). An action returns "" or
// the error that kept the last good version running; that error is shown until a reload of
// any group succeeds. Each reload is one line on stdout ("arcfire: shaders reloaded").
//
// Example, compiled as HotReload.ReloadsChangedGroups in tests/unit/app/test_hot_reload.cpp:
//   HotReload reload({reload_shaders, reload_sounds, restart_level});  // each returns "" or its error
//   reload.watch(dir + "/shaders", HotReload::Group::Shaders);
//   reload.update(now);  // every frame: polls at most every half second
//   hud.error_banner = reload.banner();
#pragma once
#include <functional>
#include <string>
#include <utility>

#include "game/app/file_watcher.h"

namespace arc {

class HotReload {
 public:
  enum class Group { Shaders, Sounds, Data };
  struct Actions {
    std::function<std::string()> shaders, sounds, data;
  };
  static constexpr double kPollSeconds = 0.5;

  explicit HotReload(Actions actions) : actions_(std::move(actions)) {}
  // A file, or every file of a folder (one level deep). Watch everything before the first
  // update(), which only notes the files as they are.
  void watch(const std::string& path, Group group);
  // Polls when `now` (seconds) has reached the next poll time, then reloads what changed.
  void update(double now);
  const std::string& error() const { return error_; }
  // The on-screen line: "reload failed: ..." or "".
  std::string banner() const { return error_.empty() ? "" : "reload failed: " + error_; }

 private:
  Actions actions_;
  FileWatcher watcher_;
  std::string error_;
  double next_poll_ = 0;
};

}  // namespace arc
