// game/net/net_peer.cpp — NetPeer: pacing, the Inputs stream, hash comparison, drops, relaying.
#include "game/net/net_peer.h"

#include <algorithm>
#include <cmath>

#include "game/sim/world.h"

namespace arc {

using namespace net;

NetPeer::NetPeer(Game game, PeerConfig config)
    : session_(std::move(game), RollbackConfig{config.slots, config.local_slot, config.input_delay,
                                                config.max_prediction, config.piloted}),
      cfg_(std::move(config)) {
  const size_t n = size_t(cfg_.slots);
  acked_by_.assign(n, 0);
  remote_tick_.assign(n, 0);
  remote_advantage_.assign(n, 0);
  last_seq_.assign(n, 0);
  remote_hashes_.resize(n);
  compared_.assign(n, 0);
  last_heard_.assign(n, -1.0);
  ping_.assign(n, 0.0);
  rate_window_start_.assign(n, -1e9);
  rate_count_.assign(n, 0);
  cfg_.piloted = session_.config().piloted;
}

void NetPeer::send(const Packet& p, int to, bool reliable) {
  Outgoing o{to, reliable, encode(p, ++seq_)};
  ++counters_.packets_out;
  counters_.bytes_out += o.bytes.size();
  out_.push_back(std::move(o));
}

std::vector<NetPeer::Outgoing> NetPeer::take_outgoing() { return std::exchange(out_, {}); }

// The peers whose inputs and hashes matter: piloted remote slots not dropped.
static bool active(const RollbackSession& s, int slot) { return slot != s.config().local_slot && !s.dropped(slot); }

int NetPeer::time_sync_skip() {
  // GGPO's time sync: half the difference of the two sides' advantages, the largest over the
  // others; the side ahead skips one frame in ten while it is ahead by a tick or more.
  double worst = 0;
  for (int s = 0; s < cfg_.slots; ++s) {
    if (!active(session_, s) || remote_tick_[size_t(s)] == 0) continue;
    const double mine = double(session_.tick()) - (double(remote_tick_[size_t(s)]) + ping_[size_t(s)] / 2.0 / cfg_.tick_ms);
    worst = std::max(worst, (mine - double(remote_advantage_[size_t(s)])) / 2.0);
  }
  if (worst < 1.0) return 0;
  if (++skip_credit_ < 10) return 0;
  skip_credit_ = 0;
  return 1;
}

void NetPeer::frame(const SlotInput& local, double now_ms) {
  if (ended_ || desync_) return;
  for (int s = 0; s < cfg_.slots; ++s)
    if (last_heard_[size_t(s)] < 0) last_heard_[size_t(s)] = now_ms;
  if (cfg_.host) check_timeouts(now_ms);
  if (now_ms - last_ping_ms_ >= 500) {
    last_ping_ms_ = now_ms;
    for (int s = 0; s < cfg_.slots; ++s)
      if (active(session_, s)) send(Ping{uint8_t(cfg_.local_slot), uint8_t(s), false, uint32_t(int64_t(now_ms))}, s, false);
  }
  if (time_sync_skip()) {
    ++counters_.skipped_frames;
  } else if (session_.window_open()) {
    session_.add_local_input(local);
    session_.advance();
  }
  session_.settle();  // a frame that did not advance still corrects what arrived
  send_inputs(now_ms);
  compare_hashes();
}

void NetPeer::send_inputs(double /*now_ms*/) {
  Inputs p;
  p.slot = uint8_t(cfg_.local_slot);
  p.current_tick = uint32_t(session_.tick());
  int64_t first = INT64_MAX;
  double adv = 0;
  for (int s = 0; s < cfg_.slots; ++s) {
    const int64_t r = session_.received(s);
    p.acks.push_back(uint32_t(std::min<int64_t>(r == RollbackSession::kNever ? session_.inputs(s).size() : r, kMaxTick)));
    if (!active(session_, s)) continue;
    first = std::min(first, acked_by_[size_t(s)] + 1);
    if (remote_tick_[size_t(s)] > 0)
      adv = std::max(adv, double(session_.tick()) - (double(remote_tick_[size_t(s)]) + ping_[size_t(s)] / 2.0 / cfg_.tick_ms));
  }
  p.advantage = int8_t(std::clamp(std::lround(adv), -127l, 127l));
  const auto& mine = session_.inputs(cfg_.local_slot);
  if (first == INT64_MAX) first = int64_t(mine.size()) + 1;
  first = std::max<int64_t>(first, 1);
  p.first_tick = uint32_t(first);
  for (int64_t t = first; t <= int64_t(mine.size()) && int(p.inputs.size()) < kMaxInputsPerPacket; ++t)
    p.inputs.push_back(mine[size_t(t - 1)]);
  const int64_t fin = session_.final_tick();
  const int64_t from = std::max<int64_t>(1, fin - kMaxHashesPerPacket + 1);
  p.first_hash_tick = uint32_t(from);
  for (int64_t t = from; t <= fin; ++t) p.hashes.push_back(session_.hash_at(t));
  send(p, -1, false);
}

bool NetPeer::rate_ok(int slot, double now_ms) {
  if (slot < 0 || slot >= cfg_.slots) return true;
  const size_t i = size_t(slot);
  if (now_ms - rate_window_start_[i] >= 1000) rate_window_start_[i] = now_ms, rate_count_[i] = 0;
  // A pilot's packets come over the host's connection: it may carry every slot's.
  const int limit = cfg_.max_packets_per_second * (!cfg_.host && slot == 0 ? cfg_.slots : 1);
  return ++rate_count_[i] <= limit;
}

void NetPeer::receive(int from_slot, const uint8_t* data, size_t size, double now_ms) {
  ++counters_.packets_in;
  counters_.bytes_in += size;
  if (!rate_ok(from_slot, now_ms)) {
    ++counters_.rate_limited;
    return;
  }
  std::string why;
  std::optional<Decoded> d = decode(data, size, &why);
  if (!d) {
    ++counters_.malformed;
    return;
  }
  if (from_slot >= 0 && from_slot < cfg_.slots) last_heard_[size_t(from_slot)] = now_ms;
  const std::vector<uint8_t> raw(data, data + size);
  if (auto* in = std::get_if<Inputs>(&d->packet)) {
    // A pilot speaks for its own slot only; what the host relays speaks for the others.
    if (in->slot >= cfg_.slots || in->slot == cfg_.local_slot || (cfg_.host && from_slot >= 0 && in->slot != from_slot)) {
      ++counters_.refused;
      return;
    }
    if (d->seq != 0 && d->seq <= last_seq_[in->slot]) {
      ++counters_.stale;
      return;
    }
    if (d->seq != 0) last_seq_[in->slot] = d->seq;
    on_inputs(*in, now_ms);
    if (d->seq == 0) return;
    if (cfg_.host)
      for (int s = 0; s < cfg_.slots; ++s)
        if (s != cfg_.local_slot && s != in->slot && active(session_, s)) out_.push_back({s, false, raw});
  } else if (auto* pg = std::get_if<Ping>(&d->packet)) {
    if (pg->from >= cfg_.slots || pg->to >= cfg_.slots || (cfg_.host && from_slot >= 0 && pg->from != from_slot)) {
      ++counters_.refused;
      return;
    }
    if (pg->to != cfg_.local_slot) {
      if (cfg_.host) out_.push_back({pg->to, false, raw});
      return;
    }
    if (!pg->pong) send(Ping{uint8_t(cfg_.local_slot), pg->from, true, pg->time_ms}, pg->from, false);
    else ping_[pg->from] = std::max(0.0, now_ms - double(pg->time_ms));
  } else if (auto* ds = std::get_if<Desync>(&d->packet)) {
    if (!desync_ || int64_t(ds->tick) < *desync_) {
      desync_ = int64_t(ds->tick);
      log_.push_back("desync at tick " + std::to_string(ds->tick) + " (found by slot " + std::to_string(ds->slot) + ")");
    }
    if (cfg_.host) send(*ds, -1, true);
  } else if (auto* dr = std::get_if<Drop>(&d->packet)) {
    if (cfg_.host || from_slot > 0 || dr->slot >= cfg_.slots) {
      ++counters_.refused;  // only the host drops pilots
      return;
    }
    session_.drop_slot(dr->slot, dr->from_tick);
    ++dropped_;
    log_.push_back("pilot of slot " + std::to_string(dr->slot) + " left at tick " + std::to_string(dr->from_tick) + ": the AI flies their ship");
  } else if (auto* by = std::get_if<Bye>(&d->packet)) {
    if (cfg_.host) {
      if (from_slot > 0 && by->slot == from_slot) drop_pilot(from_slot, now_ms);
    } else if (from_slot <= 0 && by->slot == 0) {
      ended_ = true;
      log_.push_back("the host left at tick " + std::to_string(by->tick) + ": the match is over");
    }
  } else {
    ++counters_.refused;  // Hello, Welcome and Reject belong to the connection, not the match
  }
}

void NetPeer::on_inputs(const Inputs& p, double /*now_ms*/) {
  const int s = p.slot;
  for (size_t i = 0; i < p.inputs.size(); ++i) session_.add_remote_input(s, int64_t(p.first_tick) + int64_t(i), p.inputs[i]);
  if (p.acks.size() == size_t(cfg_.slots)) acked_by_[size_t(s)] = std::max<int64_t>(acked_by_[size_t(s)], p.acks[size_t(cfg_.local_slot)]);
  remote_tick_[size_t(s)] = std::max<int64_t>(remote_tick_[size_t(s)], p.current_tick);
  remote_advantage_[size_t(s)] = p.advantage;
  auto& held = remote_hashes_[size_t(s)];
  for (size_t i = 0; i < p.hashes.size(); ++i) {
    const int64_t t = int64_t(p.first_hash_tick) + int64_t(i);
    if (t > compared_[size_t(s)] && held.size() < 4096) held.emplace(t, p.hashes[i]);
  }
}

void NetPeer::compare_hashes() {
  const int64_t fin = session_.final_tick();
  for (int s = 0; s < cfg_.slots && !desync_; ++s) {
    auto& held = remote_hashes_[size_t(s)];
    while (!held.empty() && !desync_) {
      int64_t& done = compared_[size_t(s)];
      auto it = held.begin();
      if (it->first <= done) {
        held.erase(it);
        continue;
      }
      // A gap wider than a packet's hashes was lost for good: compare from what came.
      if (it->first != done + 1 && it->first <= done + kMaxHashesPerPacket) break;
      if (it->first > fin) break;
      ++counters_.hashes_compared;
      if (it->second != session_.hash_at(it->first)) report_desync(it->first);
      done = it->first;
      held.erase(it);
    }
  }
}

void NetPeer::report_desync(int64_t tick) {
  if (desync_ && *desync_ <= tick) return;
  desync_ = tick;
  log_.push_back("desync at tick " + std::to_string(tick));
  send(Desync{uint8_t(cfg_.local_slot), uint32_t(tick)}, -1, true);
}

void NetPeer::check_timeouts(double now_ms) {
  for (int s = 0; s < cfg_.slots; ++s)
    if (active(session_, s) && now_ms - last_heard_[size_t(s)] > cfg_.timeout_ms) drop_pilot(s, now_ms);
}

void NetPeer::drop_pilot(int slot, double /*now_ms*/) {
  if (!cfg_.host || !active(session_, slot)) return;
  const int64_t from = session_.received(slot) + 1;
  // Its last inputs, which only the host may hold, go to everyone first (in order, reliable).
  Inputs last;
  last.slot = uint8_t(slot);
  const auto& k = session_.inputs(slot);
  const int64_t first = std::max<int64_t>(1, int64_t(k.size()) - kMaxInputsPerPacket + 1);
  last.first_tick = uint32_t(first);
  for (int64_t t = first; t <= int64_t(k.size()); ++t) last.inputs.push_back(k[size_t(t - 1)]);
  last.first_hash_tick = 1;
  Outgoing o{-1, true, encode(last, 0)};
  out_.push_back(std::move(o));
  session_.drop_slot(slot, from);
  ++dropped_;
  send(Drop{uint8_t(slot), uint32_t(from)}, -1, true);
  log_.push_back("pilot of slot " + std::to_string(slot) + " stopped answering at tick " + std::to_string(from) + ": the AI flies their ship");
}

void NetPeer::corrupt_at(int64_t tick) {
  session_.after_step = [tick](Game& g, int64_t t) {
    if (t != tick) return;
    for (Ship& s : g.world_mut().ships)
      if (s.alive) {
        s.hull -= 1.0;
        return;
      }
  };
}

void NetPeer::leave() {
  send(Bye{uint8_t(cfg_.local_slot), uint32_t(session_.tick())}, -1, true);
  ended_ = true;
}

}  // namespace arc
