// game/net/match_record.h — every network match as a replay: all slots' inputs by tick.
//
// A match record is text, versioned like the replay scripts:
//   arcfire-match 1
//   level levels/arena.json
//   seed 3303
//   slots 8
//   pilot 0 Host            one line per piloted slot: its slot and name
//   drop 1 920              slot 1's pilot left; the AI flies it from tick 920 on
//   in 1 0 0 0 0 64 0 0 1   tick, slot, pitch yaw roll throttle strafe_x strafe_y, buttons, then
//                           its commands by number (only ticks where a slot's input changed)
//   hash 60 0123456789abcdef
//   end 3600
// replay_match() steps the level with those inputs, as the match did, and checks every hash
// line: `arcfire --replay-match FILE` (exit 1 at the first differing tick).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "game/net/rollback.h"

namespace arc {

constexpr int kMatchRecordVersion = 1;

// The record of `session` up to its last final tick, hashes every `hash_every` ticks and at the end.
std::string match_record_text(const RollbackSession& session, const std::string& level, uint64_t seed,
                              const std::vector<std::string>& names, int hash_every = 60);

struct MatchReplayResult {
  int64_t ticks = 0;
  int64_t hashes_checked = 0;
  int64_t first_bad_tick = -1;  // −1: every hash matched
  uint64_t last_hash = 0;
};

// InputError "path:line: ..." for a malformed record.
MatchReplayResult replay_match(const std::string& path, const GameOptions& options);

}  // namespace arc
