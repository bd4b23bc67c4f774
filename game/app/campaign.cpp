// game/app/campaign.cpp — levels/campaign/campaign.json read and checked, its missions numbered in the
// menu's catalog, unlocks from the progress file, medals from a result.
#include "game/app/campaign.h"

#include <algorithm>
#include <filesystem>

#include "core/data_layers.h"
#include "core/error.h"
#include "core/input_file.h"
#include "core/json.h"
#include "game/sim/defs.h"

namespace arc {
namespace {

constexpr size_t kMaxCampaignMissions = 64;
constexpr double kSilverAccuracy = 0.4;

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  return a == b || std::filesystem::equivalent(a, b, ec);
}

}  // namespace

Campaign load_campaign(const std::string& path, const std::string& root_dir) {
  auto doc = JsonDoc::load_file(path);
  JsonObject r = JsonValue(doc, "", &doc->root()).object();
  JsonValue f = r.require("format");
  if (f.integer(0, 1000000) != 1) f.fail("'" + f.name() + "' must be 1 (the format this version reads), got " + f.raw().dump());
  Campaign c;
  c.title = r.require_string("title");
  r.check_list_length("missions", kMaxCampaignMissions);
  for (JsonObject m : r.objects("missions")) {
    CampaignEntry e;
    JsonValue level = m.require("level");
    e.level = level.string();
    const std::string file = data_file(root_dir, e.level);
    if (!input_path_exists(file)) level.fail("'" + level.name() + "' names no level file: " + file);
    for (const CampaignEntry& before : c.missions)
      if (before.level == e.level) level.fail("'" + level.name() + "' is in the campaign twice: \"" + e.level + "\"");
    JsonValue chapter = m.require("chapter");
    e.chapter = chapter.string();
    if (e.chapter.empty() || e.chapter.size() > 200)
      chapter.fail("'" + chapter.name() + "' must be a text of 1 to 200 characters, got " + std::to_string(e.chapter.size()));
    if (m.has("unlocks")) {
      m.check_list_length("unlocks", 8);
      const JsonValue list = m.require("unlocks");
      for (const JsonValue& u : list.array()) {
        const std::string ship = u.string();
        const std::string cls = data_file(root_dir, "assets/ships/" + ship + ".json");
        if (ship.empty() || ship.find_first_of("/\\.+") != std::string::npos || !input_path_exists(cls))
          u.fail("'" + u.name() + "' must name a ship class (a file stem in assets/ships/), got \"" + ship + "\"");
        bool twice = std::find(e.unlocks.begin(), e.unlocks.end(), ship) != e.unlocks.end();
        for (const CampaignEntry& before : c.missions)
          twice = twice || std::find(before.unlocks.begin(), before.unlocks.end(), ship) != before.unlocks.end();
        if (twice) u.fail("'" + u.name() + "': ship '" + ship + "' is unlocked twice in the campaign");
        e.unlocks.push_back(ship);
      }
    }
    m.finish();
    if (!load_level_def(file, root_dir).mission.present)
      level.fail("'" + level.name() + "' names a level without a \"mission\" block (title and briefing): " + file);
    c.missions.push_back(std::move(e));
  }
  if (c.missions.empty()) r.fail_key(r.has("missions") ? "missions" : "title", "a campaign needs at least one mission in 'missions'");
  r.finish();
  return c;
}

void add_campaign(std::vector<MissionInfo>& catalog, const Campaign& c, const std::string& root_dir) {
  int last_order = 0;
  for (const MissionInfo& m : catalog)
    if (m.category == MissionCategory::Mission && m.mod.empty()) last_order = std::max(last_order, m.order);
  for (size_t i = 0; i < c.missions.size(); ++i) {
    const std::string file = data_file(root_dir, c.missions[i].level);
    MissionInfo* known = nullptr;
    for (MissionInfo& m : catalog)
      if (same_file(m.path, file)) known = &m;
    if (!known) {
      const LevelDef L = load_level_def(file, root_dir);
      const MissionDef& d = L.mission;
      catalog.push_back({file, d.title, d.briefing, d.objective, last_order + 1 + int(i), MissionCategory::Mission, ""});
      known = &catalog.back();
      // The briefing's ship and loadout choice, as the catalog gives its own levels.
      known->ships = ship_choices(L, root_dir);
      if (L.loadout.present) known->suggested_ship = L.loadout.suggested_ship;
      if (L.loadout.present) known->suggested_loadout = loadout_text(L.loadout.suggested);
    }
    known->campaign = int(i) + 1;
    known->chapter = c.missions[i].chapter;
    known->unlocks = c.missions[i].unlocks;
  }
}

std::vector<MissionInfo> load_catalog_with_campaign(const std::string& root_dir) {
  std::vector<MissionInfo> all = load_mission_catalog(root_dir + "/levels", root_dir);
  const std::string file = data_file(root_dir, "levels/campaign/campaign.json");
  if (input_path_exists(file)) add_campaign(all, load_campaign(file, root_dir), root_dir);
  return all;
}

bool mission_won(const Progress& p, const std::string& path) {
  for (const char* d : {"easy", "normal", "hard"}) {
    auto it = p.best.find(progress_key(path, d));
    if (it != p.best.end() && it->second.victory) return true;
  }
  return false;
}

bool mission_locked(const std::vector<MissionInfo>& catalog, const Progress& p, const std::string& path) {
  const MissionInfo* m = find_mission(catalog, path);
  if (!m || m->campaign <= 1) return false;
  for (const MissionInfo& before : catalog)
    if (before.campaign == m->campaign - 1) return !mission_won(p, before.path);
  return false;
}

const MissionInfo* ship_locked_by(const std::vector<MissionInfo>& catalog, const Progress& p, const std::string& ship) {
  for (const MissionInfo& m : catalog)
    if (m.campaign > 0 && std::find(m.unlocks.begin(), m.unlocks.end(), ship) != m.unlocks.end())
      return mission_won(p, m.path) ? nullptr : &m;
  return nullptr;
}

std::vector<std::string> locked_ships(const std::vector<MissionInfo>& catalog, const Progress& p) {
  std::vector<const MissionInfo*> order;
  for (const MissionInfo& m : catalog)
    if (m.campaign > 0 && !m.unlocks.empty() && !mission_won(p, m.path)) order.push_back(&m);
  std::sort(order.begin(), order.end(), [](const MissionInfo* a, const MissionInfo* b) { return a->campaign < b->campaign; });
  std::vector<std::string> out;
  for (const MissionInfo* m : order) out.insert(out.end(), m->unlocks.begin(), m->unlocks.end());
  return out;
}

Medal mission_medal(const MissionResult& r) {
  if (!r.victory) return Medal::None;
  const bool bonus = r.bonus_total > 0 && r.bonus_done == r.bonus_total;
  const bool aim = r.beam_accuracy >= kSilverAccuracy;
  return bonus && aim ? Medal::Gold : bonus || aim ? Medal::Silver : Medal::Bronze;
}

const char* medal_name(Medal m) {
  switch (m) {
    case Medal::Bronze: return "bronze";
    case Medal::Silver: return "silver";
    case Medal::Gold: return "gold";
    default: return "";
  }
}

}  // namespace arc
