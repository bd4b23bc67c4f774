// tests/unit/net/test_rollback.cpp — RollbackSession against a plain run with the same inputs.
#include <gtest/gtest.h>

#include "game/net/rollback.h"
#include "game/sim/world.h"
#include "net_match_harness.h"

namespace arc {
namespace {

TEST(NetRollback, Example) {
  RollbackSession s(Game::load_level("levels/duel.json", {}), {2, 0, 0});
  s.add_local_input(SlotInput{});
  s.advance();
  SlotInput fast;
  fast.input.throttle = 127;
  EXPECT_TRUE(s.add_remote_input(1, 1, fast));
  s.add_local_input(SlotInput{});
  s.advance();
  EXPECT_EQ(s.stats().rollbacks, 1u);
  EXPECT_EQ(s.tick(), 2);
  EXPECT_EQ(s.final_tick(), 1);
}

// Late remote inputs, applied by rollback, end in the state of a run that knew them at once.
TEST(NetRollback, LateInputsReachTheSameState) {
  const Game start = Game::load_level("levels/duel.json", {});
  Game plain(start);
  plain.set_pilots({true, true});
  RollbackSession s(Game(start), {2, 0, 0, 12});
  const int ticks = 240, lag = 7;
  for (int t = 1; t <= ticks + lag; ++t) {
    if (t <= ticks) {
      plain.step_slots({nettest::scripted_input(0, t), nettest::scripted_input(1, t)});
      s.add_local_input(nettest::scripted_input(0, t));
      s.advance();
    }
    if (t - lag >= 1) s.add_remote_input(1, t - lag, nettest::scripted_input(1, t - lag));
  }
  s.add_local_input(SlotInput{});
  s.advance();  // applies the last rollback
  EXPECT_GT(s.stats().rollbacks, 10u);
  EXPECT_EQ(s.final_tick(), ticks);
  Game check(start);
  check.set_pilots({true, true});
  for (int t = 1; t <= ticks; ++t) check.step_slots({nettest::scripted_input(0, t), nettest::scripted_input(1, t)});
  EXPECT_EQ(s.hash_at(ticks), check.hash());
  EXPECT_EQ(plain.hash(), check.hash());
}

// Alone, a pilot of a level with slots flies it exactly as the single-player game does.
TEST(NetRollback, OnePilotMatchesSinglePlayerWithoutAi) {
  const Game start = Game::load_level("levels/duel.json", {});
  Game single(start), slots(start);
  slots.set_pilots({true, true});
  for (int t = 1; t <= 120; ++t) {
    single.step(nettest::scripted_input(0, t).input);
    slots.step_slots({SlotInput{nettest::scripted_input(0, t).input, {}}, SlotInput{}});
  }
  // The player's ship flew the same; the second slot's ship flew a pilot's empty input, not the AI.
  EXPECT_EQ(single.world().ships[0].position, slots.world().ships[0].position);
  Game ai(start);
  ai.set_pilots({true, false});
  for (int t = 1; t <= 120; ++t) ai.step_slots({SlotInput{nettest::scripted_input(0, t).input, {}}, SlotInput{}});
  EXPECT_EQ(single.world().ships[1].position, ai.world().ships[1].position);
}

// A host with no pilot at all (every slot flown by the AI) still runs: nothing is ever
// confirmed, and the prediction window must not overflow past "never".
TEST(NetRollback, EverySlotFlownByTheAiAdvances) {
  RollbackSession s(Game::load_level("levels/duel.json", {}), {2, 0, 0, 12, {false, false}});
  EXPECT_EQ(s.confirmed(), RollbackSession::kNever);
  for (int t = 1; t <= 30; ++t) {
    ASSERT_TRUE(s.window_open()) << "tick " << t;
    s.add_local_input(SlotInput{});
    s.advance();
  }
  EXPECT_EQ(s.tick(), 30);
  EXPECT_EQ(s.final_tick(), 30);
}

}  // namespace
}  // namespace arc
