// File watching by polled modification times, grouped so the window loop knows what to reload.
#include "game/app/file_watcher.h"

#include <set>

namespace arc {

void FileWatcher::watch(const std::string& path, const std::string& group) {
  std::error_code ec;
  roots_[path] = {group, std::filesystem::is_directory(path, ec)};
}

std::vector<std::string> FileWatcher::poll() {
  namespace fs = std::filesystem;
  std::map<std::string, fs::file_time_type> now;
  std::map<std::string, std::string> groups;
  for (const auto& [root, e] : roots_) {
    std::error_code ec;
    if (e.folder) {
      // Stepped with an error code: a folder that turns unreadable or into a loop stops the scan.
      for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
        if (!it->is_regular_file(ec)) continue;
        now[it->path().string()] = it->last_write_time(ec);
        groups[it->path().string()] = e.group;
      }
    } else if (fs::exists(root, ec)) {
      now[root] = fs::last_write_time(root, ec);
      groups[root] = e.group;
    }
  }
  std::set<std::string> changed;
  if (primed_) {
    for (const auto& [p, t] : now) {
      auto it = seen_.find(p);
      if (it == seen_.end() || it->second != t) changed.insert(groups[p]);
    }
    for (const auto& [p, t] : seen_)
      if (!now.count(p)) changed.insert(file_group_[p]);
  }
  primed_ = true;
  seen_ = std::move(now);
  file_group_ = std::move(groups);
  return {changed.begin(), changed.end()};
}

}  // namespace arc
