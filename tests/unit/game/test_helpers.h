// Shared scenes for the game tests: levels written in memory against the real ship classes.
#pragma once
#include <string>

#include "game/sim/game.h"
#include "game/sim/world.h"
#include "core/data_root.h"

namespace arc::test {

inline GameOptions options() {
  GameOptions o;
  o.root_dir = arc::data_root();
  return o;
}

// A file of the source tree (the game's levels and the tests' own), found through the build.
inline std::string repo(const std::string& rel) { return arc::build_source_tree() + "/" + rel; }

// A level file in the build's temporary folder, so Game::load_level reads it like any other.
std::string write_level(const std::string& name, const std::string& text);

// Ships: "name class team ai x y z yaw" rows become a level with destroy_all_hostiles.
std::string level_text(const std::string& ships_json, const std::string& extra = "");

// The ship the level names `name` (an invalid id when none does).
ShipId ship_named(const World& w, const std::string& name);

// The index of a capital ship's turret or subsystem by its name (size_t(-1) when it has none).
size_t part_index(const Ship& s, const std::string& name);

}  // namespace arc::test
