// game/app/net_match.cpp — NetMatch: the window's lobby and match over ENet, polled per frame.
#include "game/app/net_match.h"

#include <algorithm>
#include <cstdio>

#include <enet/enet.h>

#include "core/error.h"
#include "core/file_writer.h"
#include "core/input_file.h"
#include "game/net/content_hash.h"
#include "game/net/link_sim.h"
#include "game/net/match_record.h"
#include "game/sim/world.h"

namespace arc {

using namespace net;

namespace {

std::string hex(uint64_t v) {
  char b[17];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(v));
  return b;
}

int slot_of(ENetPeer* p) { return p && p->data ? int(reinterpret_cast<intptr_t>(p->data)) - 1 : -1; }

void send_now(ENetPeer* p, const Packet& pk) {
  const std::vector<uint8_t> b = encode(pk, 0);
  ENetPacket* e = enet_packet_create(b.data(), b.size(), ENET_PACKET_FLAG_RELIABLE);
  if (enet_peer_send(p, 0, e) != 0) enet_packet_destroy(e);
}

}  // namespace

std::string checked_pilot_name(const std::string& name, const std::string& where) {
  if (name.empty() || name.size() > kMaxNameBytes)
    throw InputError(where + ": a pilot name has 1 to 24 characters, got " + std::to_string(name.size()));
  for (char c : name)
    if (c < 0x20 || c > 0x7e) throw InputError(where + ": a pilot name holds printable ASCII characters only");
  return name;
}

// The process's ENet host, its connections by slot, and the link simulation on the way out.
struct NetMatch::Wire {
  ENetHost* host = nullptr;
  ENetPeer* server = nullptr;  // a pilot's connection to the host
  std::vector<ENetPeer*> by_slot = std::vector<ENetPeer*>(size_t(kMaxSlots), nullptr);
  LinkSim sim;
  bool simulate = false;
  explicit Wire(const Config& c) {
    if (enet_initialize() != 0) throw InputError("network: ENet did not start");
    LinkConfig l;
    l.latency_ms = c.sim_latency_ms, l.jitter_ms = c.sim_jitter_ms, l.loss = c.sim_loss;
    simulate = l.latency_ms > 0 || l.jitter_ms > 0 || l.loss > 0;
    sim = LinkSim(l);
  }
  ~Wire() {
    if (host) enet_host_destroy(host);
    enet_deinitialize();
  }
  void put(int slot, const std::vector<uint8_t>& b, bool reliable) {
    ENetPeer* p = by_slot[size_t(slot)];
    if (!p) return;
    ENetPacket* pk = enet_packet_create(b.data(), b.size(), reliable ? ENET_PACKET_FLAG_RELIABLE : ENET_PACKET_FLAG_UNSEQUENCED);
    if (enet_peer_send(p, reliable ? 0 : 1, pk) != 0) enet_packet_destroy(pk);
  }
  void send(int slot, const std::vector<uint8_t>& b, bool reliable, double now) {
    if (simulate && !reliable) sim.send(0, slot, b, reliable, now);
    else put(slot, b, reliable);
  }
  void pump(double now) {
    if (simulate)
      for (LinkSim::Delivery& d : sim.poll(now)) put(d.to, d.bytes, false);
    enet_host_flush(host);
  }
};

NetMatch::NetMatch(Config c) : cfg_(std::move(c)), wire_(std::make_unique<Wire>(cfg_)) {
  checked_pilot_name(cfg_.name, "net.name");
  if (cfg_.host) {
    level_file_ = cfg_.level;
    level_ = cfg_.level;
    const std::string root = cfg_.game.root_dir + "/";
    if (level_.rfind(root, 0) == 0) level_ = level_.substr(root.size());
    Game probe = Game::load_level(level_file_, cfg_.game);
    slots_ = int(probe.slot_count());
    if (slots_ < 1) throw InputError("--host: " + level_ + " has no player ship to fly");
    if (cfg_.players > slots_)
      throw InputError("--players " + std::to_string(cfg_.players) + ": " + level_ + " has " + std::to_string(slots_) +
                       " slots; allowed: 1.." + std::to_string(slots_));
    seed_ = probe.world().seed;
    probe.set_pilots({});
    for (const PilotSlot& p : probe.world().pilots) {  // the lobby's teams and ships
      teams_.push_back(probe.world().team_name(probe.world().ship(p.ship).team));
      ships_.push_back(probe.world().ship(p.ship).name);
    }
    status_ = "Hosting " + level_ + " on port " + std::to_string(cfg_.port);
    names_.assign(size_t(slots_), "");
    names_[0] = cfg_.name;
    owner_.assign(size_t(slots_), nullptr);
    ENetAddress addr{};
    addr.host = ENET_HOST_ANY;
    addr.port = uint16_t(cfg_.port);
    wire_->host = enet_host_create(&addr, size_t(kMaxSlots), 2, 0, 0);
    if (!wire_->host) throw InputError("--port " + std::to_string(cfg_.port) + ": cannot listen there (in use?)");
    phase_ = Phase::Lobby;
    input_delay_ = cfg_.input_delay;
  } else {
    std::string where = cfg_.join;
    int port = cfg_.port;
    if (const size_t colon = where.rfind(':'); colon != std::string::npos) {
      const std::string p = where.substr(colon + 1);
      where = where.substr(0, colon);
      if (p.empty() || p.size() > 5 || p.find_first_not_of("0123456789") != std::string::npos || std::stoi(p) < 1 ||
          std::stoi(p) > 65535)
        throw InputError("--join " + cfg_.join + ": the port must be 1..65535");
      port = std::stoi(p);
    }
    ENetAddress addr{};
    if (where.empty() || enet_address_set_host(&addr, where.c_str()) != 0) throw InputError("--join " + cfg_.join + ": unknown host");
    addr.port = uint16_t(port);
    wire_->host = enet_host_create(nullptr, 1, 2, 0, 0);
    if (!wire_->host) throw InputError("--join: cannot open a UDP socket");
    wire_->server = enet_host_connect(wire_->host, &addr, 2, 0);
    if (!wire_->server) throw InputError("--join " + cfg_.join + ": cannot connect");
    cfg_.join = where + ":" + std::to_string(port);
    status_ = "Connecting to " + cfg_.join + " ...";
  }
  pings_.assign(size_t(std::max(slots_, 1)), 0.0);
}

NetMatch::~NetMatch() {
  if (peer_ && !finished_) leave();
  if (wire_->host) {
    for (size_t i = 0; i < wire_->host->peerCount; ++i)
      if (wire_->host->peers[i].state == ENET_PEER_STATE_CONNECTED) enet_peer_disconnect_now(&wire_->host->peers[i], 0);
    enet_host_flush(wire_->host);
  }
}

int NetMatch::pilots_in() const { return int(std::count_if(names_.begin(), names_.end(), [](const std::string& n) { return !n.empty(); })); }

std::vector<NetPilotRow> NetMatch::pilots() const {
  std::vector<NetPilotRow> rows;
  for (int s = 0; s < slots_ && s < int(names_.size()); ++s) {
    NetPilotRow r;
    r.slot = s;
    r.name = names_[size_t(s)];
    r.team = s < int(teams_.size()) ? teams_[size_t(s)] : "";
    r.ship = s < int(ships_.size()) ? ships_[size_t(s)] : "";
    r.ping_ms = s < int(pings_.size()) ? pings_[size_t(s)] : 0;
    // In the match: the peers' own measure; a pilot's own row shows its round trip to the host.
    if (peer_ && s != local_) r.ping_ms = peer_->ping_ms(s);
    if (peer_ && s == local_) r.ping_ms = cfg_.host ? 0 : peer_->ping_ms(0);
    r.you = s == local_;
    rows.push_back(std::move(r));
  }
  return rows;
}

void NetMatch::over(const std::string& why) {
  if (phase_ == Phase::Over) return;
  phase_ = Phase::Over;
  status_ = why;
  messages_.push_back(why);
}

void NetMatch::poll(double now_ms) {
  if (phase_ == Phase::Over) return;
  if (phase_ == Phase::Playing) poll_match(now_ms);
  else if (cfg_.host) poll_host_lobby(now_ms);
  else poll_join_lobby(now_ms);
}

// Every pilot hears the lobby: its slot and every slot's name (Welcome, start_tick 0), the
// difficulty and the pings (Lobby).
void NetMatch::send_lobby() {
  Lobby l;
  l.difficulty = uint8_t(cfg_.game.difficulty);
  for (int s = 0; s < slots_; ++s) l.ping_ms.push_back(uint16_t(std::clamp(pings_[size_t(s)], 0.0, 65535.0)));
  for (int s = 1; s < slots_; ++s) {
    ENetPeer* p = static_cast<ENetPeer*>(owner_[size_t(s)]);
    if (!p) continue;
    send_now(p, Welcome{uint8_t(s), uint8_t(slots_), uint8_t(input_delay_), 0, seed_, 0, names_, level_});
    send_now(p, l);
  }
  enet_host_flush(wire_->host);
}

// The host's lobby events (connect, the pilot's Hello checked, slot picks, leaving).
void NetMatch::poll_host_lobby(double now_ms) {
  // Launched at the start of the poll after the last pilot came in, so the caller has the
  // lobby's messages ("Ann joined") before the launch's line.
  if (cfg_.players > 0 && pilots_in() >= cfg_.players && launch()) return;
  const uint64_t build = build_content_id(ARCFIRE_VERSION);
  bool changed = false;
  ENetEvent ev;
  while (enet_host_service(wire_->host, &ev, 0) > 0) {
    if (ev.type == ENET_EVENT_TYPE_CONNECT) {
      const uint32_t t = uint32_t(cfg_.timeout_s * 1000);
      enet_peer_timeout(ev.peer, 0, t, t);
      ev.peer->data = nullptr;
      send_now(ev.peer, Welcome{0, uint8_t(slots_), uint8_t(input_delay_), 0, seed_, 0, names_, level_});
    } else if (ev.type == ENET_EVENT_TYPE_RECEIVE) {
      std::optional<Decoded> d = decode(ev.packet->data, ev.packet->dataLength);
      enet_packet_destroy(ev.packet);
      if (!d) continue;
      const int at = slot_of(ev.peer);
      if (const Hello* h = std::get_if<Hello>(&d->packet); h && at < 0) {
        std::string why;
        if (h->build_id != build) why = "a different build of arcfire (build id " + hex(h->build_id) + ", the host's " + hex(build) + ")";
        else if (h->level_hash != level_content_hash(level_file_)) why = "level " + level_ + " differs from the host's";
        else if (h->asset_hash != asset_content_hash(cfg_.game.root_dir)) why = "ship classes, effects or AI table differ from the host's";
        int free = -1;
        for (int s = 1; s < slots_ && free < 0; ++s)
          if (!owner_[size_t(s)]) free = s;
        if (why.empty() && free < 0) why = "the match is full (" + std::to_string(slots_) + " slots)";
        std::string name = h->name.empty() ? "Pilot " + std::to_string(free) : h->name;
        for (const std::string& n : names_)
          if (why.empty() && n == name) name += " " + std::to_string(free);
        if (!why.empty()) {
          send_now(ev.peer, Reject{why});
          enet_peer_disconnect_later(ev.peer, 0);
          messages_.push_back("Refused " + h->name + ": " + why);
          continue;
        }
        ev.peer->data = reinterpret_cast<void*>(intptr_t(free + 1));
        owner_[size_t(free)] = ev.peer;
        names_[size_t(free)] = name;
        messages_.push_back(name + " joined");
        changed = true;
      } else if (const Lobby* l = std::get_if<Lobby>(&d->packet); l && at > 0) {
        const int want = l->pick;
        if (want >= 1 && want < slots_ && !owner_[size_t(want)]) {
          owner_[size_t(want)] = owner_[size_t(at)], owner_[size_t(at)] = nullptr;
          names_[size_t(want)] = names_[size_t(at)], names_[size_t(at)] = "";
          ev.peer->data = reinterpret_cast<void*>(intptr_t(want + 1));
          changed = true;
        }
      }
    } else if (ev.type == ENET_EVENT_TYPE_DISCONNECT) {
      const int at = slot_of(ev.peer);
      if (at > 0) {
        messages_.push_back(names_[size_t(at)] + " left the lobby");
        owner_[size_t(at)] = nullptr, names_[size_t(at)] = "", pings_[size_t(at)] = 0;
        changed = true;
      }
    }
  }
  if (now_ms - last_lobby_ms_ >= 500 || changed) {
    for (int s = 1; s < slots_; ++s)
      if (owner_[size_t(s)]) pings_[size_t(s)] = static_cast<ENetPeer*>(owner_[size_t(s)])->roundTripTime;
    last_lobby_ms_ = now_ms;
    send_lobby();
  }
  const int in = pilots_in();
  status_ = "Hosting " + level_ + " on port " + std::to_string(cfg_.port) + ": " + std::to_string(in) + " of " +
            std::to_string(slots_) + " slots flown" +
            (cfg_.players > 0 ? ", launch at " + std::to_string(cfg_.players) : "");
}

// A pilot's lobby (connecting, the level checked and the Hello sent, the lobby's
// changes, the launch, a refusal).
void NetMatch::poll_join_lobby(double now_ms) {
  if (last_lobby_ms_ < -1e8) last_lobby_ms_ = now_ms;
  ENetEvent ev;
  while (phase_ != Phase::Over && phase_ != Phase::Playing && enet_host_service(wire_->host, &ev, 0) > 0) {
    if (ev.type == ENET_EVENT_TYPE_CONNECT) {
      const uint32_t t = uint32_t(cfg_.timeout_s * 1000);
      enet_peer_timeout(ev.peer, 0, t, t);
      status_ = "Connected to " + cfg_.join + "; checking the level";
    } else if (ev.type == ENET_EVENT_TYPE_DISCONNECT) {
      over(told_ ? "The host closed the connection" : "No host answers at " + cfg_.join);
    } else if (ev.type == ENET_EVENT_TYPE_RECEIVE) {
      std::string why;
      std::optional<Decoded> d = decode(ev.packet->data, ev.packet->dataLength, &why);
      enet_packet_destroy(ev.packet);
      if (!d) {
        over("The host at " + cfg_.join + " speaks otherwise: " + why);
        break;
      }
      if (const Reject* r = std::get_if<Reject>(&d->packet)) {
        over("Refused by " + cfg_.join + ": " + r->reason);
        break;
      }
      if (const Lobby* l = std::get_if<Lobby>(&d->packet)) {
        cfg_.game.difficulty = Difficulty(l->difficulty);
        cfg_.game.difficulty_override = true;
        for (size_t s = 0; s < l->ping_ms.size() && s < pings_.size(); ++s) pings_[s] = l->ping_ms[s];
        continue;
      }
      const Welcome* w = std::get_if<Welcome>(&d->packet);
      if (!w) continue;
      if (!told_) {
        level_ = w->level;
        if (level_.find("..") != std::string::npos || level_.empty() || level_[0] == '/') {
          over("The host names level '" + level_ + "'; allowed: a file under the data folder");
          break;
        }
        level_file_ = cfg_.game.root_dir + "/" + level_;
        if (!input_path_exists(level_file_)) {
          over("Level " + level_ + " is not in this data folder");
          break;
        }
        Game probe = Game::load_level(level_file_, cfg_.game);
        probe.set_pilots({});
        for (const PilotSlot& p : probe.world().pilots) {
          teams_.push_back(probe.world().team_name(probe.world().ship(p.ship).team));
          ships_.push_back(probe.world().ship(p.ship).name);
        }
        send_now(wire_->server, Hello{build_content_id(ARCFIRE_VERSION), level_content_hash(level_file_),
                                      asset_content_hash(cfg_.game.root_dir), cfg_.name});
        enet_host_flush(wire_->host);
        told_ = true;
        phase_ = Phase::Lobby;
      }
      slots_ = w->slot_count, local_ = w->slot, input_delay_ = w->input_delay, seed_ = w->seed, names_ = w->names;
      pings_.resize(size_t(slots_), 0.0);
      status_ = cfg_.join + ", " + level_ + ": waiting for the launch";
      if (w->start_tick == 1) {
        piloted_.assign(size_t(slots_), false);
        for (int s = 0; s < slots_; ++s) piloted_[size_t(s)] = (w->piloted_mask >> s) & 1;
        owner_.assign(size_t(slots_), nullptr);
        for (int s = 0; s < slots_; ++s) owner_[size_t(s)] = piloted_[size_t(s)] ? this : nullptr;
        start_match();
      }
    }
  }
  if (phase_ == Phase::Connecting && now_ms - last_lobby_ms_ > 5000) over("No host answers at " + cfg_.join);
}

void NetMatch::pick_slot(int slot) {
  if (cfg_.host || phase_ != Phase::Lobby || !wire_->server || slot < 1 || slot >= slots_) return;
  Lobby l;
  l.pick = uint8_t(slot);
  send_now(wire_->server, l);
  enet_host_flush(wire_->host);
}

bool NetMatch::launch() {
  if (!cfg_.host || phase_ != Phase::Lobby) return false;
  piloted_.assign(size_t(slots_), false);
  for (int s = 0; s < slots_; ++s) piloted_[size_t(s)] = s == 0 ? cfg_.host_flies : !names_[size_t(s)].empty();
  uint8_t mask = 0;
  for (int s = 0; s < slots_; ++s) mask = uint8_t(mask | (piloted_[size_t(s)] ? 1 << s : 0));
  for (int s = 1; s < slots_; ++s)
    if (ENetPeer* p = static_cast<ENetPeer*>(owner_[size_t(s)]))
      send_now(p, Welcome{uint8_t(s), uint8_t(slots_), uint8_t(input_delay_), mask, seed_, 1, names_, level_});
  enet_host_flush(wire_->host);
  start_match();
  return true;
}

void NetMatch::start_match() {
  GameOptions o = cfg_.game;
  Game game = Game::load_level(level_file_, o);
  PeerConfig pc;
  pc.slots = slots_, pc.local_slot = local_, pc.input_delay = input_delay_, pc.host = cfg_.host;
  pc.timeout_ms = cfg_.timeout_s * 1000.0;
  pc.piloted = piloted_;
  if (cfg_.host)
    for (int s = 1; s < slots_; ++s) wire_->by_slot[size_t(s)] = static_cast<ENetPeer*>(owner_[size_t(s)]);
  else
    wire_->by_slot[0] = wire_->server;
  was_dropped_.assign(size_t(slots_), false);
  for (int s = 0; s < slots_; ++s) was_dropped_[size_t(s)] = !pc.piloted[size_t(s)];
  peer_ = std::make_unique<NetPeer>(std::move(game), pc);
  phase_ = Phase::Playing;
  status_ = "Playing " + level_;
  std::printf("net: slot %d of %d, %s\n", local_, slots_, cfg_.host ? "hosting" : "joined");
  std::fflush(stdout);
}

void NetMatch::poll_match(double now_ms) {
  ENetEvent ev;
  while (enet_host_service(wire_->host, &ev, 0) > 0) {
    const int from = cfg_.host ? slot_of(ev.peer) : 0;
    if (ev.type == ENET_EVENT_TYPE_RECEIVE) {
      peer_->receive(from, ev.packet->data, ev.packet->dataLength, now_ms);
      enet_packet_destroy(ev.packet);
    } else if (ev.type == ENET_EVENT_TYPE_DISCONNECT) {
      if (cfg_.host && from > 0) {
        wire_->by_slot[size_t(from)] = nullptr;
        peer_->drop_pilot(from, now_ms);
      } else if (!cfg_.host) {
        host_gone_ = true;
      }
    } else if (ev.type == ENET_EVENT_TYPE_CONNECT && cfg_.host) {
      enet_peer_disconnect(ev.peer, 0);  // the match has started: no one joins now
    }
  }
}

void NetMatch::frame(const SlotInput& local, double now_ms) {
  if (phase_ != Phase::Playing) return;
  peer_->frame(local, now_ms);
  for (NetPeer::Outgoing& out : peer_->take_outgoing()) {
    if (!cfg_.host) wire_->send(0, out.bytes, out.reliable, now_ms);
    else
      for (int s = 1; s < slots_; ++s)
        if (out.to == -1 || out.to == s) wire_->send(s, out.bytes, out.reliable, now_ms);
  }
  wire_->pump(now_ms);
  const RollbackSession& rs = peer_->session();
  for (int s = 0; s < slots_; ++s)
    if (rs.dropped(s) && !was_dropped_[size_t(s)]) {
      was_dropped_[size_t(s)] = true;
      messages_.push_back(names_[size_t(s)] + " left; the AI flies their ship");
    }
  for (; logged_ < peer_->log().size(); ++logged_) std::printf("net: %s\n", peer_->log()[logged_].c_str());
  if (peer_->desync_tick()) over("desync at tick " + std::to_string(*peer_->desync_tick()));
  else if (peer_->ended() || host_gone_) over("The host left at tick " + std::to_string(rs.tick()) + "; the match is over");
}

std::vector<std::string> NetMatch::take_messages() { return std::exchange(messages_, {}); }

std::string NetMatch::final_line(int64_t up_to) const {
  if (!peer_) return "";
  const RollbackSession& rs = peer_->session();
  const int64_t fin = std::min<int64_t>(rs.final_tick(), up_to);
  char b[256];
  std::snprintf(b, sizeof b,
                "net: slot %d final tick %lld hash %s rollbacks %llu resimulated %llu ticks %llu compared %llu bytes_out %llu",
                local_, (long long)fin, fin > 0 ? hex(rs.hash_at(fin)).c_str() : "-",
                (unsigned long long)rs.stats().rollbacks, (unsigned long long)rs.stats().resimulated,
                (unsigned long long)rs.stats().ticks, (unsigned long long)peer_->counters().hashes_compared,
                (unsigned long long)peer_->counters().bytes_out);
  return b;
}

int NetMatch::pilots_connected() const {
  return int(std::count_if(wire_->by_slot.begin(), wire_->by_slot.end(), [](const ENetPeer* p) { return p != nullptr; }));
}

// A Bye to the others (the host's ends the match for them), and the connections closed.
void NetMatch::leave() {
  finished_ = true;
  if (!peer_->ended()) peer_->leave();
  for (NetPeer::Outgoing& out : peer_->take_outgoing())
    for (int s = 0; s < slots_; ++s)
      if (s != local_ && (cfg_.host || s == 0)) wire_->put(s, out.bytes, true);
  for (int s = 0; s < slots_; ++s)
    if (wire_->by_slot[size_t(s)]) enet_peer_disconnect_later(wire_->by_slot[size_t(s)], 0);
  enet_host_flush(wire_->host);
}

std::string NetMatch::finish(const std::string& record_path, int64_t last_tick) {
  if (!peer_ || finished_) return "";
  leave();
  const RollbackSession& rs = peer_->session();
  const std::string record = !record_path.empty() ? record_path : "net_match_" + std::to_string(local_) + ".replay";
  write_file_atomic(record, match_record_text(rs, level_, names_, last_tick));
  if (peer_->desync_tick()) write_file_atomic("net_dump_" + std::to_string(local_) + ".txt", rs.game().state_dump());
  if (phase_ == Phase::Playing) phase_ = Phase::Over;
  return record;
}

}  // namespace arc
