#include "test_helpers.h"

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "game/sim/capital.h"

namespace arc::test {

std::string write_level(const std::string& name, const std::string& text) {
  // One folder per process: ctest runs test cases in parallel processes.
  auto dir = std::filesystem::temp_directory_path() / ("arcfire_test_game_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::string path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string level_text(const std::string& ships_json, const std::string& extra) {
  return R"({
  "name": "test",
  "seed": 7,
  "objective": "test",
  "win": { "type": "destroy_all_hostiles" },
  "lose": { "type": "none" },)" +
         extra + R"(
  "ships": [)" + ships_json + R"(]
})";
}

ShipId ship_named(const World& w, const std::string& name) {
  for (const Ship& s : w.ships)
    if (s.name == name) return s.id;
  return {};
}

size_t part_index(const Ship& s, const std::string& name) {
  for (size_t i = 0; i < s.cls->part_count(); ++i)
    if (part_name(*s.cls, i) == name) return i;
  return size_t(-1);
}

}  // namespace arc::test
