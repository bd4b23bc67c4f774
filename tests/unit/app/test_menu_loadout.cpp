// The briefing's ship and loadout choice (game/app/menu_loadout.cpp): the level's suggestion
// first, Left/Right on the Ship and Loadout rows, only unlocked ships offered, the choice in
// the Launch request, and the game it launches flying it.
#include <gtest/gtest.h>

#include "game/app/menu.h"
#include "menu_script.h"
#include "game/app/menu_input.h"
#include "game/app/menu_snapshots.h"
#include "game/sim/world.h"
#include "core/data_root.h"

namespace arc {
namespace {

using menu_test::run;
using menu_test::has_line;
const std::string kRoot = arc::data_root();

Menu make_menu(const std::vector<std::string>& unlocked = {}) {
  Menu m = menu_test::shipped_menu();
  m.set_unlocked_ships(unlocked);
  return m;
}

TEST(MenuLoadout, CatalogOffersTheLevelsShipsWithTheirLoadouts) {
  const auto all = load_mission_catalog(kRoot + "/levels", kRoot);
  const MissionInfo* skirmish = find_mission(all, kRoot + "/levels/skirmish.json");
  ASSERT_NE(skirmish, nullptr);
  ASSERT_EQ(skirmish->ships.size(), 3u);
  EXPECT_EQ(skirmish->ships[0].name, "dart");
  EXPECT_EQ(skirmish->ships[0].loadouts, (std::vector<std::string>{"beam+plasma"}));
  EXPECT_EQ(skirmish->ships[1].name, "viper");
  EXPECT_EQ(skirmish->ships[1].loadouts, (std::vector<std::string>{"beam+plasma", "beam+missile", "beam+torpedo",
                                                                   "plasma+missile", "plasma+torpedo"}));
  EXPECT_EQ(skirmish->suggested_ship, "viper");
  EXPECT_EQ(skirmish->suggested_loadout, "beam+missile");
  // The duel offers no choice: its briefing is as it was.
  EXPECT_TRUE(find_mission(all, kRoot + "/levels/duel.json")->ships.empty());
}

TEST(MenuLoadout, BriefingStartsOnTheSuggestionAndLaunchesTheChoice) {
  Menu m = make_menu();
  run(m, "accept down down accept");  // Play, Skirmish (after Training and Duel)
  ASSERT_EQ(m.screen(), MenuScreen::Briefing);
  ASSERT_EQ(m.page().title, "Skirmish");
  EXPECT_TRUE(has_line(m.page(), "Ship: < viper >")) << describe_page(m.page());
  EXPECT_TRUE(has_line(m.page(), "Loadout: < beam+missile >"));
  EXPECT_TRUE(has_line(m.page(), "Suggested: viper, beam+missile"));
  run(m, "down right");  // Ship: warden, which flies beam+missile too
  EXPECT_EQ(m.chosen_ship(), "warden");
  EXPECT_EQ(m.chosen_loadout(), "beam+missile");
  run(m, "down right");  // Loadout: the warden's next, beam+torpedo
  EXPECT_EQ(m.chosen_loadout(), "beam+torpedo");
  run(m, "up right");  // Ship: round to the dart, whose only loadout is beam+plasma
  EXPECT_EQ(m.chosen_ship(), "dart");
  EXPECT_EQ(m.chosen_loadout(), "beam+plasma");
  run(m, "left down right");  // back to the warden; its loadout rows from the first
  EXPECT_EQ(m.chosen_ship(), "warden");
  const std::vector<MenuRequest> launch = run(m, "up up accept");
  ASSERT_EQ(launch.size(), 1u);
  EXPECT_EQ(launch[0].kind, MenuRequest::Kind::Launch);
  EXPECT_EQ(launch[0].ship, "warden");
  EXPECT_EQ(launch[0].loadout, m.chosen_loadout());

  GameOptions o;
  o.root_dir = kRoot;
  o.ship = launch[0].ship;
  o.loadout = launch[0].loadout;
  Game g = Game::load_level(launch[0].level, o);
  const Ship& p = g.world().ship(g.world().player);
  EXPECT_EQ(p.cls->name, "warden+" + launch[0].loadout);
}

TEST(MenuLoadout, OnlyUnlockedShipsAreOffered) {
  Menu m = make_menu({"viper"});
  run(m, "accept down down accept");
  EXPECT_TRUE(has_line(m.page(), "Ship: < viper >"));
  run(m, "down right");
  EXPECT_EQ(m.chosen_ship(), "viper");  // nothing else to turn to
  Menu none = make_menu({"corvette"});
  run(none, "accept down down accept");
  EXPECT_FALSE(has_line(none.page(), "Ship:"));  // nothing unlocked that the level offers: no choice
  const std::vector<MenuRequest> launch = run(none, "accept");
  ASSERT_EQ(launch.size(), 1u);
  EXPECT_EQ(launch[0].ship, "");
}

TEST(MenuLoadout, ABriefingWithoutChoiceKeepsItsRows) {
  Menu m = make_menu();
  run(m, "accept down accept");  // the duel
  ASSERT_EQ(m.page().title, "Duel");
  EXPECT_FALSE(has_line(m.page(), "Ship:"));
  EXPECT_EQ(m.chosen_ship(), "");
  EXPECT_EQ(m.chosen_loadout(), "");
}

}  // namespace
}  // namespace arc
