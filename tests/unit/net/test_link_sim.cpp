// tests/unit/net/test_link_sim.cpp — the in-process link simulator (game/net/link_sim.h): its
// header example, and a lossy link that loses about its share and delivers the rest late.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "game/net/link_sim.h"

namespace arc {
namespace {

struct Peer {
  std::vector<std::vector<uint8_t>> got;
  void receive(int, const std::vector<uint8_t>& bytes) { got.push_back(bytes); }
};

TEST(NetLink, Example) {
  const std::vector<uint8_t> bytes{1, 2, 3};
  const double now_ms = 0;
  Peer peer[2];
  LinkSim link({.latency_ms = 50, .jitter_ms = 20, .loss = 0.05});
  link.send(0, 1, bytes, /*reliable=*/false, now_ms);
  for (LinkSim::Delivery& d : link.poll(now_ms + 100)) peer[d.to].receive(d.from, d.bytes);
  EXPECT_EQ(peer[1].got.size() + link.counters().lost, 1u);
  EXPECT_TRUE(peer[0].got.empty());
}

TEST(NetLink, LosesItsShareAndDeliversWithinTheJitter) {
  LinkSim link({.latency_ms = 50, .jitter_ms = 20, .loss = 0.05});
  const std::vector<uint8_t> bytes{7};
  for (int i = 0; i < 2000; ++i) link.send(0, 1, bytes, false, i);
  EXPECT_TRUE(link.poll(2000 + 29).size() < 2000u);
  const std::vector<LinkSim::Delivery> rest = link.poll(1e9);
  EXPECT_GT(link.counters().lost, 60u);
  EXPECT_LT(link.counters().lost, 140u);
  for (const LinkSim::Delivery& d : rest) EXPECT_LE(d.at_ms, 1999 + 70 + 1e-9);
}

}  // namespace
}  // namespace arc
