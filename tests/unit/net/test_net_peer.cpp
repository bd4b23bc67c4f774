// tests/unit/net/test_net_peer.cpp — one network peer (game/net/net_peer.h): its header
// example, and the packets a frame hands the transport.
#include <gtest/gtest.h>

#include <vector>

#include "game/net/link_sim.h"
#include "game/net/net_peer.h"

namespace arc {
namespace {

TEST(NetPeer, Example) {
  LinkSim link;
  const double now_ms = 0;
  NetPeer a(Game::load_level("levels/duel.json", {}), {.slots = 2, .local_slot = 0});
  a.frame(SlotInput{}, now_ms);
  for (NetPeer::Outgoing& o : a.take_outgoing()) link.send(0, 1, o.bytes, o.reliable, now_ms);
  EXPECT_GT(link.counters().sent, 0u);
  EXPECT_EQ(a.local_slot(), 0);
  EXPECT_FALSE(a.desync_tick());
}

TEST(NetPeer, AFrameSendsItsInputAndCountsIt) {
  NetPeer a(Game::load_level("levels/duel.json", {}), {.slots = 2, .local_slot = 0});
  a.frame(SlotInput{}, 0);
  const std::vector<NetPeer::Outgoing> out = a.take_outgoing();
  ASSERT_FALSE(out.empty());
  for (const NetPeer::Outgoing& o : out) EXPECT_FALSE(o.bytes.empty());
  EXPECT_TRUE(a.take_outgoing().empty());  // taken once
  EXPECT_EQ(a.counters().malformed, 0u);
}

}  // namespace
}  // namespace arc
