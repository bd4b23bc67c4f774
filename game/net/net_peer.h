// game/net/net_peer.h — one peer of a network match, independent of sockets.
//
// A NetPeer owns the RollbackSession and speaks the packets of packet.h. Each frame it takes the
// local pilot's input, advances as far as the prediction window and the time sync allow, and
// queues one Inputs packet: its slot's inputs the others have not acknowledged, its acks of
// every slot, and the hashes of its last final ticks. Received hashes are compared tick by tick
// in order with its own; the first mismatch stops the match everywhere ("desync at tick T").
// The transport (net_transport.cpp over ENet, or LinkSim in the tests) routes what take_outgoing
// returns; with the host in the middle, the host relays each pilot's packets to the others.
//
// Example, compiled as NetPeer.Example in tests/unit/net/test_net_peer.cpp:
//   NetPeer a(Game::load_level("levels/duel.json", {}), {.slots = 2, .local_slot = 0});
//   a.frame(SlotInput{}, now_ms);
//   for (NetPeer::Outgoing& o : a.take_outgoing()) link.send(0, 1, o.bytes, o.reliable, now_ms);
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "game/net/packet.h"
#include "game/net/rollback.h"

namespace arc {

struct PeerConfig {
  int slots = 1;
  int local_slot = 0;
  int input_delay = 0;
  int max_prediction = 12;
  std::vector<bool> piloted;     // per slot; empty: all
  bool host = false;             // decides drops; its Bye ends the match
  double timeout_ms = 5000;      // net.timeout: a silent pilot is dropped to the AI (host only)
  double tick_ms = 1000.0 / 60.0;
  int max_packets_per_second = 240;  // per sender; the rest are dropped
};

struct PeerCounters {
  uint64_t packets_in = 0, packets_out = 0, bytes_in = 0, bytes_out = 0;
  uint64_t malformed = 0, refused = 0, stale = 0, rate_limited = 0;
  uint64_t hashes_compared = 0, skipped_frames = 0;
};

class NetPeer {
 public:
  struct Outgoing {
    int to = -1;  // a slot, or −1 for every other peer
    bool reliable = false;
    std::vector<uint8_t> bytes;
  };

  NetPeer(Game game, PeerConfig config);

  // One display frame at now_ms: the local input, then the ticks pacing allows (0 or 1).
  void frame(const SlotInput& local, double now_ms);
  // A packet from the transport; `from_slot` is the slot of the connection it came over (−1:
  // unknown). Malformed or disallowed packets are counted and dropped, never thrown.
  void receive(int from_slot, const uint8_t* data, size_t size, double now_ms);
  std::vector<Outgoing> take_outgoing();

  // The host's decision that a pilot is gone (timeout or disconnect): the AI flies its ship.
  void drop_pilot(int slot, double now_ms);
  // Leaving: a Bye to everyone (from the host it ends the match).
  void leave();
  // This peer's state altered at a tick (tests: a forced desync).
  void corrupt_at(int64_t tick);

  const RollbackSession& session() const { return session_; }
  RollbackSession& session_mut() { return session_; }
  int local_slot() const { return cfg_.local_slot; }
  std::optional<int64_t> desync_tick() const { return desync_; }
  bool ended() const { return ended_; }
  const std::vector<std::string>& log() const { return log_; }
  const PeerCounters& counters() const { return counters_; }
  double ping_ms(int slot) const { return ping_[size_t(slot)]; }
  int64_t compared_up_to(int slot) const { return compared_[size_t(slot)]; }
  int64_t dropped_pilots() const { return dropped_; }

 private:
  void send(const net::Packet& p, int to, bool reliable);
  void send_inputs(double now_ms);
  void on_inputs(const net::Inputs& p, double now_ms);
  void compare_hashes();
  void report_desync(int64_t tick);
  bool rate_ok(int slot, double now_ms);
  void check_timeouts(double now_ms);
  int time_sync_skip();

  RollbackSession session_;
  PeerConfig cfg_;
  PeerCounters counters_;
  uint32_t seq_ = 0;
  std::vector<Outgoing> out_;
  std::vector<int64_t> acked_by_;       // per slot: the last tick of my inputs that slot holds
  std::vector<int64_t> remote_tick_;    // per slot: its current tick, as last heard
  std::vector<int> remote_advantage_;
  std::vector<uint32_t> last_seq_;      // per slot: the newest Inputs sequence taken
  std::vector<std::map<int64_t, uint64_t>> remote_hashes_;
  std::vector<int64_t> compared_;       // per slot: hashes compared up to this tick
  std::vector<double> last_heard_, ping_, rate_window_start_;
  std::vector<int> rate_count_;
  double last_ping_ms_ = -1e9;
  int skip_credit_ = 0;
  std::optional<int64_t> desync_;
  int64_t dropped_ = 0;
  bool ended_ = false;
  std::vector<std::string> log_;
};

}  // namespace arc
