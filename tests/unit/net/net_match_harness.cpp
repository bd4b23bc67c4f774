// tests/unit/net/net_match_harness.cpp — run_match: peers, the star topology and the clock.
#include "net_match_harness.h"

#include "game/net/scripted_pilot.h"

namespace arc::nettest {

SlotInput scripted_input(int slot, int64_t t) { return scripted_pilot_input(slot, t); }

MatchResult run_match(const MatchSetup& m) {
  std::vector<NetPeer> peers;
  GameOptions options;
  options.root_dir = m.root;
  const Game start = Game::load_level(m.level, options);
  for (int p = 0; p < m.peers; ++p) {
    PeerConfig c;
    c.slots = m.peers;
    c.local_slot = p;
    c.input_delay = m.input_delay;
    c.host = p == 0;
    c.timeout_ms = m.timeout_ms;
    peers.emplace_back(Game(start), c);
    if (p == m.corrupt_peer) peers.back().corrupt_at(m.corrupt_tick);
  }
  LinkSim link(m.link);
  const double frame_ms = 1000.0 / 60.0;
  double now = 0;
  auto done = [&] {
    for (const NetPeer& p : peers)
      if (!p.desync_tick() && !p.ended() && p.session().final_tick() < m.ticks) return false;
    return true;
  };
  for (int frame = 0; frame < m.ticks * 4 && !done(); ++frame) {
    now = frame * frame_ms;
    for (LinkSim::Delivery& d : link.poll(now)) {
      if (d.to == m.silent_peer && now >= m.silent_from_ms) continue;
      peers[size_t(d.to)].receive(d.from, d.bytes.data(), d.bytes.size(), now);
    }
    for (int p = 0; p < m.peers; ++p) {
      NetPeer& peer = peers[size_t(p)];
      const bool silent = p == m.silent_peer && now >= m.silent_from_ms;
      if (!silent && peer.session().tick() < m.ticks)
        peer.frame(scripted_input(p, int64_t(peer.session().inputs(p).size()) + 1), now);
      else if (!silent)
        peer.frame(SlotInput{}, now);
      for (NetPeer::Outgoing& o : peer.take_outgoing()) {
        if (silent) continue;
        if (p != 0) {
          link.send(p, 0, o.bytes, o.reliable, now);  // a pilot talks to the host only
        } else {
          for (int q = 1; q < m.peers; ++q)
            if (o.to == -1 || o.to == q) link.send(0, q, o.bytes, o.reliable, now);
        }
      }
    }
  }
  MatchResult r;
  r.seconds = now / 1000.0;
  r.link = link.counters();
  for (const NetPeer& p : peers) {
    std::vector<uint64_t> h;
    for (int64_t t = 1; t <= std::min<int64_t>(p.session().final_tick(), m.ticks); ++t) h.push_back(p.session().hash_at(t));
    r.hashes.push_back(std::move(h));
    r.stats.push_back(p.session().stats());
    r.counters.push_back(p.counters());
    r.desync.push_back(p.desync_tick());
    r.dropped.push_back(p.dropped_pilots());
  }
  return r;
}

}  // namespace arc::nettest
