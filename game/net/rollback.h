// game/net/rollback.h — rollback on the deterministic simulation (GGPO's model, no sockets).
//
// Each slot's inputs arrive by tick. The local slot's input is applied at once (after
// `input_delay` ticks); a remote slot's tick not yet received is predicted by repeating its last
// input (without its commands, which are edge-triggered). Before a tick that uses a prediction
// the state is kept; when the real input differs from the prediction used, the next advance()
// restores the state before that tick and re-simulates to the present. A slot whose pilot was
// dropped is flown by the AI from the drop tick on, on every peer alike.
//
// What the pilot sees and hears is read from the World after each advance (RenderView,
// SoundEventTracker diff the worlds they are shown), so effects and sounds of predicted ticks a
// rollback undoes are never played twice: only the corrected world is ever presented.
//
// Example, compiled as NetRollback.Example in tests/unit/net/test_rollback.cpp:
//   RollbackSession s(Game::load_level("levels/duel.json", {}), {2, 0, 0});
//   s.add_local_input(SlotInput{});
//   s.advance();
//   SlotInput fast;
//   fast.input.throttle = 127;
//   EXPECT_TRUE(s.add_remote_input(1, 1, fast));
#pragma once
#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "game/sim/game.h"

namespace arc {

struct RollbackConfig {
  int slots = 1;
  int local_slot = 0;
  int input_delay = 0;       // 0..4
  int max_prediction = 12;   // ticks the session may run past the last confirmed tick
  std::vector<bool> piloted; // per slot; empty: all
};

struct RollbackStats {
  uint64_t rollbacks = 0;        // restores
  uint64_t resimulated = 0;      // ticks stepped again after a restore
  uint64_t ticks = 0;            // ticks advanced
  uint64_t predicted = 0;        // ticks stepped with at least one predicted input
  uint64_t saves = 0;            // states kept
  int max_depth = 0;             // the deepest rollback in ticks
  double max_correction_m = 0;   // the farthest a ship jumped when a rollback corrected it
};

class RollbackSession {
 public:
  static constexpr int64_t kNever = std::numeric_limits<int64_t>::max();

  RollbackSession(Game game, RollbackConfig config);

  int64_t tick() const { return tick_; }
  const Game& game() const { return game_; }
  Game& game_mut() { return game_; }
  const RollbackConfig& config() const { return cfg_; }
  const RollbackStats& stats() const { return stats_; }

  // The local pilot's input for the next tick the delay leaves free; returns that tick.
  int64_t add_local_input(const SlotInput& in);
  // A slot's input for tick t (t ≥ 1), accepted only as the next of its contiguous run; a
  // tick already known keeps its first input. Returns whether it was new.
  bool add_remote_input(int slot, int64_t t, const SlotInput& in);
  // The AI flies the slot's ship from tick t on (inputs from then on are ignored).
  void drop_slot(int slot, int64_t from_tick);
  bool dropped(int slot) const { return drop_from_[size_t(slot)] != kNever; }

  // The last tick of the slot's contiguous inputs (0: none yet; kNever once dropped).
  int64_t received(int slot) const;
  int64_t confirmed() const;  // every slot's input known up to this tick
  // Ticks up to this one were simulated with real inputs only: their hashes are final.
  // (A real input that differed from its prediction makes its tick and the later ones wait
  // for the re-simulation.)
  int64_t final_tick() const { return std::min({confirmed(), tick_, pending_ - 1}); }
  uint64_t hash_at(int64_t t) const { return hashes_.at(size_t(t)); }

  // The next tick is inside the prediction window (its local input may still be missing).
  bool window_open() const { return tick_ + 1 - cfg_.max_prediction <= confirmed(); }
  bool can_advance() const;
  // Called after every step (re-simulated ones too), before the tick's hash: tests alter a
  // peer's state with it to force a desync.
  std::function<void(Game&, int64_t tick)> after_step;
  // Rolls back if a real input differed from its prediction, then steps one tick.
  void advance();
  // Only the rollback, when one is due: the present state re-simulated with the inputs known.
  void settle();

  // The inputs a slot flew with, tick 1 on (its known ones; for a dropped slot up to the drop).
  const std::vector<SlotInput>& inputs(int slot) const { return known_[size_t(slot)]; }
  int64_t drop_tick(int slot) const { return drop_from_[size_t(slot)]; }

 private:
  const SlotInput& input_for(int slot, int64_t t, bool* predicted) const;
  void step_one();
  void save_state();

  Game game_;
  RollbackConfig cfg_;
  RollbackStats stats_;
  int64_t tick_ = 0;
  int64_t pending_ = kNever;  // earliest tick whose input differed from the one used
  std::vector<std::vector<SlotInput>> known_;  // per slot: inputs of ticks 1.. (index t − 1)
  std::vector<std::vector<SlotInput>> used_;   // per slot: what each tick was stepped with
  std::vector<int64_t> drop_from_;
  std::vector<uint64_t> hashes_;               // index t: hash after tick t (index 0: the start)
  std::vector<int64_t> ring_tick_;  // the tick each kept state is at (−1: none)
  std::vector<Game> ring_;          // kept states, by tick modulo the ring's size
};

}  // namespace arc
