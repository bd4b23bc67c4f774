// Loadouts: their text, the classes that can fly them, the player's choice applied to a level,
// a level's "loadout" block refused with its positions, and the fighters' differences.
#include <gtest/gtest.h>

#include "core/error.h"
#include "game/sim/defs.h"
#include "game/sim/loadout.h"
#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

ShipClassDef ship(const std::string& name) {
  return load_ship_class(test::repo("assets/ships/" + name + ".json"), name, arc::data_root());
}

TEST(Loadout, TextRoundTripsAndBadTextSaysWhatIsAllowed) {
  Loadout l;
  std::string why;
  ASSERT_TRUE(parse_loadout("plasma+torpedo", l, why));
  EXPECT_EQ(l.primary, WeaponKind::Plasma);
  EXPECT_EQ(l.secondary, WeaponKind::Torpedo);
  EXPECT_EQ(loadout_text(l), "plasma+torpedo");
  EXPECT_FALSE(parse_loadout("beam", l, why));
  EXPECT_NE(why.find("PRIMARY+SECONDARY"), std::string::npos) << why;
  EXPECT_FALSE(parse_loadout("beam+laser", l, why));
  EXPECT_NE(why.find("beam, plasma, missile or torpedo"), std::string::npos) << why;
  EXPECT_FALSE(parse_loadout("", l, why));
}

TEST(Loadout, ClassesFlyOnlyTheWeaponsTheyCarry) {
  const ShipClassDef dart = ship("dart"), viper = ship("viper"), warden = ship("warden");
  EXPECT_EQ(loadout_problem(viper, {WeaponKind::Beam, WeaponKind::Torpedo}), "");
  EXPECT_EQ(loadout_problem(viper, {WeaponKind::Plasma, WeaponKind::Missile}), "");
  EXPECT_EQ(loadout_problem(warden, {WeaponKind::Beam, WeaponKind::Torpedo}), "");
  EXPECT_NE(loadout_problem(dart, {WeaponKind::Beam, WeaponKind::Torpedo}).find("carries no torpedo"), std::string::npos);
  EXPECT_NE(loadout_problem(warden, {WeaponKind::Beam, WeaponKind::Plasma}).find("carries no plasma"), std::string::npos);
  EXPECT_NE(loadout_problem(viper, {WeaponKind::Missile, WeaponKind::Plasma}).find("primary bank"), std::string::npos);
  EXPECT_NE(loadout_problem(viper, {WeaponKind::Plasma, WeaponKind::Plasma}).find("different"), std::string::npos);
  EXPECT_NE(loadout_problem(viper, {WeaponKind::Plasma, WeaponKind::Beam}).find("secondary bank"), std::string::npos);
  const ShipClassDef armed = apply_loadout(viper, {WeaponKind::Plasma, WeaponKind::Torpedo});
  EXPECT_TRUE(armed.primary_plasma);
  EXPECT_FALSE(armed.missile.present);
  EXPECT_TRUE(armed.plasma.present);
  EXPECT_TRUE(armed.torpedo.present);
  EXPECT_EQ(armed.name, "viper+plasma+torpedo");
}

// Three fighters that fly differently: the interceptor fastest and most agile, the heavy one
// slowest with the most hull and shield, the Viper between.
TEST(Loadout, ThreeFightersPlayDifferently) {
  const ShipClassDef dart = ship("dart"), viper = ship("viper"), warden = ship("warden");
  EXPECT_GT(dart.max_speed, viper.max_speed);
  EXPECT_GT(viper.max_speed, warden.max_speed);
  EXPECT_GT(dart.turn_rate[1], viper.turn_rate[1]);
  EXPECT_GT(viper.turn_rate[1], warden.turn_rate[1]);
  EXPECT_LT(dart.hull + dart.shield, viper.hull + viper.shield);
  EXPECT_LT(viper.hull + viper.shield, warden.hull + warden.shield);
}

TEST(Loadout, ThePlayersChoiceArmsItsShip) {
  GameOptions o = test::options();
  o.ship = "warden";
  o.loadout = "beam+torpedo";
  Game g = Game::load_level(test::repo("levels/duel.json"), o);
  const Ship& p = g.world().ship(g.world().player);
  EXPECT_EQ(p.cls->name, "warden+beam+torpedo");
  EXPECT_EQ(p.secondary, SecondaryWeapon::Torpedo);
  EXPECT_FALSE(p.cls->missile.present);
  // The other ships keep their classes.
  for (const Ship& s : g.world().ships)
    if (s.id != p.id) {
      EXPECT_EQ(s.cls->name, "viper");
    }
  // Plasma on the primary trigger: it fires bolts and no beam.
  o.ship = "viper";
  o.loadout = "plasma+missile";
  Game h = Game::load_level(test::repo("levels/duel.json"), o);
  InputFrame fire;
  fire.buttons = kFirePrimary;
  for (int i = 0; i < 30; ++i) h.step(fire);
  const Ship& q = h.world().ship(h.world().player);
  EXPECT_FALSE(q.beam_firing);
  EXPECT_GT(q.stats.plasma_fired, 1);
  EXPECT_EQ(q.secondary, SecondaryWeapon::Missile);
}

TEST(Loadout, ABadChoiceNamesItsOption) {
  GameOptions o = test::options();
  o.loadout = "beam+laser";
  try {
    Game::load_level(test::repo("levels/duel.json"), o);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--loadout: ", 0), 0u) << e.what();
  }
  o.loadout = "";
  o.ship = "battleship";
  try {
    Game::load_level(test::repo("levels/duel.json"), o);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--ship: ship class 'battleship' not found", 0), 0u) << e.what();
  }
  o.ship = "dart";
  o.loadout = "beam+missile";
  EXPECT_THROW(Game::load_level(test::repo("levels/duel.json"), o), InputError);
}

void expect_level_error(const std::string& block, const std::string& where, const std::string& words) {
  const std::string text = test::level_text(R"({ "name": "P", "class": "viper", "team": "blue", "player": true })",
                                            "\n  \"loadout\": " + block + ",");
  try {
    parse_level_def(text, "bad.json", arc::data_root());
    ADD_FAILURE() << "no error for " << block;
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("bad.json:" + where + ": ", 0), 0u) << m;
    EXPECT_NE(m.find(words), std::string::npos) << m;
  }
}

TEST(Loadout, LevelBlockIsValidatedWithPositions) {
  const std::string ok = R"({ "ships": ["viper", "dart"], "weapons": ["beam", "torpedo", "plasma"], "suggested_ship": "viper", "suggested_loadout": "beam+torpedo" })";
  const LevelDef L = parse_level_def(
      test::level_text(R"({ "name": "P", "class": "viper", "team": "blue", "player": true })", "\n  \"loadout\": " + ok + ","),
      "ok.json", arc::data_root());
  ASSERT_TRUE(L.loadout.present);
  EXPECT_EQ(L.loadout.ships, (std::vector<std::string>{"viper", "dart"}));
  EXPECT_EQ(L.loadout.suggested, (Loadout{WeaponKind::Beam, WeaponKind::Torpedo}));
  expect_level_error(R"({ "ships": ["corsair"], "weapons": ["beam", "missile"], "suggested_ship": "corsair", "suggested_loadout": "beam+missile" })",
                     "7:26", "not found");
  expect_level_error(R"({ "ships": ["viper"], "weapons": ["beam", "laser"], "suggested_ship": "viper", "suggested_loadout": "beam+missile" })",
                     "7:56", "beam, plasma, missile or torpedo");
  expect_level_error(R"({ "ships": ["viper"], "weapons": ["beam"], "suggested_ship": "viper", "suggested_loadout": "beam+missile" })",
                     "7:47", "at least two");
  expect_level_error(R"({ "ships": ["viper"], "weapons": ["beam", "missile"], "suggested_ship": "dart", "suggested_loadout": "beam+missile" })",
                     "7:86", "must be one of 'ships'");
  expect_level_error(R"({ "ships": ["viper"], "weapons": ["beam", "missile"], "suggested_ship": "viper", "suggested_loadout": "beam+torpedo" })",
                     "7:116", "which 'weapons' does not allow");
  expect_level_error(R"({ "ships": ["dart"], "weapons": ["beam", "missile"], "suggested_ship": "dart", "suggested_loadout": "beam+missile" })",
                     "7:114", "carries no missile");
  expect_level_error(R"({ "ships": ["viper"], "weapons": ["beam", "missile"], "suggested_ship": "viper", "suggested_loadout": "beam+missile", "locked": 1 })",
                     "7:132", "locked");
}

}  // namespace
}  // namespace arc
