// Capital ships: turret arcs, turrets firing on their own, subsystem damage and its effects,
// torpedoes that harm only capital ships, the staged break-up, and the ship class's turret and
// subsystem blocks refused with their positions.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "game/sim/capital.h"
#include "game/sim/damage.h"
#include "game/sim/defs.h"
#include "game/sim/geometry.h"
#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

std::string ship_row(const std::string& name, const std::string& cls, const std::string& team, const std::string& ai,
                     double x, double y, double z, bool player = false) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                R"({ "name": "%s", "class": "%s", "team": "%s", "ai": "%s", "position": [%g, %g, %g]%s })",
                name.c_str(), cls.c_str(), team.c_str(), ai.c_str(), x, y, z, player ? R"(, "player": true)" : "");
  return buf;
}

Game load(const std::string& name, const std::string& ships, const GameOptions& o = test::options()) {
  return Game::load_level(test::write_level(name, test::level_text(ships)), o);
}

TEST(Capital, CorvetteClassHasTurretsAndSubsystems) {
  const ShipClassDef c = load_ship_class(test::repo("assets/ships/corvette.json"), "corvette", arc::data_root());
  ASSERT_EQ(c.turrets.size(), 4u);
  ASSERT_EQ(c.subsystems.size(), 2u);
  EXPECT_TRUE(c.capital());
  EXPECT_EQ(c.turrets[0].kind, TurretKind::Beam);
  EXPECT_EQ(c.turrets[2].kind, TurretKind::Flak);
  EXPECT_EQ(c.subsystems[0].kind, SubsystemKind::Engine);
  EXPECT_EQ(c.subsystems[1].kind, SubsystemKind::ShieldGenerator);
  EXPECT_GT(c.breakup.stages, 1);
  // Every part lies inside the shield sphere, so a shielded hull stops every shot at it.
  for (size_t i = 0; i < c.part_count(); ++i) {
    Ship s;
    s.cls = &c;
    EXPECT_LT(safe_len(part_position(s, i)) + part_radius(c, i), c.shield_radius) << part_name(c, i);
  }
}

TEST(Capital, TurretArcIsMeasuredFromItsFacingOnTheTurnedShip) {
  TurretDef t;
  t.facing = {0, 1, 0};
  t.arc = 60;
  const glm::dquat level{1, 0, 0, 0};
  const glm::dvec3 mount{0, 10, 0};
  EXPECT_TRUE(turret_can_aim(t, level, mount, {0, 500, 0}));
  EXPECT_TRUE(turret_can_aim(t, level, mount, mount + glm::dvec3(std::sin(59 * kDeg), std::cos(59 * kDeg), 0) * 100.0));
  EXPECT_FALSE(turret_can_aim(t, level, mount, mount + glm::dvec3(std::sin(61 * kDeg), std::cos(61 * kDeg), 0) * 100.0));
  EXPECT_FALSE(turret_can_aim(t, level, mount, {0, -500, 0}));
  // Rolled upside down, the dorsal turret covers what is below.
  const glm::dquat rolled = glm::angleAxis(kPi, glm::dvec3(0, 0, 1));
  EXPECT_TRUE(turret_can_aim(t, rolled, mount, {0, -500, 0}));
  EXPECT_FALSE(turret_can_aim(t, rolled, mount, {0, 500, 0}));
  EXPECT_FALSE(turret_can_aim(t, level, mount, mount));  // no direction at all
}

// A hostile above the bow: the dorsal beam turret fires on it, the keel turret (facing down)
// never does, the flanks' flak only when it is inside their arcs.
TEST(Capital, TurretsFireOnlyInsideTheirArcs) {
  Game g = load("capital_arcs.json", ship_row("Corvette", "corvette", "red", "capital", 0, 0, 0) + "," +
                                         ship_row("Target", "warden", "blue", "none", 0, 400, -55));
  for (int i = 0; i < 240; ++i) g.step(InputFrame{});
  const World& w = g.world();
  const Ship& c = w.ship(test::ship_named(w, "Corvette"));
  const Ship& t = w.ship(test::ship_named(w, "Target"));
  EXPECT_GE(c.parts[test::part_index(c, "bow beam turret")].fired_tick, 0);
  EXPECT_EQ(c.parts[test::part_index(c, "keel beam turret")].fired_tick, -1);
  EXPECT_EQ(c.parts[test::part_index(c, "port flak")].fired_tick, -1);
  EXPECT_LT(t.shield + t.hull, t.cls->shield + t.cls->hull);
}

TEST(Capital, FlakBurstsHurtAFighterOnTheFlank) {
  Game g = load("capital_flak.json", ship_row("Corvette", "corvette", "red", "capital", 0, 0, 0) + "," +
                                         ship_row("Target", "dart", "blue", "none", 300, 0, 15));
  for (int i = 0; i < 300; ++i) g.step(InputFrame{});
  const World& w = g.world();
  const Ship& c = w.ship(test::ship_named(w, "Corvette"));
  const Ship& t = w.ship(test::ship_named(w, "Target"));
  EXPECT_GE(c.parts[test::part_index(c, "starboard flak")].fired_tick, 0);
  EXPECT_EQ(c.parts[test::part_index(c, "port flak")].fired_tick, -1);
  EXPECT_LT(t.shield + t.hull, t.cls->shield + t.cls->hull);
}

TEST(Capital, DestroyedEnginesStopTheShipAndAGeneratorDropsTheShield) {
  Game g = load("capital_parts.json", ship_row("Corvette", "corvette", "red", "capital", 0, 0, 0));
  for (int i = 0; i < 600; ++i) g.step(InputFrame{});
  World& w = g.world_mut();
  Ship& c = w.ship(test::ship_named(w, "Corvette"));
  const double cruising = safe_len(c.velocity);
  ASSERT_GT(cruising, 5.0);
  const size_t engines = test::part_index(c, "engines"), generator = test::part_index(c, "shield generator");
  damage_parts(w, c, part_position(c, engines), 1e6, ShipId{}, int(engines));
  EXPECT_TRUE(engines_down(c));
  EXPECT_FALSE(shield_generators_down(c));
  for (int i = 0; i < 1200; ++i) g.step(InputFrame{});
  EXPECT_LT(safe_len(w.ship(test::ship_named(w, "Corvette")).velocity), cruising * 0.05);
  Ship& c2 = w.ship(test::ship_named(w, "Corvette"));
  ASSERT_GT(c2.shield, 0.0);
  damage_parts(w, c2, part_position(c2, generator), 1e6, ShipId{}, int(generator));
  EXPECT_TRUE(shield_generators_down(c2));
  for (int i = 0; i < 1800; ++i) g.step(InputFrame{});  // longer than the regeneration delay
  EXPECT_EQ(w.ship(test::ship_named(w, "Corvette")).shield, 0.0);
  EXPECT_TRUE(w.ship(test::ship_named(w, "Corvette")).alive);
}

// Beams that reach the hull hurt the part they strike: a turret standing off the hull.
TEST(Capital, HullHitsOnAPartDamageIt) {
  Game g = load("capital_hit.json", ship_row("Corvette", "corvette", "red", "capital", 0, 0, 0));
  World& w = g.world_mut();
  Ship& c = w.ship(test::ship_named(w, "Corvette"));
  c.shield = 0;
  const size_t flak = test::part_index(c, "starboard flak");
  const double before = c.parts[flak].hull;
  apply_damage(w, c, 50, part_position(c, flak) + glm::dvec3(5, 0, 0), ShipId{});
  EXPECT_EQ(c.parts[flak].hull, before - 50);
  apply_damage(w, c, 50, glm::dvec3(0, 0, -90), ShipId{});  // the bow: no part there
  EXPECT_EQ(c.parts[flak].hull, before - 50);
}

// A Viper with torpedoes fires past a hostile fighter at the corvette behind it: the fighter
// takes nothing, the corvette's targeted engines take the whole warhead through the shield.
TEST(Capital, TorpedoHurtsOnlyCapitalShipsAndTheirSubsystems) {
  GameOptions o = test::options();
  o.loadout = "beam+torpedo";
  Game g = load("capital_torpedo.json",
                ship_row("Player", "viper", "blue", "none", 0, 0, 700, true) + "," +
                    ship_row("Fighter", "warden", "red", "none", 0, 0, 450) + "," +
                    ship_row("Corvette", "corvette", "red", "none", 0, 0, 0),
                o);
  World& w = g.world_mut();
  Ship& p = w.ship(w.player);
  EXPECT_EQ(p.secondary, SecondaryWeapon::Torpedo);
  // At a fighter the trigger does nothing.
  p.target = test::ship_named(w, "Fighter");
  InputFrame fire;
  fire.buttons = kFireSecondary;
  g.step(fire);
  EXPECT_TRUE(w.projectiles.empty());
  p.target = test::ship_named(w, "Corvette");
  g.step(InputFrame{}, {Command::TargetSubsystem});
  g.step(InputFrame{}, {Command::TargetSubsystem});
  g.step(InputFrame{}, {Command::TargetSubsystem});
  g.step(InputFrame{}, {Command::TargetSubsystem});
  g.step(InputFrame{}, {Command::TargetSubsystem});  // past the four turrets: the engines
  const Ship& c = w.ship(test::ship_named(w, "Corvette"));
  ASSERT_EQ(target_part(w, w.ship(w.player)), int(test::part_index(c, "engines")));
  g.step(fire);
  ASSERT_EQ(w.projectiles.size(), 1u);
  EXPECT_EQ(w.projectiles[0].kind, SecondaryWeapon::Torpedo);
  for (int i = 0; i < 900 && !w.projectiles.empty(); ++i) g.step(InputFrame{});
  EXPECT_TRUE(w.projectiles.empty());
  const Ship& f = w.ship(test::ship_named(w, "Fighter"));
  EXPECT_EQ(f.hull, f.cls->hull);
  EXPECT_EQ(f.shield, f.cls->shield);
  const Ship& c2 = w.ship(test::ship_named(w, "Corvette"));
  const size_t engines = test::part_index(c2, "engines");
  EXPECT_EQ(c2.parts[engines].hull, c2.cls->subsystems[0].hull - 450);
  EXPECT_LT(c2.shield + c2.hull, c2.cls->shield + c2.cls->hull);
}

TEST(Capital, SubsystemKeyCyclesLivePartsThenTheWholeShip) {
  Game g = load("capital_cycle.json", ship_row("Player", "viper", "blue", "none", 0, 0, 900, true) + "," +
                                          ship_row("Corvette", "corvette", "red", "none", 0, 0, 0) + "," +
                                          ship_row("Other", "dart", "red", "none", 0, 0, -3000));
  World& w = g.world_mut();
  ASSERT_EQ(w.ship(w.player).target, test::ship_named(w, "Corvette"));
  Ship& c = w.ship(test::ship_named(w, "Corvette"));
  c.parts[1].hull = 0;  // the keel turret is gone: skipped
  std::vector<int> seen;
  for (int i = 0; i < 6; ++i) {
    g.step(InputFrame{}, {Command::TargetSubsystem});
    seen.push_back(target_part(w, w.ship(w.player)));
  }
  EXPECT_EQ(seen, (std::vector<int>{0, 2, 3, 4, 5, -1}));
  g.step(InputFrame{}, {Command::TargetSubsystem});
  g.step(InputFrame{}, {Command::TargetNext});  // another target: the part is forgotten
  EXPECT_TRUE(w.ship(w.player).target_part.empty());
}

TEST(Capital, BreakUpBlastsInStagesThenEnds) {
  Game g = load("capital_breakup.json", ship_row("Corvette", "corvette", "red", "capital", 0, 0, 0) + "," +
                                            ship_row("Watcher", "viper", "blue", "none", 0, 0, 2000));
  g.step(InputFrame{});
  World& w = g.world_mut();
  Ship& c = w.ship(test::ship_named(w, "Corvette"));
  c.velocity = {0, 0, -20};
  apply_damage(w, c, 1e7, c.position, ShipId{});
  g.step(InputFrame{});
  EXPECT_FALSE(w.ship(test::ship_named(w, "Corvette")).alive);
  ASSERT_EQ(w.breakups.size(), 1u);
  const glm::dvec3 start = w.breakups[0].position;
  const BreakupDef& d = c.cls->breakup;
  const int64_t total = int64_t(std::llround(d.seconds * 60));
  std::vector<int> stages;
  for (int64_t i = 0; i < total - 2; ++i) {
    g.step(InputFrame{});
    stages.push_back(w.breakups.empty() ? -1 : w.breakups[0].stage);
  }
  ASSERT_EQ(w.breakups.size(), 1u);
  EXPECT_EQ(w.breakups[0].stage, d.stages);
  EXPECT_GT(safe_len(w.breakups[0].position - start), 1.0);  // the wreck drifts
  for (size_t i = 1; i < stages.size(); ++i) EXPECT_LE(stages[i - 1], stages[i]);
  EXPECT_EQ(stages[size_t(total / (d.stages + 1))], 1);  // the first blast after a share of the time
  for (int i = 0; i < 5; ++i) g.step(InputFrame{});
  EXPECT_TRUE(w.breakups.empty());  // the final blast ended it
  EXPECT_FALSE(w.explosions.empty());
}

// Fighters have no parts: their hash words for parts are empty, so old replays keep theirs.
TEST(Capital, FightersHaveNoParts) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  for (const Ship& s : g.world().ships) {
    EXPECT_TRUE(s.parts.empty());
    EXPECT_TRUE(s.primary_cooldown.empty());
  }
}

void expect_class_error(const std::string& text, const std::string& where, const std::string& words) {
  try {
    parse_ship_class(text, "bad.json", "bad");
    ADD_FAILURE() << "no error for " << text;
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("bad.json:" + where + ": ", 0), 0u) << m;
    EXPECT_NE(m.find(words), std::string::npos) << m;
  }
}

TEST(Capital, TurretAndSubsystemBlocksAreValidatedWithPositions) {
  const std::string head = R"({ "model": "m.glb", "mass": 1, "thrust": 1, "max_speed": 1, "hull": 1,
  "collision_radius": 10, "beam": { "mounts": [[0, 0, 0]] },
)";
  expect_class_error(head + R"(  "turrets": [ { "name": "a", "kind": "laser" } ] })", "3:39", "\"flak\"");
  expect_class_error(head + R"(  "turrets": [ { "name": "a", "facing": [0, 0, 0] } ] })", "3:31", "point somewhere");
  expect_class_error(head + R"(  "turrets": [ { "name": "a", "arc": 200 } ] })", "3:38", "arc");
  expect_class_error(head + R"(  "turrets": [ { "name": "a", "colour": 1 } ] })", "3:31", "colour");
  expect_class_error(head + R"(  "turrets": [ { "kind": "beam" } ] })", "3:16", "name");
  expect_class_error(head + R"(  "turrets": [ { "name": "a" } ], "subsystems": [ { "name": "a" } ] })", "3:53",
                     "already on this ship");
  expect_class_error(head + R"(  "subsystems": [ { "name": "e", "kind": "reactor" } ] })", "3:42",
                     "shield_generator");
  expect_class_error(head + R"(  "subsystems": [ { "name": "e", "hull": -1 } ] })", "3:42", "hull");
  expect_class_error(head + R"(  "breakup": { "stages": 99 } })", "3:26", "stages");
}

}  // namespace
}  // namespace arc
