// The quick battle (game/app/quick_battle.h): the level built from a setup goes through the
// level loader with the counts, classes and asteroids asked for; bad setups are refused; the
// remembered setup round-trips and a bad file falls back to the default with one line; the
// menu page changes rows with Left/Right and its Launch carries the generated level.
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <gtest/gtest.h>

#include "core/data_root.h"
#include "core/error.h"
#include "core/json.h"
#include "game/app/menu.h"
#include "menu_script.h"
#include "game/app/menu_snapshots.h"
#include "game/app/quick_battle.h"
#include "game/app/quick_battle_files.h"
#include "game/sim/defs.h"
#include "game/sim/game.h"
#include "game/sim/world.h"

namespace arc {
namespace {

using menu_test::run;
namespace fs = std::filesystem;
const std::string kRoot = arc::data_root();

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name) {
    path = fs::temp_directory_path() / ("arcfire_quick_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

int count_team(const LevelDef& l, const std::string& team, const std::string& cls) {
  int n = 0;
  for (const ShipSpawnDef& s : l.ships) n += s.team == team && s.ship_class == cls;
  return n;
}

TEST(QuickBattle, HeaderExample) {
  QuickClasses classes = quick_classes(".");
  QuickSetup s;                 // a Viper and a wingman against four Darts, few asteroids
  s.enemies = 6;
  const std::string text = quick_level_json(s, classes);        // InputError for a bad setup
  LevelDef def = parse_level_def(text, "quick.json", ".");      // the ordinary loader
  EXPECT_EQ(count_team(def, "red", "dart"), 6);
  EXPECT_EQ(count_team(def, "blue", "viper"), 2);
  EXPECT_FALSE(def.props.empty());
}

TEST(QuickBattle, ClassesFromTheDataFightersOnly) {
  const QuickClasses c = quick_classes(kRoot);
  for (const char* fighter : {"viper", "dart", "warden"})
    EXPECT_NE(std::find(c.fighters.begin(), c.fighters.end(), fighter), c.fighters.end()) << fighter;
  for (const char* other : {"station", "freighter", "drone"})
    EXPECT_EQ(std::find(c.fighters.begin(), c.fighters.end(), other), c.fighters.end()) << other;
  EXPECT_TRUE(std::is_sorted(c.fighters.begin(), c.fighters.end()));
}

TEST(QuickBattle, LevelHasTheCountsClassesAndAsteroidsAsked) {
  const QuickClasses c = quick_classes(kRoot);
  QuickSetup s;
  s.player = "warden";
  s.wingmen = 3;
  s.wing = "dart";
  s.enemies = 7;
  s.enemy = "viper";
  s.asteroids = QuickAsteroids::Many;
  s.difficulty = Difficulty::Hard;
  const LevelDef l = parse_level_def(quick_level_json(s, c), "quick.json", kRoot);
  ASSERT_EQ(l.ships.size(), 11u);
  EXPECT_TRUE(l.ships[0].player);
  EXPECT_EQ(l.ships[0].ship_class, "warden");
  EXPECT_EQ(count_team(l, "blue", "dart"), 3);
  EXPECT_EQ(count_team(l, "red", "viper"), 7);
  const size_t many = l.props.size();
  s.asteroids = QuickAsteroids::Few;
  const size_t few = parse_level_def(quick_level_json(s, c), "quick.json", kRoot).props.size();
  s.asteroids = QuickAsteroids::None;
  EXPECT_EQ(parse_level_def(quick_level_json(s, c), "quick.json", kRoot).props.size(), 0u);
  EXPECT_GT(few, 0u);
  EXPECT_GT(many, few);
  // The same setup gives the same text (and file name): a recording that names it replays.
  EXPECT_EQ(quick_level_json(s, c), quick_level_json(s, c));
  EXPECT_EQ(quick_level_path("/u", quick_level_json(s, c)), quick_level_path("/u", quick_level_json(s, c)));
  EXPECT_TRUE(is_quick_level(quick_level_path("/u", quick_level_json(s, c))));
  EXPECT_FALSE(is_quick_level(kRoot + "/levels/duel.json"));
}

TEST(QuickBattle, CapitalShipWhenTheDataHasOne) {
  QuickClasses c = quick_classes(kRoot);
  // Every capital class the data has loads on either side.
  for (const std::string& capital : c.capitals)
    for (bool friendly : {false, true}) {
      QuickSetup with;
      with.capital = capital;
      with.capital_friendly = friendly;
      const LevelDef l = parse_level_def(quick_level_json(with, c), "quick.json", kRoot);
      EXPECT_EQ(count_team(l, friendly ? "blue" : "red", capital), 1) << capital;
    }
  QuickSetup s;
  s.capital = "frigate";
  EXPECT_THROW(quick_level_json(s, c), InputError);  // not in the data
  // A capital class named by the data is placed on the chosen side (its class file must exist
  // for the loader, so only the text is checked here when the data has none).
  c.capitals.push_back("frigate");
  s.capital_friendly = true;
  const std::string text = quick_level_json(s, c);
  EXPECT_NE(text.find("\"class\": \"frigate\""), std::string::npos);
  EXPECT_NE(text.find("\"Flagship\""), std::string::npos);
}

TEST(QuickBattle, BadSetupsAreRefusedWithOneLine) {
  const QuickClasses c = quick_classes(kRoot);
  auto message = [&](QuickSetup s) {
    try {
      quick_level_json(s, c);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  QuickSetup s;
  s.enemy = "station";
  EXPECT_NE(message(s).find("enemy class 'station'"), std::string::npos) << message(s);
  s = QuickSetup{};
  s.enemies = 0;
  EXPECT_NE(message(s).find("enemies must be 1..8, got 0"), std::string::npos) << message(s);
  s = QuickSetup{};
  s.wingmen = 9;
  EXPECT_NE(message(s).find("wingmen must be 0..4"), std::string::npos);
  EXPECT_EQ(message(QuickSetup{}).find('\n'), std::string::npos);
}

TEST(QuickBattle, SetupRoundTripsAndABadFileFallsBack) {
  TempDir dir("setup");
  const QuickClasses c = quick_classes(kRoot);
  std::string message;
  EXPECT_EQ(load_quick_setup(dir.path.string(), c, message), default_quick_setup(c));  // missing: default
  EXPECT_EQ(message, "");
  QuickSetup s;
  s.player = "dart";
  s.wingmen = 0;
  s.enemies = 8;
  s.enemy = "warden";
  s.asteroids = QuickAsteroids::None;
  s.difficulty = Difficulty::Easy;
  save_quick_setup(dir.path.string(), s);
  EXPECT_EQ(load_quick_setup(dir.path.string(), c, message), s);
  EXPECT_EQ(message, "");
  for (const std::string& bad : {std::string("{ \"format\": 1, \"enemies\": 99 }"),
                                std::string("{ \"format\": 1, \"enemy\": \"banana\" }"),
                                std::string("{ \"format\": 1, \"asteroids\": \"lots\" }"), std::string("{ nope")}) {
    std::ofstream(dir.path / "quick_battle.json") << bad;
    message.clear();
    EXPECT_EQ(load_quick_setup(dir.path.string(), c, message), default_quick_setup(c)) << bad;
    EXPECT_NE(message.find("quick_battle.json"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_TRUE(fs::exists(dir.path / "quick_battle.json.bak"));
    message.clear();
    EXPECT_EQ(load_quick_setup(dir.path.string(), c, message), default_quick_setup(c));  // defaults written
    EXPECT_EQ(message, "");
  }
}

Menu make_menu(const std::string& user_dir) {
  UserFiles files;
  files.dir = user_dir;
  Menu m = menu_test::shipped_menu(files);
  offer_quick_battle(m, kRoot, user_dir);
  return m;
}

TEST(QuickBattle, MenuPageChangesRowsAndLaunchCarriesTheLevel) {
  TempDir dir("menu");
  Menu m = make_menu(dir.path.string());
  // Quick battle sits above Quit: Up from Play wraps to Quit, Up again is Quick battle.
  run(m, "up up accept");
  ASSERT_EQ(m.screen(), MenuScreen::QuickBattle);
  const std::string first = describe_page(m.page());
  EXPECT_NE(first.find("title: QUICK BATTLE"), std::string::npos) << first;
  EXPECT_NE(first.find("> Your ship: < viper >"), std::string::npos) << first;
  // Enemies: 4 → 6 (row 4 with a wingman: ship, wingmen, wing class, enemies).
  std::vector<MenuRequest> saves = run(m, "down down down right right");
  ASSERT_FALSE(saves.empty());
  EXPECT_EQ(saves.back().kind, MenuRequest::Kind::SaveQuickBattle);
  EXPECT_EQ(m.quick_setup().enemies, 6);
  run(m, "left left left left left left left left left");
  EXPECT_EQ(m.quick_setup().enemies, 1);  // held at the least
  run(m, "right up up left");             // 2 enemies; no wingmen: the wing class row goes
  EXPECT_EQ(m.quick_setup().wingmen, 0);
  EXPECT_EQ(describe_page(m.page()).find("Wing class"), std::string::npos);
  EXPECT_NE(describe_page(m.page()).find("> Wingmen: < 0 >"), std::string::npos) << describe_page(m.page());
  std::vector<MenuRequest> go;
  for (int i = 0; i < 20 && go.empty(); ++i) {
    if (describe_page(m.page()).find("> Launch") != std::string::npos) go = run(m, "accept");
    else run(m, "down");
  }
  ASSERT_EQ(go.size(), 2u);  // the setup kept, then the launch
  EXPECT_EQ(go[0].kind, MenuRequest::Kind::SaveQuickBattle);
  go.erase(go.begin());
  EXPECT_EQ(go[0].kind, MenuRequest::Kind::Launch);
  EXPECT_TRUE(is_quick_level(go[0].level));
  EXPECT_EQ(go[0].level.rfind(dir.path.string(), 0), 0u);
  const LevelDef l = parse_level_def(go[0].generated, go[0].level, kRoot);
  EXPECT_EQ(l.ships.size(), 3u);  // the player and two enemies
  EXPECT_EQ(m.screen(), MenuScreen::Closed);

  // Written where the request says, it launches like any level and shows its results.
  write_generated_level(go[0].level, go[0].generated);
  GameOptions o;
  o.root_dir = kRoot;
  Game g = Game::load_level(go[0].level, o);
  for (int i = 0; i < 600; ++i) g.step(InputFrame{});
  EXPECT_TRUE(m.show_results(go[0].level, go[0].difficulty, mission_result(g.world())).empty());  // no best kept
  const std::string results = describe_page(m.page());
  EXPECT_NE(results.find("subtitle: Quick battle (normal)"), std::string::npos) << results;
  EXPECT_TRUE(m.progress().best.empty());
  // Retry launches the same file again.
  std::vector<MenuRequest> retry = run(m, "accept");
  ASSERT_EQ(retry.size(), 1u);
  EXPECT_EQ(retry[0].level, go[0].level);
}

TEST(QuickBattle, CapitalRowOnlyWhenTheDataHasACapitalClass) {
  TempDir dir("capital");
  Menu m = make_menu(dir.path.string());
  QuickClasses c = quick_classes(kRoot);
  c.capitals = {};
  m.set_quick_battle(c, default_quick_setup(c));
  run(m, "up up accept");
  EXPECT_EQ(describe_page(m.page()).find("Capital ship"), std::string::npos);
  c.capitals = {"corvette"};
  m.set_quick_battle(c, default_quick_setup(c));
  run(m, "down down down down down");  // ship, wingmen, wing class, enemies, enemy class, capital
  EXPECT_NE(describe_page(m.page()).find("> Capital ship: < none >"), std::string::npos) << describe_page(m.page());
  run(m, "right");
  EXPECT_NE(describe_page(m.page()).find("> Capital ship: < corvette (enemy) >"), std::string::npos);
  run(m, "right");
  EXPECT_NE(describe_page(m.page()).find("> Capital ship: < corvette (yours) >"), std::string::npos);
  EXPECT_EQ(m.quick_setup().capital, "corvette");
  EXPECT_TRUE(m.quick_setup().capital_friendly);
  run(m, "right");
  EXPECT_EQ(m.quick_setup().capital, "none");
}

TEST(QuickBattle, RecordingCopyBesideTheScript) {
  TempDir dir("record");
  const std::string level = (dir.path / "quick" / "quick-1.json").string();
  write_generated_level(level, "{}\n");
  const std::string copy = copy_beside_recording(level, (dir.path / "fight.replay").string());
  EXPECT_EQ(copy, (dir.path / "fight.level.json").string());
  EXPECT_EQ(read_text_file(copy), "{}\n");
}

}  // namespace
}  // namespace arc
