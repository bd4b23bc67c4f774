// game/app/campaign.h — the campaign: its missions in order (levels/campaign/campaign.json), which are
// unlocked, and the medal a result earns.
//
// levels/campaign/campaign.json: { "format": 1, "title": TEXT, "missions": [ { "level": PATH, "chapter":
// TEXT, "unlocks": [SHIP, ...] }, ... ] } ("unlocks" optional: ship classes its win opens); every
// level must load and have a "mission" block. The menu lists campaign
// missions after the others as "Campaign N. Title"; the first is open, each later one opens when
// the one before has been won at any difficulty (a won mission stays replayable at every
// difficulty). Unlocks are read from the progress file's results, so they need no state of their own.
//
// Example, compiled as Campaign.HeaderExample in tests/unit/app/test_campaign.cpp:
//   std::vector<MissionInfo> all = load_mission_catalog("levels", ".");
//   add_campaign(all, load_campaign("levels/campaign/campaign.json", "."), ".");
#pragma once
#include <string>
#include <vector>

#include "game/app/mission_catalog.h"
#include "game/app/user_settings.h"

namespace arc {

struct CampaignEntry {
  std::string level;    // as the file names it (relative to the data root)
  std::string chapter;  // 1..200 characters, shown above the mission's briefing
  std::vector<std::string> unlocks;  // "unlocks": ship classes its win opens (locked until then)
};

struct Campaign {
  std::string title;
  std::vector<CampaignEntry> missions;
};

// Positioned InputError for a bad file, a level that does not load or one without a "mission" block.
Campaign load_campaign(const std::string& path, const std::string& root_dir);
// Numbers the catalog's missions the campaign names (campaign 1, 2, ...) and appends those it
// lacks (category mission, after every other).
void add_campaign(std::vector<MissionInfo>& catalog, const Campaign& c, const std::string& root_dir);
// The catalog of the data root's levels with its campaign added (levels/campaign/campaign.json, if any).
std::vector<MissionInfo> load_catalog_with_campaign(const std::string& root_dir);

// Whether `path` is a campaign mission after one not yet won at any difficulty.
bool mission_locked(const std::vector<MissionInfo>& catalog, const Progress& p, const std::string& path);
// Whether any difficulty's best for `path` is a victory.
bool mission_won(const Progress& p, const std::string& path);

// Ship unlocks: a ship class a campaign mission's "unlocks" names is locked until that mission is
// won at any difficulty; every other ship is always open. The mission that still locks `ship`
// (nullptr: open).
const MissionInfo* ship_locked_by(const std::vector<MissionInfo>& catalog, const Progress& p, const std::string& ship);
// Every ship some campaign mission unlocks that is still locked, in campaign order.
std::vector<std::string> locked_ships(const std::vector<MissionInfo>& catalog, const Progress& p);

enum class Medal { None = 0, Bronze = 1, Silver = 2, Gold = 3 };
// Bronze: won; Silver: won with every bonus objective done, or with beam accuracy of 40 % or
// more; Gold: won with both.
Medal mission_medal(const MissionResult& r);
const char* medal_name(Medal m);  // "", "bronze", "silver", "gold"

}  // namespace arc
