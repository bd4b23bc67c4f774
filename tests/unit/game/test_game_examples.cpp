// The usage examples of game/sim's header banners as tests (HeaderExamples.MatchTheirTests
// keeps each banner and its test the same text).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/data_root.h"
#include "game/sim/defs.h"
#include "game/sim/game.h"
#include "game/sim/serialize.h"

namespace arc {
namespace {

// The examples name files relative to the source folder, as the game runs from it.
struct InSourceDir {
  std::filesystem::path cwd = std::filesystem::current_path();
  InSourceDir() { std::filesystem::current_path(arc::data_root()); }
  ~InSourceDir() { std::filesystem::current_path(cwd); }
};

TEST(GameExamples, LoadALevel) {
  const InSourceDir here;
  LevelDef level = load_level_def("levels/duel.json", ".");   // also loads the ship classes
  EXPECT_EQ(level.name, "Duel");
  EXPECT_EQ(level.seed, 1101u);
}

TEST(GameExamples, StepAndHash) {
  const InSourceDir here;
  const InputFrame input{};
  const std::vector<Command> commands;
  Game game = Game::load_level("levels/duel.json", GameOptions{});   // InputError on bad files
  for (int tick = 0; tick < 60; ++tick) game.step(input, commands);
  uint64_t h = game.hash();
  Game again = Game::load_level("levels/duel.json", GameOptions{});
  for (int tick = 0; tick < 60; ++tick) again.step(input, commands);
  EXPECT_EQ(h, again.hash()) << "the same level, inputs and ticks give the same hash";
}

TEST(GameExamples, SaveAndLoad) {
  const InSourceDir here;
  const GameOptions base;
  Game game = Game::load_level("levels/duel.json", base);
  for (int tick = 0; tick < 30; ++tick) game.step(InputFrame{});
  const World& w = game.world();
  std::vector<uint8_t> bytes = save_world(w);
  GameOptions o = snapshot_options(bytes, base);     // the level is loaded with these
  Game copy = Game::load_level("levels/duel.json", o);
  World& w2 = copy.world_mut();
  load_world(w2, bytes);                             // w2: that level, freshly initialised
  EXPECT_EQ(copy.hash(), game.hash());
}

}  // namespace
}  // namespace arc
