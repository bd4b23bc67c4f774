// game/app/net_match.h — a network match: the lobby and the match, polled a frame at a time
// (by the window, and by net_run.cpp's headless loop for `--headless --host` / `--join`).
//
// The host listens and flies slot 0; a pilot connects, shows the host its build, level and data
// (refused with one line naming what differs), takes the first free slot and may pick another
// free one in the lobby (Lobby packets). The host sends every pilot the lobby (Welcome with
// start_tick 0: names by slot; Lobby: pings) whenever it changes and every half second, and
// Launch sends the final Welcome (start_tick 1). Then a NetPeer (game/net/net_peer.h) runs the
// match: frame() once per 60 Hz tick with the local pilot's input. Nothing here blocks.
//
// Example, compiled as NetMatch.HostAndJoin in tests/unit/app/test_net_match.cpp:
//   NetMatch host(host_config(port));
//   jc.join = "127.0.0.1:" + std::to_string(port);
//   jc.name = "Ann";
//   NetMatch pilot(jc);
//   pilot.pick_slot(3);
//   ASSERT_TRUE(host.launch());
//   host.poll(now_ms()), pilot.poll(now_ms());
//   host.frame(SlotInput{}, now_ms()), pilot.frame(SlotInput{}, now_ms());
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "game/net/net_peer.h"
#include "game/sim/game.h"

namespace arc {

class Settings;

// A row of the lobby (and of the scoreboard's names): one per slot of the level.
struct NetPilotRow {
  int slot = 0;
  std::string name;    // "" : the AI flies it
  std::string team;    // the level's team of the slot's ship
  std::string ship;    // the ship's name in the level
  double ping_ms = 0;  // round trip to the host (the host's own: 0)
  bool you = false;
};

class NetMatch {
 public:
  struct Config {
    bool host = false;
    std::string level;         // host: the level file
    std::string join;          // pilot: HOST[:PORT]
    int port = 27960;          // host: where to listen; pilot: the port when `join` names none
    int players = 0;           // host: launch when this many pilots are in (0: the host launches)
    std::string name = "Pilot";
    bool host_flies = true;    // host: false leaves slot 0 to the AI (a headless host without a pilot)
    GameOptions game;          // the host's difficulty goes to everyone with the level
    int input_delay = 0;
    double timeout_s = 5;
    double sim_latency_ms = 0, sim_jitter_ms = 0, sim_loss = 0;  // net.sim_* (tests)
  };
  enum class Phase { Connecting, Lobby, Playing, Over };

  // Host: listens (InputError when the port is taken); pilot: starts to connect.
  explicit NetMatch(Config c);
  ~NetMatch();
  NetMatch(const NetMatch&) = delete;
  NetMatch& operator=(const NetMatch&) = delete;

  // Takes what arrived: lobby changes before the launch, the peers' packets after it.
  void poll(double now_ms);
  Phase phase() const { return phase_; }
  bool host() const { return cfg_.host; }
  // One line for the lobby: whom it waits for, or why the match is over.
  const std::string& status() const { return status_; }
  std::vector<NetPilotRow> pilots() const;
  int pilots_in() const;
  const std::string& level_name() const { return level_; }  // as the host names it
  const std::string& level_file() const { return level_file_; }
  int local_slot() const { return local_; }
  // A pilot asks for a free slot (the host keeps slot 0); the host's answer is the next lobby.
  void pick_slot(int slot);
  // The host starts the match with the pilots in; false (and status()) when it cannot.
  bool launch();

  // Playing: one tick's frame with the local pilot's input, then the packets out.
  void frame(const SlotInput& local, double now_ms);
  bool peer_ready() const { return peer_ != nullptr; }
  const NetPeer& peer() const { return *peer_; }
  NetPeer& peer_mut() { return *peer_; }
  const std::vector<std::string>& names() const { return names_; }
  // Lines for the screen since the last call: drops ("Ann left; the AI flies their ship"), the
  // host leaving, a desync.
  std::vector<std::string> take_messages();
  // Leaves the match (a Bye), writes the match record (and on a desync the state dump);
  // returns the record's path ("" before the launch or when done before). The record stops at
  // `last_tick` when the peers ran on past the match's end while saying goodbye. The destructor
  // leaves without writing (the window calls finish() when a match ends or it closes).
  std::string finish(const std::string& record_path = "", int64_t last_tick = RollbackSession::kNever);
  // "net: slot S final tick T hash H rollbacks R ... bytes_out B", the line a match ends with.
  std::string final_line(int64_t up_to_tick) const;
  // Host: the pilots still connected (a host lingers after the end until they have compared).
  int pilots_connected() const;

 private:
  void poll_host_lobby(double now_ms);
  void poll_join_lobby(double now_ms);
  void poll_match(double now_ms);
  void send_lobby();
  void start_match();
  void over(const std::string& why);
  void leave();

  struct Wire;
  Config cfg_;
  std::unique_ptr<Wire> wire_;
  Phase phase_ = Phase::Connecting;
  std::string status_;
  std::string level_, level_file_;
  uint64_t seed_ = 0;
  int slots_ = 1, local_ = 0, input_delay_ = 0;
  std::vector<std::string> names_;   // by slot ("" : AI)
  std::vector<double> pings_;        // by slot
  std::vector<void*> owner_;         // host: the connection flying each slot
  std::vector<bool> piloted_;        // by slot at the launch: flown by a pilot's input, not the AI
  std::vector<std::string> teams_, ships_;
  std::unique_ptr<NetPeer> peer_;
  std::vector<bool> was_dropped_;
  size_t logged_ = 0;
  std::vector<std::string> messages_;
  double last_lobby_ms_ = -1e9;
  bool told_ = false, finished_ = false, host_gone_ = false;
};

// "Ann": 1..24 printable ASCII characters, else InputError naming `where` and what is allowed.
std::string checked_pilot_name(const std::string& name, const std::string& where);

}  // namespace arc
