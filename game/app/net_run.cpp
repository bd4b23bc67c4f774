// game/app/net_run.cpp — the network match over ENet: joining, the match loop, the record.
#include "game/app/net_run.h"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <thread>

#include <enet/enet.h>

#include "core/error.h"
#include "core/file_writer.h"
#include "core/input_file.h"
#include "core/settings.h"
#include "game/app/app_options.h"
#include "game/net/content_hash.h"
#include "game/net/link_sim.h"
#include "game/net/match_record.h"
#include "game/net/net_peer.h"
#include "game/net/scripted_pilot.h"
#include "game/sim/world.h"

namespace arc {
namespace {

using namespace net;
constexpr int64_t kDefaultTicks = 3600;  // a 60-second match

double now_ms() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

struct EnetLib {
  EnetLib() {
    if (enet_initialize() != 0) throw InputError("network: ENet did not start");
  }
  ~EnetLib() { enet_deinitialize(); }
};

// The connections of this process: the host's to each pilot by slot, a pilot's to the host
// (slot 0); what goes out may pass the link simulation first (net.sim_*).
class Wire {
 public:
  Wire(ENetHost* h, const Settings& s) : host_(h), by_slot_(kMaxSlots, nullptr) {
    LinkConfig c;
    c.latency_ms = s.number("net.sim_latency_ms");
    c.jitter_ms = s.number("net.sim_jitter_ms");
    c.loss = s.number("net.sim_loss");
    simulate_ = c.latency_ms > 0 || c.jitter_ms > 0 || c.loss > 0;
    sim_ = LinkSim(c);
  }
  ~Wire() {
    if (host_) enet_host_destroy(host_);
  }
  ENetHost* host() { return host_; }
  void bind(int slot, ENetPeer* p) { by_slot_[size_t(slot)] = p; }
  ENetPeer* peer(int slot) { return by_slot_[size_t(slot)]; }
  void send(int slot, const std::vector<uint8_t>& b, bool reliable) {
    if (simulate_) sim_.send(0, slot, b, reliable, now_ms());
    else put(slot, b, reliable);
  }
  void pump() {
    if (simulate_)
      for (LinkSim::Delivery& d : sim_.poll(now_ms())) put(d.to, d.bytes, false /*order kept by the sim*/);
    enet_host_flush(host_);
  }
  uint64_t bytes() const { return bytes_; }

 private:
  void put(int slot, const std::vector<uint8_t>& b, bool reliable) {
    ENetPeer* p = by_slot_[size_t(slot)];
    if (!p) return;
    bytes_ += b.size();
    ENetPacket* pk = enet_packet_create(b.data(), b.size(), reliable ? ENET_PACKET_FLAG_RELIABLE : ENET_PACKET_FLAG_UNSEQUENCED);
    if (enet_peer_send(p, reliable ? 0 : 1, pk) != 0) enet_packet_destroy(pk);
  }
  ENetHost* host_;
  std::vector<ENetPeer*> by_slot_;
  LinkSim sim_;
  bool simulate_ = false;
  uint64_t bytes_ = 0;
};

int slot_of(ENetPeer* p) { return p->data ? int(reinterpret_cast<intptr_t>(p->data)) - 1 : -1; }

std::string hex(uint64_t v) {
  char b[17];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(v));
  return b;
}

struct Match {
  std::string level;      // as the host names it
  std::string level_file; // found on this machine
  int slots = 1, local = 0;
  std::vector<bool> piloted;
  std::vector<std::string> names;
  int input_delay = 0;
};

std::string pilot_name(const AppOptions& o) {
  std::string n = o.net.name.empty() ? "Pilot" : o.net.name;
  if (n.size() > kMaxNameBytes) throw InputError("--name: at most 24 characters, got " + std::to_string(n.size()));
  for (char c : n)
    if (c < 0x20 || c > 0x7e) throw InputError("--name: printable ASCII characters only");
  return n;
}

// Long: the whole match loop (receive, frame, route, end conditions, linger, record).
int play(const AppOptions& o, Wire& wire, const Match& m, bool host) {
  GameOptions gopt = o.game;
  Game game = Game::load_level(m.level_file, gopt);
  PeerConfig pc;
  pc.slots = m.slots, pc.local_slot = m.local, pc.input_delay = m.input_delay, pc.piloted = m.piloted;
  pc.host = host;
  pc.timeout_ms = o.settings.number("net.timeout") * 1000.0;
  NetPeer peer(std::move(game), pc);
  const int64_t ticks = o.ticks > 0 ? o.ticks : kDefaultTicks;
  const bool scripted = o.net.pilot == "scripted";
  const double frame_ms = 1000.0 / 60.0;
  size_t logged = 0;
  double next = now_ms(), done_at = -1;
  std::printf("net: slot %d of %d, %s\n", m.local, m.slots, host ? "hosting" : "joined");
  for (;;) {
    ENetEvent ev;
    while (enet_host_service(wire.host(), &ev, 0) > 0) {
      const int from = host ? slot_of(ev.peer) : 0;
      if (ev.type == ENET_EVENT_TYPE_RECEIVE) {
        peer.receive(from, ev.packet->data, ev.packet->dataLength, now_ms());
        enet_packet_destroy(ev.packet);
      } else if (ev.type == ENET_EVENT_TYPE_DISCONNECT) {
        if (host && from > 0) {
          wire.bind(from, nullptr);
          peer.drop_pilot(from, now_ms());
        } else if (!host && !peer.ended()) {
          std::printf("net: the host is gone: the match is over\n");
          done_at = done_at < 0 ? now_ms() : done_at;
        }
      } else if (ev.type == ENET_EVENT_TYPE_CONNECT && host) {
        enet_peer_disconnect(ev.peer, 0);  // the match has started: no one joins now
      }
    }
    const int64_t next_tick = int64_t(peer.session().inputs(m.local).size()) + 1;
    peer.frame(scripted && next_tick <= ticks ? scripted_pilot_input(m.local, next_tick) : SlotInput{}, now_ms());
    for (NetPeer::Outgoing& out : peer.take_outgoing()) {
      if (!host) wire.send(0, out.bytes, out.reliable);
      else
        for (int s = 1; s < m.slots; ++s)
          if (out.to == -1 || out.to == s) wire.send(s, out.bytes, out.reliable);
    }
    wire.pump();
    for (; logged < peer.log().size(); ++logged) std::printf("net: %s\n", peer.log()[logged].c_str());
    bool finished = peer.session().final_tick() >= ticks;
    for (int s = 0; s < m.slots && finished; ++s)
      if (s != m.local && !peer.session().dropped(s)) finished = peer.compared_up_to(s) >= ticks;
    if ((finished || peer.desync_tick() || peer.ended()) && done_at < 0) done_at = now_ms();
    // The host lingers so every pilot can compare its last hashes; a pilot leaves at once.
    bool clients_left = true;
    for (int s = 1; s < m.slots && host; ++s) clients_left = clients_left && !wire.peer(s);
    if (done_at >= 0 && (!host || clients_left || now_ms() - done_at > 3000 || peer.desync_tick())) break;
    next += frame_ms;
    const double wait = next - now_ms();
    if (wait > 0) std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(wait));
    else if (wait < -250) next = now_ms();  // a long stall: no burst of frames to catch up
  }
  peer.leave();
  for (NetPeer::Outgoing& out : peer.take_outgoing())
    for (int s = 0; s < m.slots; ++s)
      if (s != m.local && (host || s == 0)) wire.send(s, out.bytes, true);
  wire.pump();
  for (int s = 0; s < m.slots; ++s)
    if (wire.peer(s)) enet_peer_disconnect_later(wire.peer(s), 0);
  enet_host_flush(wire.host());

  const RollbackSession& rs = peer.session();
  const std::string record = !o.net.match_record.empty() ? o.net.match_record : "net_match_" + std::to_string(m.local) + ".replay";
  write_file_atomic(record, match_record_text(rs, m.level, m.names, ticks));
  const int64_t fin = std::min<int64_t>(rs.final_tick(), ticks);
  std::printf("net: slot %d final tick %lld hash %s rollbacks %llu resimulated %llu ticks %llu compared %llu bytes_out %llu\n",
              m.local, (long long)fin, fin > 0 ? hex(rs.hash_at(fin)).c_str() : "-", (unsigned long long)rs.stats().rollbacks,
              (unsigned long long)rs.stats().resimulated, (unsigned long long)rs.stats().ticks,
              (unsigned long long)peer.counters().hashes_compared, (unsigned long long)wire.bytes());
  if (peer.desync_tick()) {
    const std::string dump = "net_dump_" + std::to_string(m.local) + ".txt";
    write_file_atomic(dump, rs.game().state_dump());
    std::fprintf(stderr, "arcfire: desync at tick %lld; state in %s, match in %s\n", (long long)*peer.desync_tick(),
                 dump.c_str(), record.c_str());
    return 1;
  }
  return 0;
}

// Waits up to `ms` for one event of the kinds wanted; false on timeout.
bool wait_event(ENetHost* h, ENetEvent& ev, double ms) {
  const double until = now_ms() + ms;
  while (now_ms() < until) {
    if (enet_host_service(h, &ev, 20) > 0) return true;
  }
  return false;
}

void send_now(ENetPeer* p, const Packet& pk, bool reliable = true) {
  const std::vector<uint8_t> b = encode(pk, 0);
  ENetPacket* e = enet_packet_create(b.data(), b.size(), reliable ? ENET_PACKET_FLAG_RELIABLE : 0);
  if (enet_peer_send(p, 0, e) != 0) enet_packet_destroy(e);
}

// What differs between a pilot's Hello and this host, in one line ("" when nothing does).
std::string hello_mismatch(const Hello& h, uint64_t build, uint64_t level, uint64_t assets, const std::string& level_name) {
  if (h.build_id != build) return "a different build of arcfire (build id " + hex(h.build_id) + ", the host's " + hex(build) + ")";
  if (h.level_hash != level) return "level " + level_name + " differs from the host's (content " + hex(h.level_hash) + ", the host's " + hex(level) + ")";
  if (h.asset_hash != assets)
    return "ship classes, effects or AI table differ from the host's (content " + hex(h.asset_hash) + ", the host's " + hex(assets) + ")";
  return "";
}

// The host's lobby: pilots connect, are checked and take the next slots until all came.
int host_match(const AppOptions& o) {
  Match m;
  m.level_file = o.level;
  m.level = o.level;
  const std::string root = o.game.root_dir + "/";
  if (m.level.rfind(root, 0) == 0) m.level = m.level.substr(root.size());
  const Game probe = Game::load_level(m.level_file, o.game);
  m.slots = int(probe.slot_count());
  if (m.slots < 1) throw InputError("--host: " + m.level + " has no player ship to fly");
  if (o.net.players > m.slots)
    throw InputError("--players " + std::to_string(o.net.players) + ": " + m.level + " has " + std::to_string(m.slots) +
                     " slots; allowed: 1.." + std::to_string(m.slots));
  m.input_delay = int(o.settings.integer("net.input_delay"));
  m.names.assign(size_t(m.slots), "");
  m.names[0] = pilot_name(o);
  m.piloted.assign(size_t(m.slots), false);
  m.piloted[0] = !o.headless || !o.net.pilot.empty();
  const uint64_t build = build_content_id(ARCFIRE_VERSION), level = level_content_hash(m.level_file),
                 assets = asset_content_hash(o.game.root_dir);
  EnetLib lib;
  ENetAddress addr{};
  addr.host = ENET_HOST_ANY;
  addr.port = uint16_t(o.net.port);
  ENetHost* h = enet_host_create(&addr, size_t(kMaxSlots), 2, 0, 0);
  if (!h) throw InputError("--port " + std::to_string(o.net.port) + ": cannot listen there (in use?)");
  Wire wire(h, o.settings);
  std::printf("net: hosting %s on port %d for %d pilots\n", m.level.c_str(), o.net.port, o.net.players);
  std::fflush(stdout);
  int joined = 1;
  const double give_up = now_ms() + 120000;
  while (joined < o.net.players) {
    if (now_ms() > give_up) throw InputError("--host: " + std::to_string(joined) + " of " + std::to_string(o.net.players) + " pilots after 120 s; no match");
    ENetEvent ev;
    if (!wait_event(h, ev, 100)) continue;
    if (ev.type == ENET_EVENT_TYPE_CONNECT) {
      enet_peer_timeout(ev.peer, 0, uint32_t(o.settings.number("net.timeout") * 1000), uint32_t(o.settings.number("net.timeout") * 1000));
      Welcome info{uint8_t(joined), uint8_t(m.slots), uint8_t(m.input_delay), 0, probe.world().seed, 0, m.names, m.level};
      send_now(ev.peer, info);
    } else if (ev.type == ENET_EVENT_TYPE_RECEIVE) {
      std::optional<Decoded> d = decode(ev.packet->data, ev.packet->dataLength);
      enet_packet_destroy(ev.packet);
      const Hello* hello = d ? std::get_if<Hello>(&d->packet) : nullptr;
      if (!hello || slot_of(ev.peer) >= 0) continue;
      const std::string why = hello_mismatch(*hello, build, level, assets, m.level);
      if (!why.empty()) {
        std::printf("net: refused %s: %s\n", hello->name.c_str(), why.c_str());
        send_now(ev.peer, Reject{why});
        enet_peer_disconnect_later(ev.peer, 0);
        continue;
      }
      ev.peer->data = reinterpret_cast<void*>(intptr_t(joined + 1));
      wire.bind(joined, ev.peer);
      m.names[size_t(joined)] = hello->name;
      m.piloted[size_t(joined)] = true;
      std::printf("net: %s joined in slot %d\n", hello->name.c_str(), joined);
      ++joined;
    } else if (ev.type == ENET_EVENT_TYPE_DISCONNECT && slot_of(ev.peer) > 0) {
      throw InputError("--host: " + m.names[size_t(slot_of(ev.peer))] + " left before the launch; no match");
    }
  }
  uint8_t mask = 0;
  for (int s = 0; s < m.slots; ++s) mask = uint8_t(mask | (m.piloted[size_t(s)] ? 1 << s : 0));
  for (int s = 1; s < joined; ++s)
    send_now(wire.peer(s), Welcome{uint8_t(s), uint8_t(m.slots), uint8_t(m.input_delay), mask, probe.world().seed, 1, m.names, m.level});
  enet_host_flush(h);
  return play(o, wire, m, true);
}

// A pilot's way in: connect, learn the level, show the host what it has, wait for the launch.
int join_match(const AppOptions& o) {
  std::string where = o.net.join;
  int port = o.net.port;
  if (const size_t colon = where.rfind(':'); colon != std::string::npos) {
    const std::string p = where.substr(colon + 1);
    where = where.substr(0, colon);
    if (p.empty() || p.size() > 5 || p.find_first_not_of("0123456789") != std::string::npos || std::stoi(p) < 1 || std::stoi(p) > 65535)
      throw InputError("--join " + o.net.join + ": the port must be 1..65535");
    port = std::stoi(p);
  }
  EnetLib lib;
  ENetAddress addr{};
  if (where.empty() || enet_address_set_host(&addr, where.c_str()) != 0) throw InputError("--join " + o.net.join + ": unknown host");
  addr.port = uint16_t(port);
  ENetHost* h = enet_host_create(nullptr, 1, 2, 0, 0);
  if (!h) throw InputError("--join: cannot open a UDP socket");
  Wire wire(h, o.settings);
  ENetPeer* host = enet_host_connect(h, &addr, 2, 0);
  const std::string at = where + ":" + std::to_string(port);
  ENetEvent ev;
  if (!host || !wait_event(h, ev, 5000) || ev.type != ENET_EVENT_TYPE_CONNECT)
    throw InputError("--join " + at + ": no host answers there");
  const double timeout_ms = o.settings.number("net.timeout") * 1000;
  enet_peer_timeout(host, 0, uint32_t(timeout_ms), uint32_t(timeout_ms));
  wire.bind(0, host);
  Match m;
  bool told = false;
  const double give_up = now_ms() + 130000;
  while (now_ms() < give_up) {
    if (!wait_event(h, ev, 100)) continue;
    if (ev.type == ENET_EVENT_TYPE_DISCONNECT) throw InputError("--join " + at + ": the host closed the connection");
    if (ev.type != ENET_EVENT_TYPE_RECEIVE) continue;
    std::string why;
    std::optional<Decoded> d = decode(ev.packet->data, ev.packet->dataLength, &why);
    enet_packet_destroy(ev.packet);
    if (!d) throw InputError("--join " + at + ": the host speaks otherwise: " + why);
    if (const Reject* r = std::get_if<Reject>(&d->packet)) throw InputError("--join " + at + ": refused: " + r->reason);
    const Welcome* w = std::get_if<Welcome>(&d->packet);
    if (!w) continue;
    if (!told) {
      m.level = w->level;
      if (m.level.find("..") != std::string::npos || m.level.empty() || m.level[0] == '/')
        throw InputError("--join " + at + ": the host names level '" + m.level + "'; allowed: a file under the data folder");
      m.level_file = o.game.root_dir + "/" + m.level;
      if (!input_path_exists(m.level_file)) throw InputError("--join " + at + ": level " + m.level + " is not in this data folder");
      send_now(host, Hello{build_content_id(ARCFIRE_VERSION), level_content_hash(m.level_file), asset_content_hash(o.game.root_dir), pilot_name(o)});
      enet_host_flush(h);
      told = true;
      std::printf("net: joined %s, level %s; waiting for the launch\n", at.c_str(), m.level.c_str());
      std::fflush(stdout);
    }
    if (w->start_tick == 1) {
      m.slots = w->slot_count, m.local = w->slot, m.input_delay = w->input_delay, m.names = w->names;
      m.piloted.assign(size_t(m.slots), false);
      for (int s = 0; s < m.slots; ++s) m.piloted[size_t(s)] = (w->piloted_mask >> s) & 1;
      return play(o, wire, m, false);
    }
  }
  throw InputError("--join " + at + ": the host did not launch within 130 s");
}

}  // namespace

int run_net(const AppOptions& o) {
  if (o.net.host && !o.net.join.empty()) throw InputError("--host and --join: one at a time");
  if (!o.headless) throw InputError("--host / --join: network matches run with --headless in this build");
  return o.net.host ? host_match(o) : join_match(o);
}

}  // namespace arc
