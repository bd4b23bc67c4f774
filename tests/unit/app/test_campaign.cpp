// The campaign: its file, its missions in the menu's catalog, unlocking in order, medals, the
// objectives in a result and in progress.json (format 2, format 1 still read).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "core/data_root.h"
#include "core/error.h"
#include "game/app/campaign.h"
#include "game/app/menu.h"
#include "game/app/menu_snapshots.h"
#include "game/sim/game.h"
#include "game/sim/world.h"

namespace arc {

namespace {

const std::string kRoot = arc::data_root();

std::vector<MissionInfo> catalog() { return load_catalog_with_campaign(kRoot); }

std::string write(const std::string& name, const std::string& text) {
  auto dir = std::filesystem::temp_directory_path() / ("arcfire_campaign_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string campaign_error(const std::string& text) {
  try {
    load_campaign(write("c.json", text), kRoot);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const MissionInfo& nth(const std::vector<MissionInfo>& all, int n) {
  for (const MissionInfo& m : all)
    if (m.campaign == n) return m;
  throw std::runtime_error("no campaign mission " + std::to_string(n));
}

TEST(Campaign, EightMissionsInOrderEveryLevelLoads) {
  const Campaign c = load_campaign(kRoot + "/levels/campaign/campaign.json", kRoot);
  ASSERT_EQ(c.missions.size(), 8u);
  EXPECT_EQ(c.missions[0].level, "levels/training.json");
  const std::vector<MissionInfo> all = catalog();
  EXPECT_EQ(nth(all, 1).title, load_level_def(kRoot + "/levels/training.json", kRoot).mission.title);
  EXPECT_EQ(nth(all, 3).title, "Cargo Run");
  for (int n = 1; n <= 8; ++n) EXPECT_FALSE(nth(all, n).chapter.empty());
}

TEST(Campaign, HeaderExample) {
  std::vector<MissionInfo> all = load_mission_catalog("levels", ".");
  add_campaign(all, load_campaign("levels/campaign/campaign.json", "."), ".");
  EXPECT_EQ(all.back().campaign, 8);
}

TEST(Campaign, UnlocksInOrderAtAnyDifficulty) {
  const std::vector<MissionInfo> all = catalog();
  Progress p;
  EXPECT_FALSE(mission_locked(all, p, nth(all, 1).path));
  EXPECT_TRUE(mission_locked(all, p, nth(all, 2).path));
  MissionResult lost;
  record_result(p, progress_key(nth(all, 1).path, "hard"), lost);
  EXPECT_TRUE(mission_locked(all, p, nth(all, 2).path));  // a defeat opens nothing
  MissionResult won;
  won.victory = true;
  record_result(p, progress_key(nth(all, 1).path, "easy"), won);
  EXPECT_FALSE(mission_locked(all, p, nth(all, 2).path));
  EXPECT_TRUE(mission_locked(all, p, nth(all, 3).path));
}

TEST(Campaign, MenuRefusesALockedMissionAndLabelsIt) {
  Bindings b = load_bindings(kRoot + "/assets/settings/bindings.json");
  Menu m(catalog(), UserFiles{}, b, b, kRoot + "/assets/settings/quality.json");
  m.handle(parse_ui_inputs("accept", "s").front());  // Play
  const MenuPage page = m.page();
  int locked = -1;
  for (size_t i = 0; i < page.items.size(); ++i)
    if (page.items[i].find("Campaign 2. Quiet Sector") != std::string::npos) locked = int(i);
  ASSERT_GE(locked, 0);
  EXPECT_NE(page.items[size_t(locked)].find("(locked)"), std::string::npos);
  for (int i = 0; i < locked; ++i) m.handle(parse_ui_inputs("down", "s").front());
  m.handle(parse_ui_inputs("accept", "s").front());
  EXPECT_EQ(m.screen(), MenuScreen::Missions);
  EXPECT_NE(m.page().message.find("Locked"), std::string::npos);
}

TEST(Campaign, MedalsForBonusObjectivesAndAccuracy) {
  MissionResult r;
  EXPECT_EQ(mission_medal(r), Medal::None);
  r.victory = true;
  EXPECT_EQ(mission_medal(r), Medal::Bronze);
  r.bonus_total = 2, r.bonus_done = 2;
  EXPECT_EQ(mission_medal(r), Medal::Silver);
  r.beam_accuracy = 0.45;
  EXPECT_EQ(mission_medal(r), Medal::Gold);
  r.bonus_done = 1;
  EXPECT_EQ(mission_medal(r), Medal::Silver);
  EXPECT_STREQ(medal_name(Medal::Gold), "gold");
}

TEST(Campaign, ResultCountsTheObjectives) {
  GameOptions o;
  o.root_dir = kRoot;
  Game g = Game::load_level(kRoot + "/levels/campaign/03_escort.json", o);
  World& w = g.world_mut();
  w.mission->objectives[0].status = ObjectiveStatus::Done;
  w.mission->objectives[1].status = ObjectiveStatus::Failed;
  const MissionResult r = mission_result(w);
  EXPECT_EQ(r.primary_done, 1);
  EXPECT_EQ(r.primary_total, 1);
  EXPECT_EQ(r.bonus_total, 1);  // the hidden one was never revealed
  EXPECT_EQ(r.bonus_done, 0);
}

TEST(Campaign, ProgressFormatTwoRoundTripsAndFormatOneStillLoads) {
  Progress p;
  MissionResult r;
  r.victory = true;
  r.seconds = 57;
  r.primary_done = r.primary_total = 1;
  r.bonus_total = 2;
  r.bonus_done = 1;
  p.best["03_escort/normal"] = r;
  const std::string text = progress_json(p);
  EXPECT_NE(text.find("\"format\": 2"), std::string::npos);
  EXPECT_EQ(parse_progress(text, "p.json"), p);
  const Progress old = parse_progress(R"({ "format": 1, "best": { "duel/normal": { "victory": true, "seconds": 40 } } })", "p.json");
  EXPECT_TRUE(old.best.at("duel/normal").victory);
  EXPECT_THROW(parse_progress(R"({ "format": 3 })", "p.json"), InputError);
  EXPECT_THROW(parse_progress(R"({ "format": 2, "best": { "a/normal": { "seconds": 1, "bonus_total": 1, "bonus_done": 2 } } })", "p.json"),
               InputError);
}

TEST(Campaign, FileErrorsArePositioned) {
  EXPECT_NE(campaign_error(R"({ "format": 1, "title": "T", "missions": [ { "level": "levels/nope.json", "chapter": "c" } ] })")
                .find("c.json:1:55: 'missions[0].level' names no level file"),
            std::string::npos);
  EXPECT_NE(campaign_error(R"({ "format": 1, "title": "T", "missions": [ { "level": "levels/attract.json", "chapter": "" } ] })")
                .find("'missions[0].chapter' must be a text of 1 to 200"),
            std::string::npos);
  EXPECT_NE(campaign_error(R"({ "format": 1, "title": "T", "missions": [] })").find("at least one mission"), std::string::npos);
  EXPECT_NE(campaign_error(R"({ "format": 1, "title": "T", "missions": [ { "level": "levels/duel.json", "chapter": "a" },
    { "level": "levels/duel.json", "chapter": "b" } ] })").find("in the campaign twice"),
            std::string::npos);
  EXPECT_NE(campaign_error(R"({ "format": 1, "title": "T", "extra": 1, "missions": [ { "level": "levels/duel.json", "chapter": "a" } ] })")
                .find("unknown key 'extra'"),
            std::string::npos);
}

}  // namespace
}  // namespace arc
