// tests/unit/net/test_net_match.cpp — whole matches over the link simulator: identical hashes
// under latency and loss, no rollback on a perfect link, a forced desync at its tick, drops.
#include <algorithm>

#include <gtest/gtest.h>

#include "net_match_harness.h"

namespace arc::nettest {
namespace {

void expect_same_hashes(const MatchResult& r, size_t ticks) {
  for (size_t p = 0; p < r.hashes.size(); ++p) {
    ASSERT_GE(r.hashes[p].size(), ticks) << "peer " << p;
    for (size_t t = 0; t < ticks; ++t)
      ASSERT_EQ(r.hashes[p][t], r.hashes[0][t]) << "peer " << p << " differs at tick " << t + 1;
    EXPECT_FALSE(r.desync[p]) << "peer " << p;
  }
}

TEST(NetMatch, PerfectLinkNeverRollsBack) {
  MatchSetup m;
  m.ticks = 300;
  m.input_delay = 2;  // covers the relay's frame through the host
  MatchResult r = run_match(m);
  expect_same_hashes(r, 300);
  for (const RollbackStats& s : r.stats) EXPECT_EQ(s.rollbacks, 0u);
}

TEST(NetMatch, SameHashesUnderLatencyJitterAndLoss) {
  MatchSetup m;
  m.ticks = 600;
  m.link = {.latency_ms = 25, .jitter_ms = 10, .loss = 0.05, .duplicate = 0.02, .reorder = 0.02, .seed = 5};
  MatchResult r = run_match(m);  // 100 ms between pilots through the host: 4 × 25 ms
  expect_same_hashes(r, 600);
  uint64_t rollbacks = 0, resim = 0;
  double jump = 0;
  for (const RollbackStats& s : r.stats) rollbacks += s.rollbacks, resim += s.resimulated, jump = std::max(jump, s.max_correction_m);
  EXPECT_GT(rollbacks, 0u);
  std::printf("[ figures ] rollbacks %llu resimulated %llu lost %llu largest correction %.2f m\n", (unsigned long long)rollbacks,
              (unsigned long long)resim, (unsigned long long)r.link.lost, jump);
}

TEST(NetMatch, FourPilotsAgree) {
  MatchSetup m;
  m.level = "levels/arena.json";
  m.peers = 4;
  m.ticks = 240;
  m.link = {.latency_ms = 25, .jitter_ms = 10, .loss = 0.05, .seed = 9};
  MatchResult r = run_match(m);
  expect_same_hashes(r, 240);
}

TEST(NetMatch, ForcedDesyncIsReportedAtItsTick) {
  MatchSetup m;
  m.ticks = 400;
  m.link = {.latency_ms = 20, .jitter_ms = 5, .loss = 0.05, .seed = 3};
  m.corrupt_peer = 1;
  m.corrupt_tick = 150;
  MatchResult r = run_match(m);
  for (size_t p = 0; p < r.desync.size(); ++p) {
    ASSERT_TRUE(r.desync[p]) << "peer " << p;
    EXPECT_EQ(*r.desync[p], 150) << "peer " << p;
  }
}

TEST(NetMatch, SilentPilotIsDroppedToTheAi) {
  MatchSetup m;
  m.peers = 2;
  m.ticks = 500;
  m.silent_peer = 1;
  m.silent_from_ms = 2000;
  m.timeout_ms = 1500;
  MatchResult r = run_match(m);
  EXPECT_EQ(r.dropped[0], 1);
  EXPECT_GE(r.hashes[0].size(), 500u);  // the host plays on
  EXPECT_FALSE(r.desync[0]);
}

TEST(NetMatch, GarbageIsCountedNotThrown) {
  NetPeer host(Game::load_level("levels/duel.json", {}), {.slots = 2, .local_slot = 0, .host = true});
  std::vector<uint8_t> junk(64, 0xAB);
  host.receive(1, junk.data(), junk.size(), 0);
  net::Inputs spoof;
  spoof.slot = 0;  // a pilot claiming the host's slot
  std::vector<uint8_t> b = net::encode(spoof, 1);
  host.receive(1, b.data(), b.size(), 0);
  spoof.slot = 1;
  b = net::encode(spoof, 2);
  host.receive(1, b.data(), b.size(), 0);
  host.receive(1, b.data(), b.size(), 0);  // replayed
  EXPECT_EQ(host.counters().malformed, 1u);
  EXPECT_EQ(host.counters().refused, 1u);
  EXPECT_EQ(host.counters().stale, 1u);
  for (int i = 0; i < 400; ++i) host.receive(1, junk.data(), junk.size(), 10);
  EXPECT_GT(host.counters().rate_limited, 0u);
}

}  // namespace
}  // namespace arc::nettest
