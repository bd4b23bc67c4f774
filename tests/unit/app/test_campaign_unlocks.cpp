// Ship unlocks from campaign progress (campaign.h): the Viper always open, the Dart after
// mission 3, the Warden after mission 5; the briefing's Ship row and the quick battle offering
// only open ships and naming the locked ones; the results screen of the win that opens one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/data_root.h"
#include "core/error.h"
#include "game/app/campaign.h"
#include "game/app/menu.h"
#include "game/app/menu_input.h"
#include "game/app/menu_snapshots.h"
#include "game/app/quick_battle.h"

namespace arc {
namespace {

const std::string kRoot = arc::data_root();

const MissionInfo& nth(const std::vector<MissionInfo>& all, int n) {
  for (const MissionInfo& m : all)
    if (m.campaign == n) return m;
  throw std::runtime_error("no campaign mission " + std::to_string(n));
}

// Campaign missions 1..n won at normal.
Progress won_through(const std::vector<MissionInfo>& all, int n) {
  Progress p;
  MissionResult won;
  won.victory = true;
  for (int i = 1; i <= n; ++i) record_result(p, progress_key(nth(all, i).path, "normal"), won);
  return p;
}

Menu make_menu(const Progress& p) {
  Bindings b = load_bindings(kRoot + "/assets/settings/bindings.json");
  UserFiles files;
  files.progress = p;
  Menu m(load_catalog_with_campaign(kRoot), files, b, b, kRoot + "/assets/settings/quality.json");
  m.set_quick_battle(quick_classes(kRoot), QuickSetup{});
  return m;
}

void run(Menu& m, const std::string& script) {
  for (const UiInput& in : parse_ui_inputs(script, "script")) m.handle(in);
}

// The briefing of campaign mission `n` (the mission list scrolled to its row).
void open_briefing(Menu& m, int n) {
  run(m, "accept");  // Play
  const std::string label = "Campaign " + std::to_string(n) + ".";
  for (int i = 0; i < 40 && m.page().items[size_t(m.page().selection)].find(label) == std::string::npos; ++i) run(m, "down");
  run(m, "accept");
  ASSERT_EQ(m.screen(), MenuScreen::Briefing) << describe_page(m.page());
}

// Every ship the Ship row steps through, from the one shown.
std::vector<std::string> ship_row(Menu& m) {
  std::vector<std::string> seen;
  run(m, "down");  // Launch, then Ship
  for (int i = 0; i < 4; ++i) {
    if (std::find(seen.begin(), seen.end(), m.chosen_ship()) == seen.end()) seen.push_back(m.chosen_ship());
    run(m, "right");
  }
  std::sort(seen.begin(), seen.end());
  return seen;
}

TEST(CampaignUnlocks, DartAfterMissionThreeWardenAfterMissionFive) {
  const std::vector<MissionInfo> all = load_catalog_with_campaign(kRoot);
  EXPECT_EQ(nth(all, 3).unlocks, std::vector<std::string>{"dart"});
  EXPECT_EQ(nth(all, 5).unlocks, std::vector<std::string>{"warden"});
  Progress p;
  EXPECT_EQ(ship_locked_by(all, p, "viper"), nullptr);
  EXPECT_EQ(ship_locked_by(all, p, "dart"), &nth(all, 3));
  EXPECT_EQ(locked_ships(all, p), (std::vector<std::string>{"dart", "warden"}));
  p = won_through(all, 3);
  EXPECT_EQ(ship_locked_by(all, p, "dart"), nullptr);
  EXPECT_EQ(locked_ships(all, p), std::vector<std::string>{"warden"});
  p = won_through(all, 5);
  EXPECT_TRUE(locked_ships(all, p).empty());
}

TEST(CampaignUnlocks, BriefingOffersOnlyOpenShipsAndNamesTheLocked) {
  const std::vector<MissionInfo> all = load_catalog_with_campaign(kRoot);
  Menu fresh = make_menu(won_through(all, 1));
  open_briefing(fresh, 2);
  const std::string page = describe_page(fresh.page());
  EXPECT_NE(page.find("Locked: dart (win Campaign 3. Cargo Run), warden (win Campaign 5."), std::string::npos) << page;
  EXPECT_EQ(ship_row(fresh), std::vector<std::string>{"viper"});

  Menu later = make_menu(won_through(all, 3));
  open_briefing(later, 4);
  EXPECT_EQ(ship_row(later), (std::vector<std::string>{"dart", "viper"}));
  EXPECT_NE(describe_page(later.page()).find("Locked: warden"), std::string::npos);

  Menu all_open = make_menu(won_through(all, 5));
  open_briefing(all_open, 6);
  EXPECT_EQ(ship_row(all_open), (std::vector<std::string>{"dart", "viper", "warden"}));
  EXPECT_EQ(describe_page(all_open.page()).find("Locked:"), std::string::npos);
}

TEST(CampaignUnlocks, QuickBattleOffersOnlyOpenShips) {
  const std::vector<MissionInfo> all = load_catalog_with_campaign(kRoot);
  Menu m = make_menu(Progress{});
  run(m, "up up accept");  // Quick battle
  ASSERT_EQ(m.screen(), MenuScreen::QuickBattle);
  for (int i = 0; i < 6; ++i) {
    run(m, "right");  // Your ship: every open fighter in turn
    EXPECT_TRUE(m.ship_open(m.page().items[0].substr(m.page().items[0].find("< ") + 2,
                                                      m.page().items[0].find(" >") - m.page().items[0].find("< ") - 2)))
        << m.page().items[0];
  }
  EXPECT_NE(describe_page(m.page()).find("Locked: dart (win Campaign 3. Cargo Run)"), std::string::npos);
  Menu open = make_menu(won_through(all, 5));
  run(open, "up up accept right");
  EXPECT_EQ(describe_page(open.page()).find("Locked:"), std::string::npos);
}

TEST(CampaignUnlocks, ResultsSayWhenAWinOpensAShip) {
  const std::vector<MissionInfo> all = load_catalog_with_campaign(kRoot);
  Menu m = make_menu(won_through(all, 2));
  MissionResult won;
  won.victory = true;
  m.show_results(nth(all, 3).path, Difficulty::Normal, won);
  EXPECT_NE(describe_page(m.page()).find("New ship unlocked: dart"), std::string::npos) << describe_page(m.page());
  EXPECT_TRUE(m.ship_open("dart"));
  // The same win again opens nothing new.
  m.show_results(nth(all, 3).path, Difficulty::Hard, won);
  EXPECT_EQ(describe_page(m.page()).find("New ship unlocked"), std::string::npos);
  // A defeat opens nothing.
  m.show_results(nth(all, 5).path, Difficulty::Normal, MissionResult{});
  EXPECT_EQ(describe_page(m.page()).find("New ship unlocked"), std::string::npos);
  EXPECT_FALSE(m.ship_open("warden"));
}

TEST(CampaignUnlocks, UnknownOrRepeatedShipIsAPositionedError) {
  auto error_of = [](const std::string& missions) {
    const std::string path = ::testing::TempDir() + "unlocks.json";
    FILE* f = std::fopen(path.c_str(), "w");
    std::fputs(("{ \"format\": 1, \"title\": \"T\", \"missions\": [ " + missions + " ] }").c_str(), f);
    std::fclose(f);
    try {
      load_campaign(path, kRoot);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of(R"({ "level": "levels/duel.json", "chapter": "a", "unlocks": ["zeppelin"] })")
                .find("'missions[0].unlocks[0]' must name a ship class"),
            std::string::npos);
  EXPECT_NE(error_of(R"({ "level": "levels/duel.json", "chapter": "a", "unlocks": ["dart"] },
                       { "level": "levels/skirmish.json", "chapter": "b", "unlocks": ["dart"] })")
                .find("unlocked twice"),
            std::string::npos);
}

}  // namespace
}  // namespace arc
