// game/net/link_sim.h — an in-process network between peers: latency, jitter, loss,
// duplication and reordering, drawn from a keyed RNG so a test run is the same every time.
//
// Unreliable packets may be lost, duplicated or overtaken; reliable ones (ENet's reliable
// channel) arrive once and in order after the same latency and jitter.
//
// Example, compiled as NetLink.Example in tests/unit/net/test_link_sim.cpp:
//   LinkSim link({.latency_ms = 50, .jitter_ms = 20, .loss = 0.05});
//   link.send(0, 1, bytes, /*reliable=*/false, now_ms);
//   for (LinkSim::Delivery& d : link.poll(now_ms + 100)) peer[d.to].receive(d.from, d.bytes);
#pragma once
#include <cstdint>
#include <vector>

namespace arc {

struct LinkConfig {
  double latency_ms = 0;   // one way
  double jitter_ms = 0;    // ± around the latency, uniform
  double loss = 0;         // share of unreliable packets lost
  double duplicate = 0;    // share of unreliable packets delivered twice
  double reorder = 0;      // share of unreliable packets held back one more latency
  uint64_t seed = 1;
};

class LinkSim {
 public:
  struct Delivery {
    double at_ms = 0;
    uint64_t order = 0;
    int from = 0, to = 0;
    std::vector<uint8_t> bytes;
  };
  struct Counters {
    uint64_t sent = 0, lost = 0, duplicated = 0, delivered = 0, bytes = 0;
  };

  explicit LinkSim(LinkConfig config = {}) : cfg_(config) {}
  void send(int from, int to, const std::vector<uint8_t>& bytes, bool reliable, double now_ms);
  // Every packet due by now_ms, in arrival order.
  std::vector<Delivery> poll(double now_ms);
  const Counters& counters() const { return counters_; }
  void set_config(const LinkConfig& c) { cfg_ = c; }

 private:
  double draw(uint64_t what);  // 0..1
  LinkConfig cfg_;
  Counters counters_;
  uint64_t draws_ = 0, order_ = 0;
  std::vector<Delivery> queue_;
  std::vector<std::vector<double>> last_reliable_;  // [from][to]: arrival of the last reliable packet
};

}  // namespace arc
