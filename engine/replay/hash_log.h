// replay/hash_log.h — the per-tick state-hash log of a replay (golden/<script>/hashes.txt).
//
// A script's `hash` lines check a few ticks; the log holds the cheap hash of every tick (and
// the full hash, every particle included, every `full_every` ticks), so a mismatch can be
// traced to the first tick that diverged and the state there dumped. The log is written by
// --update-golden beside the snapshots and read back on every replay.
//
//   arcfire-hashlog 1
//   0 5c1f0e6a9b3d2c47 9e02d4c1a0b37f55      tick, cheap hash, full hash (every N ticks)
//   1 0f3c...
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace arc::replay {

struct HashLog {
  std::vector<uint64_t> hashes;  // hashes[t] = the cheap state hash after t steps
  std::vector<std::pair<uint64_t, uint64_t>> full;  // (tick, full hash), ascending ticks
};

HashLog parse_hash_log(const std::string& text, const std::string& path);  // InputError on bad lines
std::string write_hash_log(const HashLog& log);

}  // namespace arc::replay
