// Reinforcement waves: when they arrive, what they post, the outcome waiting for them, their
// validation; the wing messages and the comms menu on the HUD.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "game/render/hud_comms.h"
#include "game/render/render_view_builder.h"
#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

const std::string kShips = R"(
    { "name": "Lead", "class": "viper", "team": "blue", "player": true, "position": [0, 0, 0] },
    { "name": "Red 1", "class": "dart", "team": "red", "ai": "none", "position": [0, 0, -3000] },
    { "name": "Red 2", "class": "dart", "team": "red", "ai": "none", "position": [100, 0, -3000] })";

std::string with_waves(const std::string& waves) {
  return test::level_text(kShips, "\n  \"waves\": " + waves + ",");
}

const std::string kTwoWaves = R"([
    { "after_seconds": 2, "ships": [
      { "name": "Red 3", "class": "viper", "team": "red", "ai": "none", "position": [0, 0, -4000] } ] },
    { "when_team_below": { "team": "red", "count": 2 }, "ships": [
      { "name": "Blue 2", "class": "viper", "team": "blue", "position": [0, 0, 500] },
      { "name": "Blue 3", "class": "viper", "team": "blue", "position": [50, 0, 500] } ] }
  ])";

Game load(const std::string& text, const std::string& name) {
  return Game::load_level(test::write_level(name, text), test::options());
}

std::string error_of(const std::string& text) {
  try {
    parse_level_def(text, "bad.json", arc::data_root());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool has_text(const HudLayer& h, const std::string& s) {
  for (const HudText& t : h.texts)
    if (t.text.find(s) != std::string::npos) return true;
  return false;
}

TEST(Waves, WaitUntilTheirTriggerThenArriveWithAMessage) {
  Game g = load(with_waves(kTwoWaves), "waves_two.json");
  const World& w = g.world();
  ASSERT_EQ(w.ships.size(), 6u);  // the waves' ships follow the level's, waiting
  ASSERT_EQ(w.waves.size(), 2u);
  EXPECT_FALSE(w.ships[3].alive);
  EXPECT_TRUE(waiting(w.ships[3]));
  EXPECT_TRUE(w.ships[3].shield_fx.clusters.empty());
  while (w.tick < 119) g.step({});
  EXPECT_FALSE(w.ships[3].alive);
  g.step({});  // tick 120: two seconds
  EXPECT_TRUE(w.ships[3].alive);
  EXPECT_FALSE(w.ships[3].shield_fx.clusters.empty());
  EXPECT_EQ(w.waves[0].arrived_tick, 120);
  ASSERT_FALSE(w.messages.empty());
  EXPECT_EQ(w.messages.back().text, "Reinforcements: 1 hostile ship");
  EXPECT_EQ(w.messages.back().kind, MessageKind::Hostile);
  EXPECT_EQ(w.messages.back().tick, 120);
  // Red has three; the second wave waits for fewer than two.
  for (int i = 0; i < 60; ++i) g.step({});
  EXPECT_FALSE(w.ships[4].alive);
  g.world_mut().ships[1].hull = -1;  // two kills, as a beam would make them
  g.world_mut().ships[2].hull = -1;
  g.step({});
  g.step({});
  EXPECT_TRUE(w.ships[4].alive && w.ships[5].alive);
  EXPECT_EQ(w.messages.back().text, "Reinforcements: 2 friendly ships");
  EXPECT_EQ(w.messages.back().kind, MessageKind::Friendly);
}

TEST(Waves, AHostileWaveStillToComeKeepsTheFightOpen) {
  Game g = load(with_waves(kTwoWaves), "waves_open.json");
  g.world_mut().ships[1].hull = -1;
  g.world_mut().ships[2].hull = -1;
  for (int i = 0; i < 60; ++i) g.step({});
  EXPECT_EQ(g.world().outcome, Outcome::Undecided);  // Red 3 arrives at two seconds
}

TEST(Waves, SnapshotRestoresWaitingAndArrivedShips) {
  const std::string text = with_waves(kTwoWaves);
  Game g = load(text, "waves_snap.json");
  for (int i = 0; i < 150; ++i) g.step({});
  Game copy = Game::restore(g.save(), test::write_level("waves_snap.json", text), test::options());
  EXPECT_EQ(copy.hash(), g.hash());
  for (int i = 0; i < 60; ++i) copy.step({}), g.step({});
  EXPECT_EQ(copy.hash(), g.hash());
  EXPECT_EQ(copy.world().waves[0].arrived_tick, 120);
}

TEST(Waves, ErrorsArePositioned) {
  EXPECT_EQ(error_of(with_waves(kTwoWaves)), "");
  std::string e = error_of(with_waves(R"([ { "ships": [] } ])"));
  EXPECT_NE(e.find("bad.json:7:"), std::string::npos) << e;
  EXPECT_NE(e.find("exactly one trigger"), std::string::npos) << e;
  e = error_of(with_waves(R"([ { "after_seconds": 5, "when_team_below": { "team": "red", "count": 1 }, "ships": [] } ])"));
  EXPECT_NE(e.find("exactly one trigger"), std::string::npos) << e;
  e = error_of(with_waves(R"([ { "after_seconds": -1, "ships": [] } ])"));
  EXPECT_NE(e.find("'waves[0].after_seconds' must be in [0, 36000]"), std::string::npos) << e;
  e = error_of(with_waves(R"([ { "after_seconds": 5, "ships": [] } ])"));
  EXPECT_NE(e.find("a wave needs at least one ship"), std::string::npos) << e;
  e = error_of(with_waves(R"([ { "when_team_below": { "team": "green", "count": 1 },
      "ships": [ { "name": "G", "class": "dart", "team": "green" } ] } ])"));
  EXPECT_NE(e.find("bad.json:7:"), std::string::npos) << e;
  EXPECT_NE(e.find("names no team of the level's 'ships': \"green\""), std::string::npos) << e;
  e = error_of(with_waves(R"([ { "after_seconds": 5, "ships": [ { "name": "Red 1", "class": "dart", "team": "red" } ] } ])"));
  EXPECT_NE(e.find("ship name 'Red 1' is used twice"), std::string::npos) << e;
  e = error_of(with_waves(R"([ { "after_seconds": 5, "ships": [ { "name": "P", "class": "dart", "team": "blue", "player": true } ] } ])"));
  EXPECT_NE(e.find("the player starts in 'ships'"), std::string::npos) << e;
  e = error_of(with_waves(R"([ { "after_seconds": 5, "ships": [ { "name": "X", "class": "dart", "team": "red", "speed": 3 } ] } ])"));
  EXPECT_NE(e.find("speed"), std::string::npos) << e;
}

TEST(Waves, WingFlagIsValidated) {
  const auto level = [](const std::string& wing_ship) {
    return test::level_text(R"(
    { "name": "Lead", "class": "viper", "team": "blue", "player": true },)" + wing_ship);
  };
  EXPECT_EQ(error_of(level(R"({ "name": "W", "class": "viper", "team": "blue", "wing": true })")), "");
  std::string e = error_of(level(R"({ "name": "W", "class": "viper", "team": "red", "wing": true })"));
  EXPECT_NE(e.find("bad.json:8:"), std::string::npos) << e;
  EXPECT_NE(e.find("a wingman flies on the player's team \"blue\", not \"red\""), std::string::npos) << e;
  e = error_of(level(R"({ "name": "W", "class": "viper", "team": "blue", "ai": "gunner", "wing": true })"));
  EXPECT_NE(e.find("a wingman needs 'ai': \"fighter\""), std::string::npos) << e;
}

TEST(WingHud, MessagesJoinTheKillFeedAndTheCommsMenuListsTheOrders) {
  Game g = Game::load_level(arc::data_root() + "/levels/skirmish.json", test::options());
  g.step({}, {Command::OrderFormUp});
  RenderView v;
  HudState hud;
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, hud, 1280, 720, v);
  EXPECT_TRUE(has_text(v.hud, "Alpha 2, Alpha 3: forming up"));
  EXPECT_FALSE(has_text(v.hud, kCommsOrders[0]));
  hud.comms_open = true;
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, hud, 1280, 720, v);
  for (const char* line : kCommsOrders) EXPECT_TRUE(has_text(v.hud, line)) << line;
  EXPECT_TRUE(has_text(v.hud, "3  Form up  <"));  // the wing's order now
}

}  // namespace
}  // namespace arc
