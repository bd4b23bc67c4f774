// game/net/link_sim.cpp — the in-process network of the netcode tests.
#include "game/net/link_sim.h"

#include <algorithm>

#include "core/rng.h"

namespace arc {

double LinkSim::draw(uint64_t what) {
  return double(key_hash(cfg_.seed, what, draws_++, 0) >> 11) * (1.0 / 9007199254740992.0);
}

void LinkSim::send(int from, int to, const std::vector<uint8_t>& bytes, bool reliable, double now_ms) {
  ++counters_.sent;
  counters_.bytes += bytes.size();
  const double delay = std::max(0.0, cfg_.latency_ms + (draw(1) * 2.0 - 1.0) * cfg_.jitter_ms);
  double at = now_ms + delay;
  if (reliable) {
    if (last_reliable_.size() <= size_t(std::max(from, to))) last_reliable_.resize(size_t(std::max(from, to)) + 1);
    for (auto& row : last_reliable_) row.resize(last_reliable_.size(), 0.0);
    double& last = last_reliable_[size_t(from)][size_t(to)];
    at = std::max(at, last);  // in order, as ENet's reliable channel delivers
    last = at;
    queue_.push_back({at, order_++, from, to, bytes});
    return;
  }
  if (draw(2) < cfg_.loss) {
    ++counters_.lost;
    return;
  }
  if (draw(3) < cfg_.reorder) at += cfg_.latency_ms;
  queue_.push_back({at, order_++, from, to, bytes});
  if (draw(4) < cfg_.duplicate) {
    ++counters_.duplicated;
    queue_.push_back({at + draw(5) * cfg_.jitter_ms, order_++, from, to, bytes});
  }
}

std::vector<LinkSim::Delivery> LinkSim::poll(double now_ms) {
  std::vector<Delivery> due;
  auto split = std::stable_partition(queue_.begin(), queue_.end(), [&](const Delivery& d) { return d.at_ms > now_ms; });
  due.assign(std::make_move_iterator(split), std::make_move_iterator(queue_.end()));
  queue_.erase(split, queue_.end());
  std::sort(due.begin(), due.end(), [](const Delivery& a, const Delivery& b) {
    return a.at_ms != b.at_ms ? a.at_ms < b.at_ms : a.order < b.order;
  });
  counters_.delivered += due.size();
  return due;
}

}  // namespace arc
