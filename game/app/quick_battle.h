// game/app/quick_battle.h — the "Quick battle" setup: a battle built from the ship classes that exist.
//
// A QuickSetup (the player's ship, wingmen and enemies with their classes and counts, a capital
// ship on either side or none, asteroids, difficulty) becomes level JSON that goes through the
// same loader and validation as levels/*.json. The generated file is named by its content
// (DIR/quick/quick-HASH.json below the player's folder), so a recording that names it replays.
// The last setup is kept in DIR/quick_battle.json, written atomically; a bad file is kept as .bak
// and the default setup used, with a one-line message, as settings.json is.
//
// Classes come from assets/ships/*.json: a class with "turrets" or "subsystems" is a capital
// ship; a class that has thrust and a beam that does damage is a fighter. The rest (stations,
// freighters, training drones) are not offered.
//
// Example, compiled as QuickBattle.HeaderExample in tests/unit/app/test_quick_battle.cpp:
//   QuickClasses classes = quick_classes(".");
//   QuickSetup s;                 // a Viper and a wingman against four Darts, few asteroids
//   s.enemies = 6;
//   const std::string text = quick_level_json(s, classes);        // InputError for a bad setup
//   LevelDef def = parse_level_def(text, "quick.json", ".");      // the ordinary loader
#pragma once
#include <string>
#include <vector>

#include "game/sim/game.h"

namespace arc {

enum class QuickAsteroids { None = 0, Few = 1, Many = 2 };
const char* asteroids_name(QuickAsteroids a);

inline constexpr int kQuickMaxWingmen = 4;
inline constexpr int kQuickMaxEnemies = 8;

struct QuickClasses {
  std::vector<std::string> fighters;  // sorted by name
  std::vector<std::string> capitals;  // sorted by name; empty when the data has none
};
// The classes of `root_dir`/assets/ships; a file that does not parse is left out (the level
// loader reports it when a level names it).
QuickClasses quick_classes(const std::string& root_dir);

struct QuickSetup {
  std::string player = "viper";
  int wingmen = 1;                 // 0..kQuickMaxWingmen
  std::string wing = "viper";
  int enemies = 4;                 // 1..kQuickMaxEnemies
  std::string enemy = "dart";
  std::string capital = "none";    // a capital class, or "none"
  bool capital_friendly = false;   // the capital ship flies with the player (else against)
  QuickAsteroids asteroids = QuickAsteroids::Few;
  Difficulty difficulty = Difficulty::Normal;
  bool operator==(const QuickSetup&) const = default;
};

// The default setup with every class replaced by one `classes` has, where it lacks it.
QuickSetup default_quick_setup(const QuickClasses& classes);

// The level text of the battle. InputError ("quick battle: ...") for a class the data lacks
// or a count out of range.
std::string quick_level_json(const QuickSetup& s, const QuickClasses& classes);
// DIR/quick/quick-HASH.json: the file the level text is written to (named by its content).
std::string quick_level_path(const std::string& user_dir, const std::string& level_text);
// Whether `path` is a generated quick battle (by its name).
bool is_quick_level(const std::string& path);

// quick_battle.json: positioned InputError for a bad file or a value `classes` does not allow.
QuickSetup parse_quick_setup(const std::string& text, const std::string& path, const QuickClasses& classes);
std::string quick_setup_json(const QuickSetup& s);
// The setup of DIR/quick_battle.json; a missing file gives the default, a bad one is kept as
// .bak and replaced by the default, and `message` says so.
QuickSetup load_quick_setup(const std::string& dir, const QuickClasses& classes, std::string& message);
void save_quick_setup(const std::string& dir, const QuickSetup& s);

}  // namespace arc
