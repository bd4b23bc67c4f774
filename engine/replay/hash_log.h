// replay/hash_log.h — the per-tick state-hash log of a replay (golden/<script>/hashes.txt).
//
// A script's `hash` lines check a few ticks; the log holds the cheap hash of every tick, so a
// mismatch can be traced to the first tick that diverged and the state there dumped. The log
// is written by --update-golden beside the snapshots and read back on every replay.
//
//   arcfire-hashlog 1
//   0 5c1f0e6a9b3d2c47
//   1 ...
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace arc::replay {

struct HashLog {
  std::vector<uint64_t> hashes;  // hashes[t] = the cheap state hash after t steps
};

HashLog parse_hash_log(const std::string& text, const std::string& path);  // InputError on bad lines
std::string write_hash_log(const HashLog& log);

}  // namespace arc::replay
