#include "core/log.h"

#include <cstdio>

namespace arc {
namespace {
LogLevel g_level = LogLevel::Warn;
const char* level_name(LogLevel l) {
  switch (l) {
    case LogLevel::Error: return "error";
    case LogLevel::Warn: return "warning";
    case LogLevel::Info: return "info";
    case LogLevel::Debug: return "debug";
  }
  return "";
}
}  // namespace

void set_log_level(LogLevel level) { g_level = level; }
LogLevel log_level() { return g_level; }
void log(LogLevel level, std::string_view message) {
  if (level > g_level) return;
  std::fprintf(stderr, "arcfire: %s: %.*s\n", level_name(level), int(message.size()), message.data());
}

}  // namespace arc
