#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <unistd.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/json.h"
#include "game/sim/defs.h"
#include "game/sim/effects.h"
#include "test_helpers.h"
#include "core/data_root.h"

namespace arc {
namespace {

const std::string kRoot = arc::data_root();

// Parses level text and returns the error message ("" when it loads).
std::string error_of(const std::string& text) {
  try {
    parse_level_def(text, "bad.json", kRoot);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kGood = R"({
  "name": "ok",
  "objective": "x",
  "win": { "type": "destroy_all_hostiles" },
  "lose": { "type": "player_destroyed" },
  "ships": [
    { "name": "P", "class": "viper", "team": "blue", "player": true }
  ]
})";

TEST(LevelFiles, EveryShippedLevelValidatesAndLoads) {
  int count = 0;
  for (const auto& e : std::filesystem::directory_iterator(kRoot + "/levels")) {
    if (e.path().extension() != ".json") continue;
    SCOPED_TRACE(e.path().string());
    LevelDef def = load_level_def(e.path().string(), kRoot);
    EXPECT_FALSE(def.ships.empty());
    EXPECT_FALSE(def.objective.empty());
    Game g = Game::load_level(e.path().string(), test::options());
    for (int i = 0; i < 3; ++i) g.step(InputFrame{});
    EXPECT_EQ(g.tick(), 3u);
    ++count;
  }
  EXPECT_GE(count, 5);  // duel, skirmish, arena, attract, gallery
}

TEST(LevelFiles, RequiredLevelsHaveTheirShapes) {
  LevelDef duel = load_level_def(kRoot + "/levels/duel.json", kRoot);
  EXPECT_EQ(duel.ships.size(), 2u);
  LevelDef sk = load_level_def(kRoot + "/levels/skirmish.json", kRoot);
  // The player, two wingmen, the first pair and the last Viper (inactive: an event brings it).
  EXPECT_EQ(sk.ships.size(), 6u);
  size_t sk_waves = 0;
  for (const WaveDef& wave : sk.waves) sk_waves += wave.ships.size();
  EXPECT_EQ(sk_waves, 2u);  // the pair after the first
  LevelDef arena = load_level_def(kRoot + "/levels/arena.json", kRoot);
  size_t arena_ships = arena.ships.size();
  for (const WaveDef& wave : arena.waves) arena_ships += wave.ships.size();
  EXPECT_GE(arena_ships, 16u);
  LevelDef attract = load_level_def(kRoot + "/levels/attract.json", kRoot);
  for (const ShipSpawnDef& s : attract.ships) EXPECT_EQ(s.ai, AiKind::Fighter) << s.name;
  LevelDef gallery = load_level_def(kRoot + "/levels/gallery.json", kRoot);
  // Every effect has a labelled cell of its own (unlabelled spawns are a cell's backdrop).
  std::set<std::string> effects, labels;
  for (const EffectSpawnDef& e : gallery.effects) {
    if (e.label.empty()) continue;
    effects.insert(e.effect);
    EXPECT_TRUE(labels.insert(e.label).second) << "label used twice: " << e.label;
  }
  // A field (dust, debris) spans kilometres and no cell holds it: the fleet battle lays it out.
  const LevelDef fleet = load_level_def(kRoot + "/levels/campaign/08_fleet.json", kRoot);
  std::set<std::string> fields;
  for (const EffectSpawnDef& e : fleet.effects) fields.insert(e.effect);
  for (const auto& e : std::filesystem::directory_iterator(kRoot + "/assets/effects"))
    if (e.path().extension() == ".json") {
      const std::string name = e.path().stem().string();
      const bool field = name.size() > 6 && name.compare(name.size() - 6, 6, "_field") == 0;
      EXPECT_TRUE(field ? fields.count(name) > 0 : effects.count(name) > 0) << e.path();
    }
  bool wall = false;
  for (const PropDef& p : gallery.props) wall = wall || p.model == "assets/models/wall.glb";
  EXPECT_TRUE(wall);
}

TEST(LevelFiles, ShipClassesValidate) {
  for (const char* name : {"viper", "warden", "dart"}) {
    ShipClassDef c = load_ship_class(kRoot + "/assets/ships/" + name + ".json", name);
    EXPECT_GE(c.shield_radius, c.collision_radius);
    EXPECT_FALSE(c.beam.mounts.empty());
    EXPECT_TRUE(c.missile.present || c.plasma.present) << name;
  }
}

TEST(LevelErrors, GoodTextLoads) { EXPECT_EQ(error_of(kGood), ""); }

TEST(LevelErrors, SyntaxErrorHasPosition) {
  std::string e = error_of("{\n  \"name\": \"x\",\n  \"seed\": ,\n}");
  EXPECT_EQ(e.rfind("bad.json:3:", 0), 0u) << e;
}

TEST(LevelErrors, UnknownKeyPointsAtTheKey) {
  std::string t = kGood;
  t.replace(t.find("\"objective\""), 0, "\"objectve\": \"typo\",\n  ");
  std::string e = error_of(t);
  EXPECT_EQ(e.rfind("bad.json:3:3: unknown key 'objectve'", 0), 0u) << e;
}

TEST(LevelErrors, UnknownKeyInsideAShip) {
  std::string t = kGood;
  t.replace(t.find("\"player\": true"), 0, "\"hul\": 5, ");
  std::string e = error_of(t);
  EXPECT_EQ(e.rfind("bad.json:7:54: unknown key 'hul'", 0), 0u) << e;
}

TEST(LevelErrors, WrongTypePointsAtTheValue) {
  std::string t = kGood;
  t.replace(t.find("\"objective\": \"x\""), 16, "\"objective\": 5");
  std::string e = error_of(t);
  EXPECT_EQ(e.rfind("bad.json:3:16: 'objective' must be a string", 0), 0u) << e;
}

TEST(LevelErrors, OutOfRangeValue) {
  std::string t = kGood;
  t.replace(t.find("\"objective\""), 0, "\"tick_rate\": 5000,\n  ");
  std::string e = error_of(t);
  EXPECT_EQ(e.rfind("bad.json:3:16: 'tick_rate'", 0), 0u) << e;
  EXPECT_NE(e.find("480"), std::string::npos) << e;
}

TEST(LevelErrors, HugeNumberIsRejected) {
  std::string t = kGood;
  t.replace(t.find("\"player\": true"), 0, "\"position\": [0, 1e300, 0], ");
  std::string e = error_of(t);
  EXPECT_EQ(e.rfind("bad.json:7:", 0), 0u) << e;
  EXPECT_NE(e.find("position"), std::string::npos) << e;
}

TEST(LevelErrors, OverflowingNumberIsRejectedWithPosition) {
  std::string t = kGood;
  t.replace(t.find("\"objective\""), 0, "\"seed\": 1e999,\n  ");
  std::string e = error_of(t);
  EXPECT_EQ(e.rfind("bad.json:3:", 0), 0u) << e;
}

TEST(LevelErrors, MissingShipClassNamesTheClassAtItsPosition) {
  std::string t = kGood;
  t.replace(t.find("\"viper\""), 7, "\"frigate\"");
  std::string e = error_of(t);
  EXPECT_EQ(e.rfind("bad.json:7:29: ship class 'frigate' not found", 0), 0u) << e;
}

TEST(LevelErrors, ClassNameMustNotBeAPath) {
  std::string t = kGood;
  t.replace(t.find("\"viper\""), 7, "\"../x\"");
  EXPECT_EQ(error_of(t).rfind("bad.json:7:29:", 0), 0u) << error_of(t);
}

TEST(LevelErrors, MissingRequiredKeyAndBadChoices) {
  std::string t = kGood;
  t.replace(t.find("\"objective\": \"x\","), 17, "");
  EXPECT_NE(error_of(t).find("missing required key 'objective'"), std::string::npos) << error_of(t);
  std::string d = kGood;
  d.replace(d.find("\"objective\""), 0, "\"difficulty\": \"insane\",\n  ");
  std::string e = error_of(d);
  EXPECT_EQ(e.rfind("bad.json:3:17: 'difficulty' must be one of", 0), 0u) << e;
}

TEST(LevelErrors, TwoPlayersAndDuplicateNamesAreRejected) {
  std::string t = kGood;
  t.replace(t.find("]\n}"), 0, ",{ \"name\": \"P\", \"class\": \"dart\", \"team\": \"red\" }");
  EXPECT_NE(error_of(t).find("used twice"), std::string::npos) << error_of(t);
  std::string u = kGood;
  u.replace(u.find("]\n}"), 0, ",{ \"name\": \"Q\", \"class\": \"dart\", \"team\": \"red\", \"player\": true }");
  EXPECT_NE(error_of(u).find("only one ship may be the player"), std::string::npos) << error_of(u);
}

TEST(LevelErrors, BadShipClassFileIsReportedInThatFile) {
  auto dir = std::filesystem::temp_directory_path() / "arcfire_bad_root";
  std::filesystem::create_directories(dir / "assets/ships");
  std::filesystem::copy_file(kRoot + "/assets/ships/viper.json", dir / "assets/ships/viper.json",
                             std::filesystem::copy_options::overwrite_existing);
  {
    std::ofstream f(dir / "assets/ships/broken.json");
    f << "{\n  \"model\": \"m.glb\",\n  \"mass\": -3\n}\n";
  }
  std::string t = kGood;
  t.replace(t.find("\"viper\""), 7, "\"broken\"");
  try {
    parse_level_def(t, "bad.json", dir.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("broken.json:3:11: 'mass'"), std::string::npos) << m;
  }
}

// assets/settings/ai.json is validated like a level: the first bad value, at its position.
TEST(LevelErrors, BadAiDifficultyFileIsReportedInThatFile) {
  auto dir = std::filesystem::temp_directory_path() / ("arcfire_bad_ai_root_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir / "assets/settings");
  auto error_for = [&](const std::string& text) -> std::string {
    std::ofstream(dir / "assets/settings/ai.json") << text;
    try {
      load_ai_difficulties(dir.string());
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string row = R"("aim_error_deg": 1, "reaction_s": 0.2, "aggression": 0.5, "stick_limit": 1, "jink": 0,)";
  const std::string ok = "{\n\"easy\": {" + row + R"( "tail_limit_s": 3, "tail_break_s": 2 },)" + "\n\"normal\": {" +
                         row + R"( "tail_limit_s": 3, "tail_break_s": 2 },)" + "\n\"hard\": {" + row +
                         R"( "tail_limit_s": 0, "tail_break_s": 0 })" + "\n}\n";
  EXPECT_EQ(error_for(ok), "");
  std::string m = error_for(std::string(ok).replace(ok.find("\"aggression\": 0.5"), 17, "\"aggression\": 1.5"));
  EXPECT_NE(m.find("ai.json:2:"), std::string::npos) << m;
  EXPECT_NE(m.find("'easy.aggression'"), std::string::npos) << m;
  m = error_for(std::string(ok).replace(ok.find("\"jink\""), 6, "\"jinx\""));
  EXPECT_NE(m.find("missing required key 'jink'"), std::string::npos) << m;
  m = error_for(std::string(ok).replace(ok.find("\"tail_break_s\": 2"), 17, "\"tail_break_s\": 0"));
  EXPECT_NE(m.find("ai.json:2:"), std::string::npos) << m;
  EXPECT_NE(m.find("'easy.tail_break_s' must be above zero"), std::string::npos) << m;
  m = error_for("{ \"easy\": {" + row + R"( "tail_limit_s": 0, "tail_break_s": 0 } })");
  EXPECT_NE(m.find("normal"), std::string::npos) << m;
}

// "to", "velocity" and ship labels (the gallery's cells): each misuse is one positioned line.
TEST(LevelErrors, EffectTargetsAndVelocitiesAreChecked) {
  auto with_effect = [](const std::string& effect) {
    std::string t = kGood;
    return t.replace(t.find("\"ships\""), 0, "\"effects\": [" + effect + "],\n  ");
  };
  auto fx = load_effect_library(kRoot);
  auto error_with_library = [&](const std::string& text) -> std::string {
    try {
      parse_level_def(text, "bad.json", kRoot, fx.get());
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string beam = R"({ "effect": "lightning_beam", "position": [0, 0, 0], )";
  EXPECT_EQ(error_with_library(with_effect(beam + R"("to": [30, 0, 0], "repeat_ticks": 60 })")), "");
  std::string e = error_with_library(with_effect(beam + R"("orientation": [90, 0, 0], "to": [30, 0, 0] })"));
  EXPECT_EQ(e.rfind("bad.json:6:", 0), 0u) << e;
  EXPECT_NE(e.find("'orientation' or 'to'"), std::string::npos) << e;
  e = error_with_library(with_effect(beam + R"("to": [0, 0, 0] })"));
  EXPECT_EQ(e.rfind("bad.json:6:74: 'effects[0].to' must lie away from 'position'", 0), 0u) << e;
  e = error_with_library(with_effect(R"({ "effect": "shield_hit", "to": [1, 0, 0] })"));
  EXPECT_EQ(e.rfind("bad.json:6:47: 'effects[0].to' aims a lightning channel", 0), 0u) << e;
  e = error_with_library(with_effect(R"({ "effect": "plasma_bolt", "velocity": [10, 0, 0] })"));
  EXPECT_EQ(e.rfind("bad.json:6:54: a moving effect needs 'repeat_ticks'", 0), 0u) << e;
  e = error_with_library(with_effect(R"({ "effect": "plasma_bolt", "label_at": [1, 2] })"));
  EXPECT_EQ(e.rfind("bad.json:6:54: 'effects[0].label_at' must be", 0), 0u) << e;
  std::string t = kGood;
  e = error_of(t.replace(t.find("\"player\": true"), 0, "\"label\": 3, "));
  EXPECT_EQ(e.rfind("bad.json:7:63: 'ships[0].label' must be a string", 0), 0u) << e;
}

TEST(LevelErrors, UnknownEffectIsAMissingFileAtItsPosition) {
  std::string t = kGood;
  t.replace(t.find("\"ships\""), 0, "\"effects\": [{ \"effect\": \"no_such_effect\" }],\n  ");
  auto fx = load_effect_library(kRoot);
  try {
    parse_level_def(t, "bad.json", kRoot, fx.get());
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("bad.json:6:27: '", 0), 0u) << m;
    EXPECT_NE(m.find("effect' names effect file "), std::string::npos) << m;
    EXPECT_NE(m.find("assets/effects/no_such_effect.json: no such file; effects: "), std::string::npos) << m;
  }
  EXPECT_NO_THROW(parse_level_def(t, "bad.json", kRoot));  // without a library names are not checked
}

}  // namespace
// The "mission" block: titles and briefings for the menu, validated like every other key.
std::string with_mission(const std::string& block) {
  std::string t = kGood;
  t.replace(t.find("\"objective\""), 0, "\"mission\": " + block + ",\n  ");
  return t;
}

TEST(LevelMissions, ShippedLevelsHaveTitlesAndTheGalleryIsAnEffect) {
  for (const char* name : {"duel", "skirmish", "arena"}) {
    LevelDef L = load_level_def(kRoot + "/levels/" + name + ".json", kRoot);
    EXPECT_TRUE(L.mission.present) << name;
    EXPECT_EQ(L.mission.category, MissionCategory::Mission) << name;
    EXPECT_FALSE(L.mission.briefing.empty()) << name;
  }
  EXPECT_EQ(load_level_def(kRoot + "/levels/gallery.json", kRoot).mission.category, MissionCategory::Effects);
  EXPECT_EQ(load_level_def(kRoot + "/levels/attract.json", kRoot).mission.category, MissionCategory::Demo);
}

TEST(LevelMissions, BlockIsReadAndErrorsArePositioned) {
  const std::string ok = R"({ "title": "T", "briefing": "B.", "objective": "O.", "order": 4 })";
  EXPECT_EQ(error_of(with_mission(ok)), "");
  LevelDef L = parse_level_def(with_mission(ok), "m.json", kRoot);
  EXPECT_EQ(L.mission.title, "T");
  EXPECT_EQ(L.mission.order, 4);
  EXPECT_EQ(L.mission.order_where, "m.json:3:76");
  std::string e = error_of(with_mission(R"({ "title": "", "briefing": "B.", "objective": "O.", "order": 1 })"));
  EXPECT_EQ(e.rfind("bad.json:3:25: 'mission.title' must be a text of 1 to 40 characters, got 0", 0), 0u) << e;
  e = error_of(with_mission(R"({ "title": "T", "briefing": "B.", "objective": "O.", "order": 0 })"));
  EXPECT_EQ(e.rfind("bad.json:3:76: 'mission.order' must be in [1, 1000], got 0", 0), 0u) << e;
  e = error_of(with_mission(R"({ "title": "T", "briefing": "B.", "order": 1 })"));
  EXPECT_NE(e.find("missing required key 'objective'"), std::string::npos) << e;
  e = error_of(with_mission(R"({ "title": "T", "briefing": "B.", "objective": "O.", "order": 1, "category": "x" })"));
  EXPECT_NE(e.find("'mission.category' must be one of \"mission\", \"effects\" or \"demo\""), std::string::npos) << e;
  e = error_of(with_mission(R"({ "title": "T", "briefing": "B.", "objective": "O.", "order": 1, "brief": "x" })"));
  EXPECT_NE(e.find("unknown key 'brief'"), std::string::npos) << e;
}

// levels/README.md states the position limit once; the loader takes exactly that limit, and a
// value just over it is reported with the digits that show why (not "got 1e+12").
TEST(LevelFiles, PositionLimitIsTheReadmesAndItsErrorShowsEveryDigit) {
  const std::string readme = read_text_file(build_source_tree() + "/levels/README.md");
  const std::regex limit_rx("within ±([0-9.e+]+)");
  ASSERT_EQ(std::distance(std::sregex_iterator(readme.begin(), readme.end(), limit_rx), std::sregex_iterator()), 1)
      << "the README must state the position limit exactly once";
  std::smatch m;
  std::regex_search(readme, m, limit_rx);
  const double limit = std::stod(m[1].str());
  auto level_at = [](double x) {
    char pos[64];
    std::snprintf(pos, sizeof pos, "%.17g", x);
    std::string text = kGood;
    text.replace(text.find("\"player\": true"), 14, std::string("\"player\": true, \"position\": [") + pos + ", 0, 0]");
    return text;
  };
  EXPECT_EQ(error_of(level_at(limit)), "");
  EXPECT_EQ(error_of(level_at(-limit)), "");
  const std::string e = error_of(level_at(std::nextafter(limit, 2 * limit)));
  std::smatch example;
  ASSERT_TRUE(std::regex_search(readme, example, std::regex("e\\.g\\. `([^`]+)`")));
  EXPECT_NE(e.find(example[1].str()), std::string::npos) << e << "\nREADME: " << example[1];
}

}  // namespace arc
