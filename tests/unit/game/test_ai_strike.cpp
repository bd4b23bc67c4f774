// Fighter pilots against a capital ship (game/sim/ai_strike.h): the subsystem they go for, a
// pilot with torpedoes taking the corvette's shield generator out with them, one without never
// launching any, the player's side leaving a capital ship alone unless ordered, and the
// "subsystem_destroyed" trigger with its positioned error.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "game/sim/ai_strike.h"
#include "game/sim/capital.h"
#include "game/sim/defs.h"
#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

// The player idles far off (out of every turret's range); the striker is the AI under test.
std::string strike_ships(const std::string& striker_class) {
  return R"({ "name": "Player", "class": "viper", "team": "blue", "player": true, "position": [0, 0, 6000] },
    { "name": "Striker", "class": ")" + striker_class + R"(", "team": "blue", "position": [0, 200, 1400], "orientation": [0, 0, 0] },
    { "name": "Corvette", "class": "corvette", "team": "red", "ai": "capital", "position": [0, 0, 0], "orientation": [180, 0, 0] })";
}

// The player's side strikes a capital ship only when ordered: here a level event's order.
const std::string kStrikeOrder = R"(
  "events": [ { "id": "strike", "when": { "type": "time", "seconds": 0 },
                "do": [ { "type": "order", "ship": "Striker", "order": "attack", "target": "Corvette" } ] } ],)";

// Unordered, a pilot of the player's side leaves the corvette to the player's own strike.
TEST(CapitalAi, PlayersSideLeavesCapitalShipsAloneUnordered) {
  Game g = Game::load_level(test::write_level("strike_unordered.json", test::level_text(strike_ships("viper"))), test::options());
  const World& w = g.world();
  const ShipId striker = test::ship_named(w, "Striker");
  for (int64_t t = 0; t < seconds_to_ticks(w, 10.0); ++t) {
    g.step(InputFrame{});
    ASSERT_FALSE(w.ship(striker).target) << "tick " << w.tick;
  }
}

TEST(CapitalAi, StrikePartIsShieldGeneratorThenEnginesThenNearestTurret) {
  Game g = Game::load_level(test::write_level("strike_parts.json", test::level_text(strike_ships("viper"))), test::options());
  World& w = g.world_mut();
  const Ship& s = w.ship(test::ship_named(w, "Striker"));
  Ship& c = w.ship(test::ship_named(w, "Corvette"));
  EXPECT_EQ(pick_strike_part(w, s, c), int(test::part_index(c, "shield generator")));
  c.parts[test::part_index(c, "shield generator")].hull = 0;
  EXPECT_EQ(pick_strike_part(w, s, c), int(test::part_index(c, "engines")));
  c.parts[test::part_index(c, "engines")].hull = 0;
  const int turret = pick_strike_part(w, s, c);
  ASSERT_GE(turret, 0);
  EXPECT_LT(size_t(turret), c.cls->turrets.size());
  for (size_t i = 0; i < c.cls->turrets.size(); ++i) c.parts[i].hull = 0;
  EXPECT_EQ(pick_strike_part(w, s, c), -1);
  // A fighter has no parts to go for.
  EXPECT_EQ(pick_strike_part(w, c, s), -1);
}

// A Viper carries torpedoes: it locks the shield generator and launches them until it is gone.
TEST(CapitalAi, PilotWithTorpedoesKillsTheShieldGenerator) {
  Game g = Game::load_level(test::write_level("strike_torpedo.json", test::level_text(strike_ships("viper"), kStrikeOrder)), test::options());
  const World& w = g.world();
  const ShipId corvette = test::ship_named(w, "Corvette"), striker = test::ship_named(w, "Striker");
  const size_t generator = test::part_index(w.ship(corvette), "shield generator");
  bool torpedo_seen = false, aimed = false;
  int64_t ticks = 0;
  const int64_t limit = seconds_to_ticks(w, 60.0);
  for (; ticks < limit && part_alive(w.ship(corvette), generator); ++ticks) {
    g.step(InputFrame{});
    for (const Projectile& p : w.projectiles)
      torpedo_seen = torpedo_seen || (p.kind == SecondaryWeapon::Torpedo && p.owner == striker);
    aimed = aimed || target_part(w, w.ship(striker)) == int(generator);
  }
  EXPECT_TRUE(aimed);
  EXPECT_TRUE(torpedo_seen);
  EXPECT_FALSE(part_alive(w.ship(corvette), generator)) << "generator hull " << w.ship(corvette).parts[generator].hull;
  EXPECT_TRUE(shield_generators_down(w.ship(corvette)));
  EXPECT_EQ(w.ship(corvette).shield, 0.0);
}

// A Dart carries no torpedoes: it goes for the same subsystem with its guns and never launches one.
TEST(CapitalAi, PilotWithoutTorpedoesNeverLaunchesThem) {
  Game g = Game::load_level(test::write_level("strike_dart.json", test::level_text(strike_ships("dart"), kStrikeOrder)), test::options());
  const World& w = g.world();
  const ShipId corvette = test::ship_named(w, "Corvette"), striker = test::ship_named(w, "Striker");
  ASSERT_FALSE(w.ship(striker).cls->torpedo.present);
  bool aimed = false;
  for (int64_t t = 0; t < seconds_to_ticks(w, 30.0) && w.ship(striker).alive; ++t) {
    g.step(InputFrame{});
    for (const Projectile& p : w.projectiles) ASSERT_NE(p.kind, SecondaryWeapon::Torpedo);
    aimed = aimed || target_part(w, w.ship(striker)) == int(test::part_index(w.ship(corvette), "shield generator"));
  }
  EXPECT_TRUE(aimed);
}

TEST(CapitalAi, SubsystemDestroyedTriggerRunsItsActions) {
  const std::string extra = R"(
  "objectives": [ { "id": "gen", "text": "Take out the shield generator", "kind": "secondary" } ],
  "events": [ { "id": "gen_down", "when": { "type": "subsystem_destroyed", "ship": "Corvette", "subsystem": "shield generator" },
                "do": [ { "type": "objective", "id": "gen", "state": "done" } ] } ],)";
  Game g = Game::load_level(test::write_level("strike_trigger.json", test::level_text(strike_ships("viper"), extra)),
                            test::options());
  World& w = g.world_mut();
  g.step(InputFrame{});
  ASSERT_TRUE(w.mission);
  EXPECT_EQ(w.mission->objectives[0].status, ObjectiveStatus::Pending);
  Ship& c = w.ship(test::ship_named(w, "Corvette"));
  const size_t generator = test::part_index(c, "shield generator");
  damage_parts(w, c, part_position(c, generator), 1e6, ShipId{}, int(generator));
  g.step(InputFrame{});
  EXPECT_EQ(w.mission->objectives[0].status, ObjectiveStatus::Done);
}

TEST(CapitalAi, SubsystemDestroyedNamesThePartsOnAMistake) {
  const std::string extra = R"(
  "objectives": [ { "id": "gen", "text": "x" } ],
  "events": [ { "id": "e", "when": { "type": "subsystem_destroyed", "ship": "Corvette", "subsystem": "bridge" },
                "do": [ { "type": "objective", "id": "gen", "state": "done" } ] } ],)";
  try {
    parse_level_def(test::level_text(strike_ships("viper"), extra), "bad.json", arc::data_root());
    FAIL() << "loaded";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad.json:"), std::string::npos) << what;
    EXPECT_NE(what.find("has no turret or subsystem named \"bridge\""), std::string::npos) << what;
    EXPECT_NE(what.find("\"engines\""), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace arc
