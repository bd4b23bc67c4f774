// game/sim/loadout.h — the player's ship and loadout choice applied to a level (loadout.cpp).
//
// Parsing and checking loadouts is declared in defs.h (parse_loadout, loadout_problem,
// apply_loadout); a level's "loadout" block fills LevelDef::loadout.
#pragma once
#include <string>

#include "game/sim/defs.h"

namespace arc {

// The player's ship becomes class `ship` ("" keeps the level's) armed with `loadout` ("" keeps
// the class's weapons): the armed class is added to L.classes as "CLASS+PRIMARY+SECONDARY".
// InputError naming --ship or --loadout for a class that does not exist or a loadout it cannot fly.
void apply_player_choice(LevelDef& L, const std::string& ship, const std::string& loadout, const std::string& root_dir);

}  // namespace arc
