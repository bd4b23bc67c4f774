// Hot reload: a FileWatcher's changed groups to their reload actions, and the error kept.
#include "game/app/hot_reload.h"

#include <cstdio>

namespace arc {
namespace {

const char* group_name(HotReload::Group g) {
  switch (g) {
    case HotReload::Group::Shaders: return "shaders";
    case HotReload::Group::Sounds: return "sounds";
    case HotReload::Group::Data: return "data";
  }
  return "data";
}

}  // namespace

void HotReload::watch(const std::string& path, Group group) { watcher_.watch(path, group_name(group)); }

void HotReload::update(double now) {
  if (now < next_poll_) return;
  next_poll_ = now + kPollSeconds;
  for (const std::string& group : watcher_.poll()) {
    if (group == "shaders" || group == "sounds") {
      error_ = group == "shaders" ? actions_.shaders() : actions_.sounds();
      std::printf("arcfire: %s reloaded%s\n", group.c_str(), error_.empty() ? "" : " with errors (kept the old ones)");
    } else {
      // A level, ship or effect that fails to load keeps the last good version playing.
      error_ = actions_.data();
      if (error_.empty()) std::printf("arcfire: data changed, level restarted\n");
    }
    std::fflush(stdout);
  }
}

}  // namespace arc
