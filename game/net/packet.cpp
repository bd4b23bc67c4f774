// game/net/packet.cpp — encoding and the bounds-checked decoding of the match's packets.
#include "game/net/packet.h"

#include <type_traits>

namespace arc::net {
namespace {

class Out {
 public:
  void u8(uint8_t v) { b_.push_back(v); }
  void u16(uint16_t v) { put(v, 2); }
  void u32(uint32_t v) { put(v, 4); }
  void u64(uint64_t v) { put(v, 8); }
  void str(const std::string& s, size_t max) {
    const size_t n = s.size() < max ? s.size() : max;
    u8(uint8_t(n));
    b_.insert(b_.end(), s.begin(), s.begin() + long(n));
  }
  std::vector<uint8_t> take() { return std::move(b_); }

 private:
  void put(uint64_t v, int n) {
    for (int i = 0; i < n; ++i) b_.push_back(uint8_t(v >> (8 * i)));
  }
  std::vector<uint8_t> b_;
};

// Every read checks the bytes left; the first failure sticks and names what was being read.
class In {
 public:
  In(const uint8_t* p, size_t n) : p_(p), n_(n) {}
  bool ok() const { return err_.empty(); }
  const std::string& error() const { return err_; }
  void fail(const std::string& what) {
    if (err_.empty()) err_ = what;
  }
  uint64_t get(int bytes, const char* what) {
    if (!ok()) return 0;
    if (n_ - i_ < size_t(bytes)) {
      fail(std::string("truncated at ") + what);
      return 0;
    }
    uint64_t v = 0;
    for (int k = 0; k < bytes; ++k) v |= uint64_t(p_[i_ + size_t(k)]) << (8 * k);
    i_ += size_t(bytes);
    return v;
  }
  uint8_t u8(const char* w) { return uint8_t(get(1, w)); }
  uint16_t u16(const char* w) { return uint16_t(get(2, w)); }
  uint32_t u32(const char* w) { return uint32_t(get(4, w)); }
  uint64_t u64(const char* w) { return get(8, w); }
  uint32_t tick(const char* w) {
    uint32_t t = u32(w);
    if (t > kMaxTick) fail(std::string(w) + " beyond tick " + std::to_string(kMaxTick));
    return t;
  }
  // Printable ASCII only, at most `max` bytes.
  std::string str(size_t max, const char* w) {
    const size_t n = u8(w);
    if (!ok()) return {};
    if (n > max || n > n_ - i_) {
      fail(std::string(w) + " longer than allowed or than the packet");
      return {};
    }
    std::string s(reinterpret_cast<const char*>(p_ + i_), n);
    i_ += n;
    for (char c : s)
      if (c < 0x20 || c > 0x7e) fail(std::string(w) + " holds a byte outside printable ASCII");
    return s;
  }
  size_t left() const { return n_ - i_; }

 private:
  const uint8_t* p_;
  size_t n_, i_ = 0;
  std::string err_;
};

void put_input(Out& o, const SlotInput& s) {
  const InputFrame& f = s.input;
  for (int8_t a : {f.pitch, f.yaw, f.roll, f.throttle, f.strafe_x, f.strafe_y}) o.u8(uint8_t(a));
  o.u16(f.buttons);
  const size_t n = s.commands.size() < size_t(kMaxCommandsPerTick) ? s.commands.size() : size_t(kMaxCommandsPerTick);
  o.u8(uint8_t(n));
  for (size_t i = 0; i < n; ++i) o.u8(uint8_t(s.commands[i]));
}

// Only what steers the pilot's own ship: pause and the camera never cross the network.
bool ship_command(uint8_t c) {
  switch (Command(c)) {
    case Command::TargetNext: case Command::TargetNearest: case Command::TargetNextHostile:
    case Command::SwitchWeapon: case Command::Countermeasure: case Command::OrderAttack:
    case Command::OrderCover: case Command::OrderFormUp: case Command::OrderEngage: return true;
    default: return false;
  }
}

SlotInput get_input(In& in) {
  SlotInput s;
  InputFrame& f = s.input;
  for (int8_t* a : {&f.pitch, &f.yaw, &f.roll, &f.throttle, &f.strafe_x, &f.strafe_y}) {
    *a = int8_t(in.u8("axis"));
    if (*a == -128) in.fail("axis value -128 (allowed -127..127)");
  }
  f.buttons = in.u16("buttons");
  if (f.buttons > 0xF) in.fail("unknown button bits");
  const int n = in.u8("command count");
  if (n > kMaxCommandsPerTick) in.fail("more than 8 commands in a tick");
  for (int i = 0; i < n && in.ok(); ++i) {
    uint8_t c = in.u8("command");
    if (!ship_command(c)) in.fail("command " + std::to_string(c) + " is not a ship command");
    s.commands.push_back(Command(c));
  }
  return s;
}

void put(Out& o, const Hello& p) {
  o.u64(p.build_id), o.u64(p.level_hash), o.u64(p.asset_hash), o.str(p.name, kMaxNameBytes);
}
void put(Out& o, const Welcome& p) {
  o.u8(p.slot), o.u8(p.slot_count), o.u8(p.input_delay), o.u8(p.piloted_mask), o.u64(p.seed), o.u32(p.start_tick);
  o.u8(uint8_t(p.names.size()));
  for (const std::string& n : p.names) o.str(n, kMaxNameBytes);
  o.str(p.level, kMaxTextBytes);
}
void put(Out& o, const Reject& p) { o.str(p.reason, kMaxTextBytes); }
void put(Out& o, const Inputs& p) {
  o.u8(p.slot), o.u32(p.current_tick), o.u8(uint8_t(p.advantage));
  o.u8(uint8_t(p.acks.size()));
  for (uint32_t a : p.acks) o.u32(a);
  o.u32(p.first_tick), o.u8(uint8_t(p.inputs.size()));
  for (const SlotInput& s : p.inputs) put_input(o, s);
  o.u32(p.first_hash_tick), o.u8(uint8_t(p.hashes.size()));
  for (uint64_t h : p.hashes) o.u64(h);
}
void put(Out& o, const Ping& p) { o.u8(p.from), o.u8(p.to), o.u8(p.pong ? 1 : 0), o.u32(p.time_ms); }
void put(Out& o, const Drop& p) { o.u8(p.slot), o.u32(p.from_tick); }
void put(Out& o, const Desync& p) { o.u8(p.slot), o.u32(p.tick); }
void put(Out& o, const Bye& p) { o.u8(p.slot), o.u32(p.tick); }
void put(Out& o, const Lobby& p) {
  o.u8(p.pick), o.u8(p.difficulty), o.u8(uint8_t(p.ping_ms.size()));
  for (uint16_t ms : p.ping_ms) o.u16(ms);
}

uint8_t slot_of(In& in, const char* w) {
  uint8_t s = in.u8(w);
  if (s >= kMaxSlots) in.fail(std::string(w) + " beyond the 8 slots");
  return s;
}

Packet get_packet(In& in, PacketType type) {
  switch (type) {
    case PacketType::Hello: {
      Hello p;
      p.build_id = in.u64("build id"), p.level_hash = in.u64("level hash"), p.asset_hash = in.u64("asset hash");
      p.name = in.str(kMaxNameBytes, "name");
      return p;
    }
    case PacketType::Welcome: {
      Welcome p;
      p.slot = slot_of(in, "slot");
      p.slot_count = in.u8("slot count");
      if (p.slot_count < 1 || p.slot_count > kMaxSlots || p.slot >= p.slot_count) in.fail("slot count outside 1..8 or below the slot");
      p.input_delay = in.u8("input delay");
      if (p.input_delay > 4) in.fail("input delay above 4");
      p.piloted_mask = in.u8("piloted mask"), p.seed = in.u64("seed"), p.start_tick = in.tick("start tick");
      const int n = in.u8("name count");
      if (n != p.slot_count) in.fail("a name for each slot");
      for (int i = 0; i < n && in.ok(); ++i) p.names.push_back(in.str(kMaxNameBytes, "name"));
      p.level = in.str(kMaxTextBytes, "level");
      return p;
    }
    case PacketType::Reject: return Reject{in.str(kMaxTextBytes, "reason")};
    case PacketType::Inputs: {
      Inputs p;
      p.slot = slot_of(in, "slot"), p.current_tick = in.tick("current tick"), p.advantage = int8_t(in.u8("advantage"));
      const int na = in.u8("ack count");
      if (na > kMaxSlots) in.fail("more acks than slots");
      for (int i = 0; i < na && in.ok(); ++i) p.acks.push_back(in.tick("ack"));
      p.first_tick = in.tick("first tick");
      const int ni = in.u8("input count");
      if (ni > kMaxInputsPerPacket) in.fail("more than 40 inputs");
      if (in.ok() && in.left() < size_t(ni) * 9) in.fail("truncated inputs");
      for (int i = 0; i < ni && in.ok(); ++i) p.inputs.push_back(get_input(in));
      if (uint64_t(p.first_tick) + uint64_t(ni) > kMaxTick) in.fail("inputs beyond the last tick");
      p.first_hash_tick = in.tick("first hash tick");
      const int nh = in.u8("hash count");
      if (nh > kMaxHashesPerPacket) in.fail("more than 16 hashes");
      for (int i = 0; i < nh && in.ok(); ++i) p.hashes.push_back(in.u64("hash"));
      return p;
    }
    case PacketType::Ping: {
      Ping p;
      p.from = slot_of(in, "from"), p.to = slot_of(in, "to");
      uint8_t pong = in.u8("pong");
      if (pong > 1) in.fail("pong flag other than 0 or 1");
      p.pong = pong == 1, p.time_ms = in.u32("time");
      return p;
    }
    case PacketType::Drop: {
      Drop p;
      p.slot = slot_of(in, "slot"), p.from_tick = in.tick("from tick");
      return p;
    }
    case PacketType::Desync: {
      Desync p;
      p.slot = slot_of(in, "slot"), p.tick = in.tick("tick");
      return p;
    }
    case PacketType::Bye: {
      Bye p;
      p.slot = slot_of(in, "slot"), p.tick = in.tick("tick");
      return p;
    }
    case PacketType::Lobby: {
      Lobby p;
      p.pick = slot_of(in, "pick");
      p.difficulty = in.u8("difficulty");
      if (p.difficulty > 2) in.fail("difficulty above 2");
      const int n = in.u8("ping count");
      if (n > kMaxSlots) in.fail("more pings than slots");
      for (int i = 0; i < n && in.ok(); ++i) p.ping_ms.push_back(in.u16("ping"));
      return p;
    }
  }
  in.fail("unknown packet type");
  return Bye{};
}

}  // namespace

std::vector<uint8_t> encode(const Packet& p, uint32_t seq) {
  Out o;
  o.u8('A'), o.u8('F'), o.u16(kProtocolVersion), o.u8(uint8_t(p.index() + 1)), o.u32(seq);
  std::visit([&](const auto& x) { put(o, x); }, p);
  return o.take();
}

std::optional<Decoded> decode(const uint8_t* data, size_t size, std::string* why) {
  auto refuse = [&](const std::string& w) -> std::optional<Decoded> {
    if (why) *why = w;
    return std::nullopt;
  };
  if (!data || size < kHeaderBytes) return refuse("packet shorter than its 9-byte header");
  if (size > kMaxPacketBytes) return refuse("packet over 1400 bytes");
  In in(data, size);
  if (in.u8("magic") != 'A' || in.u8("magic") != 'F') return refuse("not an Arcfire packet (magic)");
  const uint16_t version = in.u16("version");
  if (version != kProtocolVersion)
    return refuse("protocol version " + std::to_string(version) + ", this build speaks " + std::to_string(kProtocolVersion));
  const uint8_t type = in.u8("type");
  if (type < 1 || type > uint8_t(PacketType::Lobby)) return refuse("unknown packet type " + std::to_string(type));
  Decoded d;
  d.seq = in.u32("sequence");
  d.packet = get_packet(in, PacketType(type));
  if (in.ok() && in.left() != 0) in.fail(std::to_string(in.left()) + " bytes after the packet's end");
  if (!in.ok()) return refuse(in.error());
  return d;
}

}  // namespace arc::net
