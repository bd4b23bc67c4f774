// tests/unit/net/net_match_harness.h — whole matches between NetPeers over a LinkSim, the host
// in the middle as over ENet, each slot flying a scripted input that changes every few ticks.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "game/net/link_sim.h"
#include "game/net/net_peer.h"

namespace arc::nettest {

struct MatchSetup {
  std::string level = "levels/duel.json";
  std::string root = ".";  // the data root (GameOptions::root_dir)
  int peers = 2;
  int ticks = 600;
  int input_delay = 0;
  LinkConfig link;
  int corrupt_peer = -1;      // this peer's state is altered at corrupt_tick
  int64_t corrupt_tick = 0;
  int silent_peer = -1;       // this peer stops sending at silent_from_ms
  double silent_from_ms = 0;
  double timeout_ms = 5000;
};

struct MatchResult {
  std::vector<std::vector<uint64_t>> hashes;  // per peer: final hashes of ticks 1..
  std::vector<RollbackStats> stats;
  std::vector<PeerCounters> counters;
  std::vector<std::optional<int64_t>> desync;
  std::vector<int64_t> dropped;
  LinkSim::Counters link;
  double seconds = 0;  // simulated time
};

// The input slot s flies at tick t: held for 12 ticks, then another.
SlotInput scripted_input(int slot, int64_t t);
MatchResult run_match(const MatchSetup& setup);

}  // namespace arc::nettest
