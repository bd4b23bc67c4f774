// game/net/packet.h — the network match's packets: versioned, bounds-checked, never throwing.
//
// Every packet starts with a 9-byte header: "AF", the protocol version (u16), the type (u8) and
// the sender's sequence number (u32), little-endian. decode() checks every length against the
// bytes left and every value against its range before anything is allocated, and answers a
// malformed packet with std::nullopt and one line saying what is wrong. The peers' rules on top
// (a pilot's inputs only for its own slot, sequence and rate checks) are in net_peer.cpp.
//
// Example, compiled as NetPacket.RoundTrip in tests/unit/net/test_packet.cpp:
//   net::Packet p = net::Ping{1, 0, false, 1234};
//   std::vector<uint8_t> bytes = net::encode(p, /*seq=*/7);
//   std::string why;
//   std::optional<net::Decoded> d = net::decode(bytes.data(), bytes.size(), &why);  // d->packet == p
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "game/sim/input.h"

namespace arc::net {

constexpr uint16_t kProtocolVersion = 1;
constexpr size_t kHeaderBytes = 9;
constexpr size_t kMaxPacketBytes = 1400;         // under a common path MTU: never fragmented
constexpr int kMaxSlots = 8;
constexpr int kMaxInputsPerPacket = 40;
constexpr int kMaxHashesPerPacket = 16;
constexpr int kMaxCommandsPerTick = 8;
constexpr size_t kMaxNameBytes = 24;
constexpr size_t kMaxTextBytes = 200;
constexpr uint32_t kMaxTick = 100000000;          // 19 days at 60 Hz

enum class PacketType : uint8_t { Hello = 1, Welcome, Reject, Inputs, Ping, Drop, Desync, Bye, Lobby };

// A pilot asks to join: what must match the host's exactly, and its name.
struct Hello {
  uint64_t build_id = 0;
  uint64_t level_hash = 0;   // the level file's bytes
  uint64_t asset_hash = 0;   // the data root's content (ships, effects, settings)
  std::string name;
  bool operator==(const Hello&) const = default;
};

// The host's word to a pilot: first on connecting (start_tick 0: the level to check and load),
// then again when the host launches the match (start_tick 1), with every slot's pilot.
struct Welcome {
  uint8_t slot = 0;
  uint8_t slot_count = 1;
  uint8_t input_delay = 0;
  uint8_t piloted_mask = 1;  // bit i: slot i has a pilot
  uint64_t seed = 0;
  uint32_t start_tick = 0;
  std::vector<std::string> names;  // one per slot ("" for the AI)
  std::string level;               // as the host names it, relative to the data root
  bool operator==(const Welcome&) const = default;
};

struct Reject {
  std::string reason;
  bool operator==(const Reject&) const = default;
};

// A slot's inputs from `first_tick` on, what its sender has of every slot (acks), and the
// hashes of its final ticks from `first_hash_tick` on.
struct Inputs {
  uint8_t slot = 0;
  uint32_t current_tick = 0;
  int8_t advantage = 0;              // sender's ticks ahead of the others (time sync)
  std::vector<uint32_t> acks;        // per slot: the last tick of its inputs the sender holds
  uint32_t first_tick = 0;
  std::vector<SlotInput> inputs;
  uint32_t first_hash_tick = 0;
  std::vector<uint64_t> hashes;
  bool operator==(const Inputs&) const = default;
};

struct Ping {
  uint8_t from = 0, to = 0;
  bool pong = false;
  uint32_t time_ms = 0;  // the pinger's clock, echoed back
  bool operator==(const Ping&) const = default;
};

// The host's word: a slot's pilot is gone, the AI flies its ship from `from_tick` on.
struct Drop {
  uint8_t slot = 0;
  uint32_t from_tick = 0;
  bool operator==(const Drop&) const = default;
};

struct Desync {
  uint8_t slot = 0;  // who found it
  uint32_t tick = 0;
  bool operator==(const Desync&) const = default;
};

// A peer leaves; from the host (slot 0) it ends the match for everyone.
struct Bye {
  uint8_t slot = 0;
  uint32_t tick = 0;
  bool operator==(const Bye&) const = default;
};

// The lobby before the launch. From a pilot: the slot it asks to fly (`pick`); from the host:
// the match's difficulty (0 easy, 1 normal, 2 hard) and every slot's round trip to the host in
// milliseconds (`ping_ms`, one per slot; 0 for none).
struct Lobby {
  uint8_t pick = 0;
  uint8_t difficulty = 1;
  std::vector<uint16_t> ping_ms;
  bool operator==(const Lobby&) const = default;
};

using Packet = std::variant<Hello, Welcome, Reject, Inputs, Ping, Drop, Desync, Bye, Lobby>;

struct Decoded {
  uint32_t seq = 0;
  Packet packet;
};

std::vector<uint8_t> encode(const Packet& p, uint32_t seq);
// nullopt (and *why, when given) for anything but a whole, valid packet of this protocol.
std::optional<Decoded> decode(const uint8_t* data, size_t size, std::string* why = nullptr);

}  // namespace arc::net
