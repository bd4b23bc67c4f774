// game/app/file_watcher.h — notices edits to the files tweakers change while the game runs.
//
// Polls modification times (cheap: a few dozen stat calls, at most twice a second) of the
// level, the ship classes, the effects and the shaders. The window loop reloads what changed:
// shaders in place, data files by reloading the level; a file that fails to load keeps the last
// good version running and its error is shown on screen.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace arc {

class FileWatcher {
 public:
  // Files are watched directly; folders are scanned for their files (one level deep).
  void watch(const std::string& path, const std::string& group);
  // Groups with at least one file whose time or presence changed since the last call.
  std::vector<std::string> poll();

 private:
  struct Entry { std::string group; bool folder; };
  std::map<std::string, Entry> roots_;
  std::map<std::string, std::filesystem::file_time_type> seen_;
  std::map<std::string, std::string> file_group_;
  bool primed_ = false;
};

}  // namespace arc
