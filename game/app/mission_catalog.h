// game/app/mission_catalog.h — the levels the menu lists, from their "mission" blocks.
//
// load_mission_catalog() reads every *.json of a folder, and of the same folder in every mod in
// use (core/data_layers.h), as a level (validated like --level), keeps those with a "mission"
// block and sorts them: the game's own first, then each mod's apart; within each, by category,
// then order. Two levels of one category and one mod with the same order are an InputError at
// the second one's `order`. "Next mission" stays within the mod.
//
// Example, compiled as AppExamples.NextMission in tests/unit/app/test_app_examples.cpp:
//   std::vector<MissionInfo> all = load_mission_catalog("levels", ".");
//   const MissionInfo* next = next_mission(all, "levels/duel.json");   // skirmish
#pragma once
#include <string>
#include <vector>

#include "game/sim/defs.h"

namespace arc {

// A ship the briefing offers and the loadouts ("beam+torpedo") it can fly with the level's weapons.
struct ShipChoice {
  std::string name;
  std::vector<std::string> loadouts;
};

struct MissionInfo {
  std::string path;  // the level file, as --level takes it
  std::string title, briefing, objective;
  int order = 0;
  MissionCategory category = MissionCategory::Mission;
  std::string mod;   // the mod folder's name the level comes from ("" for the game's own)
  int campaign = 0;  // its place in the campaign (game/app/campaign.h), 1 first; 0: not in it
  std::string chapter;  // the campaign's line before its briefing ("" outside the campaign)
  // The level's "loadout" block: the ships offered (empty: no choice) and the suggestion.
  std::vector<ShipChoice> ships;
  std::string suggested_ship, suggested_loadout;
  std::vector<std::string> unlocks;  // the ship classes its win opens (campaign.h)
};

// The ships and loadouts a level's "loadout" block offers (none without one).
std::vector<ShipChoice> ship_choices(const LevelDef& L, const std::string& root_dir);

std::vector<MissionInfo> load_mission_catalog(const std::string& levels_dir, const std::string& root_dir);
// The mission after `path` in order (category Mission only), or nullptr after the last.
const MissionInfo* next_mission(const std::vector<MissionInfo>& all, const std::string& path);
const MissionInfo* find_mission(const std::vector<MissionInfo>& all, const std::string& path);

}  // namespace arc
