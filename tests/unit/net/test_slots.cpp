// tests/unit/net/test_slots.cpp — the "slots" block of levels: what loads and what is refused.
#include <gtest/gtest.h>

#include "core/error.h"
#include "game/sim/defs.h"
#include "game/sim/game.h"

namespace arc {
namespace {

std::string level_with(const std::string& slots) {
  return R"({"name": "t", "objective": "o", "win": {"type": "destroy_all_hostiles"}, "lose": {"type": "none"},
  "ships": [
    {"name": "P", "class": "viper", "team": "blue", "player": true},
    {"name": "R", "class": "viper", "team": "red", "position": [0, 0, -500]},
    {"name": "G", "class": "viper", "team": "red", "ai": "gunner", "position": [0, 0, -900]}
  ],
  "slots": )" + slots + "}";
}

std::string error_of(const std::string& slots) {
  try {
    parse_level_def(level_with(slots), "t.json", ".");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(NetSlots, LoadsAndCounts) {
  LevelDef L = parse_level_def(level_with(R"([{"ship": "P"}, {"ship": "R"}])"), "t.json", ".");
  ASSERT_EQ(L.slots.size(), 2u);
  EXPECT_EQ(L.slots[1].team, "red");
  EXPECT_EQ(Game::load_level("levels/arena.json", {}).slot_count(), 8u);
}

TEST(NetSlots, RefusesWithPosition) {
  EXPECT_EQ(error_of(R"([{"ship": "P"}, {"ship": "X"}])"), "t.json:7:29: 'slots[1].ship' names no ship of 'ships': \"X\"");
  EXPECT_NE(error_of(R"([{"ship": "P"}, {"ship": "P"}])").find("has two slots"), std::string::npos);
  EXPECT_NE(error_of(R"([{"ship": "P"}, {"ship": "G"}])").find("must be the player or a fighter"), std::string::npos);
  EXPECT_NE(error_of(R"([{"ship": "R"}, {"ship": "P"}])").find("first slot must be the player's ship"), std::string::npos);
  EXPECT_NE(error_of(R"([])").find("at least one"), std::string::npos);
  EXPECT_NE(error_of(R"([{"ship": "P", "team": "x"}])").find("team"), std::string::npos);
}

}  // namespace
}  // namespace arc
