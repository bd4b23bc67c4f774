// Shared scenes for the game tests: levels written in memory against the real ship classes.
#pragma once
#include <string>

#include "game/sim/game.h"
#include "game/sim/world.h"

namespace arc::test {

inline GameOptions options() {
  GameOptions o;
  o.root_dir = ARCFIRE_SOURCE_DIR;
  return o;
}

inline std::string repo(const std::string& rel) { return std::string(ARCFIRE_SOURCE_DIR) + "/" + rel; }

// A level file in the build's temporary folder, so Game::load_level reads it like any other.
std::string write_level(const std::string& name, const std::string& text);

// Ships: "name class team ai x y z yaw" rows become a level with destroy_all_hostiles.
std::string level_text(const std::string& ships_json, const std::string& extra = "");

}  // namespace arc::test
