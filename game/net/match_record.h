// game/net/match_record.h — every network match as a replay script: all slots' inputs by tick.
//
// A match record is a replay script of format version 2 (tests/replays/README.md): the
// level, seed, difficulty and simulation settings the match ran under, `slots N`, a `pilot`
// line per piloted slot (and `drop` where its pilot left), each slot's input changes and
// commands as `T slot K ...` lines, the state hash every `hash_every` ticks and at the end:
//   arcfire-replay 2
//   level levels/arena.json
//   seed 3303
//   ...
//   slots 8
//   pilot 0 Host
//   pilot 1 Pilot1
//   drop 1 919              the AI flies slot 1's ship from step 920 on
//   0 axis throttle 0.5039  slot 0's input for step 1
//   0 slot 1 press fire_primary
//   60 hash 0123456789abcdef
//   3600 end
// `arcfire --headless --replay FILE` plays it like any replay (hash checks, --audio-out,
// snapshots added by hand).
//
// Example, compiled as NetMatchRecord.Example in tests/unit/replay/test_match_replay.cpp:
//   const std::string text = match_record_text(session, "levels/duel.json", {"Host", "Pilot1"});
//   replay::Script s = replay::parse_script(text, "match.replay", all_settings());
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "game/net/rollback.h"

namespace arc {

// The record of `session` up to its last final tick, or `last_tick` if that is sooner (a match
// of N ticks whose peers ran on while they said goodbye); `level` as the replay should name it
// (relative to the data root), `names` by slot.
std::string match_record_text(const RollbackSession& session, const std::string& level,
                              const std::vector<std::string>& names, int64_t last_tick = RollbackSession::kNever,
                              int hash_every = 60);

}  // namespace arc
