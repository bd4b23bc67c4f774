// tests/unit/net/test_packet.cpp — the packet codec: round trips, and refusals of bad bytes.
#include <gtest/gtest.h>

#include "game/net/packet.h"

namespace arc::net {
namespace {

std::optional<Decoded> round(const Packet& p) {
  std::vector<uint8_t> b = encode(p, 7);
  std::string why;
  std::optional<Decoded> d = decode(b.data(), b.size(), &why);
  EXPECT_TRUE(d) << why;
  return d;
}

TEST(NetPacket, RoundTrip) {
  net::Packet p = net::Ping{1, 0, false, 1234};
  std::vector<uint8_t> bytes = net::encode(p, /*seq=*/7);
  std::string why;
  std::optional<net::Decoded> d = net::decode(bytes.data(), bytes.size(), &why);  // d->packet == p
  ASSERT_TRUE(d) << why;
  EXPECT_EQ(d->seq, 7u);
  EXPECT_EQ(d->packet, p);
}

TEST(NetPacket, EveryTypeRoundTrips) {
  Inputs in;
  in.slot = 3, in.current_tick = 99, in.advantage = -2, in.acks = {1, 2, 3, 4};
  in.first_tick = 90;
  SlotInput s;
  s.input.pitch = -127, s.input.throttle = 127, s.input.buttons = 5;
  s.commands = {Command::TargetNext, Command::Countermeasure};
  in.inputs = {s, SlotInput{}};
  in.first_hash_tick = 80, in.hashes = {0x1234567890abcdefull, 7};
  Welcome w{1, 2, 3, 3, 42, 0, {"host", "pilot"}, "levels/duel.json"};
  for (const Packet& p : std::vector<Packet>{Hello{1, 2, 3, "Ace"}, w, Reject{"level differs"}, in,
                                             Ping{0, 1, true, 5}, Drop{2, 100}, Desync{1, 5}, Bye{0, 9}}) {
    std::optional<Decoded> d = round(p);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->packet, p);
  }
}

TEST(NetPacket, RefusesWhatIsWrong) {
  std::string why;
  std::vector<uint8_t> b = encode(Drop{2, 100}, 1);
  EXPECT_FALSE(decode(b.data(), b.size() - 1, &why));
  EXPECT_NE(why.find("truncated"), std::string::npos) << why;
  std::vector<uint8_t> longer = b;
  longer.push_back(0);
  EXPECT_FALSE(decode(longer.data(), longer.size(), &why));
  std::vector<uint8_t> version = b;
  version[2] = 9;
  EXPECT_FALSE(decode(version.data(), version.size(), &why));
  EXPECT_EQ(why, "protocol version 9, this build speaks 1");
  std::vector<uint8_t> slot = encode(Drop{9, 1}, 1);
  EXPECT_FALSE(decode(slot.data(), slot.size(), &why));
  // Pause may not come from another peer.
  Inputs in;
  SlotInput s;
  s.commands = {Command::Pause};
  in.inputs = {s};
  std::vector<uint8_t> pause = encode(in, 1);
  EXPECT_FALSE(decode(pause.data(), pause.size(), &why));
  EXPECT_NE(why.find("not a ship command"), std::string::npos) << why;
  EXPECT_FALSE(decode(nullptr, 0, &why));
  std::vector<uint8_t> huge(kMaxPacketBytes + 1, 0);
  EXPECT_FALSE(decode(huge.data(), huge.size(), &why));
}

}  // namespace
}  // namespace arc::net
