// WindowSession's network match: the lobby on the menu, the match's ticks through the rollback
// session with the local pilot's live input, the local slot's view, the net HUD and the end.
//
// There is no pause in a network match (the others fly on): Esc says so, and a second Esc
// within three seconds leaves the match.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/data_layers.h"
#include "core/input_file.h"
#include "core/json.h"
#include "game/app/campaign.h"
#include "game/app/mission_catalog.h"
#include "game/app/window_session.h"
#include "game/sim/camera_rig.h"
#include "game/sim/world.h"

namespace arc {
namespace {

double wall_ms() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

// Only what steers the pilot's own ship crosses the network (packet.h refuses the rest).
bool ship_command(Command c) {
  switch (c) {
    case Command::TargetNext: case Command::TargetNearest: case Command::TargetNextHostile:
    case Command::SwitchWeapon: case Command::Countermeasure: case Command::OrderAttack:
    case Command::OrderCover: case Command::OrderFormUp: case Command::OrderEngage: return true;
    default: return false;
  }
}

std::string padded(std::string s, size_t n) {
  if (s.size() > n) s.resize(n);
  s.resize(n, ' ');
  return s;
}

NetLobbyView lobby_view(const NetMatch& m, bool standalone) {
  NetLobbyView v;
  v.status = m.status();
  v.host = m.host();
  v.standalone = standalone;
  for (const NetPilotRow& r : m.pilots()) {
    const std::string ping = r.name.empty() ? "" : r.slot == 0 ? "host" : std::to_string(int(std::lround(r.ping_ms))) + " ms";
    v.rows.push_back(padded(std::to_string(r.slot), 5) + padded(r.team, 6) + padded(r.ship, 14) +
                     padded(r.name.empty() ? "(AI)" : r.name + (r.you ? " (you)" : ""), 25) + ping);
    v.free.push_back(r.name.empty());
  }
  return v;
}

}  // namespace

void WindowSession::start_net(NetMatch::Config c, bool standalone) {
  c.game.root_dir = game_options_.root_dir;
  c.input_delay = int(settings_.integer("net.input_delay"));
  c.timeout_s = settings_.number("net.timeout");
  c.sim_latency_ms = settings_.number("net.sim_latency_ms");
  c.sim_jitter_ms = settings_.number("net.sim_jitter_ms");
  c.sim_loss = settings_.number("net.sim_loss");
  net_ = std::make_unique<NetMatch>(std::move(c));
  net_standalone_ = standalone;
  net_view_on_ = net_camera_known_ = net_results_shown_ = net_reported_ = false;
  net_over_at_ = -1;
  net_rollback_samples_.clear();
  menu_->open_lobby(lobby_view(*net_, standalone));
  std::printf("net: %s\n", net_->status().c_str());
  std::fflush(stdout);
}

// The levels of the catalog with two or more slots (a "slots" list): the ones worth hosting.
std::vector<NetMission> WindowSession::net_missions() const {
  std::vector<NetMission> out;
  for (const MissionInfo& m : load_catalog_with_campaign(game_options_.root_dir)) {
    if (m.category != MissionCategory::Mission) continue;
    try {
      if (read_text_file(m.path).find("\"slots\"") != std::string::npos) out.push_back({m.path, m.title});
    } catch (const InputError&) {
    }
  }
  return out;
}

// The match's phases as the window follows them (lobby on the menu, the launch, messages,
// the end by --ticks, outcome, host leaving or desync, and what the window does after).
void WindowSession::update_net() {
  if (!net_) return;
  const double now = window_->time_seconds();
  const NetMatch::Phase before = net_->phase();
  net_view(false);
  net_->poll(wall_ms());
  for (const std::string& m : net_->take_messages()) {
    notices_.show(m, now, 6.0);
    std::printf("net: %s\n", m.c_str());
    std::fflush(stdout);
  }
  const NetMatch::Phase phase = net_->phase();
  if (!net_->peer_ready()) {
    if (menu_->screen() == MenuScreen::Lobby) menu_->set_lobby(lobby_view(*net_, net_standalone_));
    if (phase != NetMatch::Phase::Over) return;
    // Refused, or no host: one line, and the window closes (command line) or the menu says it.
    std::fprintf(stderr, "arcfire: %s\n", net_->status().c_str());
    if (net_standalone_) {
      net_failed_ = true;
      window_->request_close();
      return;
    }
    const std::string why = net_->status();
    net_.reset();
    menu_->open_main();
    menu_->set_message(why);
    return;
  }
  if (before != NetMatch::Phase::Playing && before != NetMatch::Phase::Over) {
    // The launch: the match's level is shown, flown by the menu's devices no more.
    menu_->close_lobby();
    load_models_for(net_->peer().session().game());
    clock_.emplace(int(std::lround(1.0 / net_->peer().session().game().tick_seconds())));
    const World& w = net_->peer().session().game().world();
    net_camera_ = net_prev_camera_ = w.camera;
    input_->reset_throttle();
    hud_.show_hud = true;
  }
  if (net_->peer_ready()) {
    const int64_t end_tick = options_.ticks > 0 ? options_.ticks : -1;
    const NetPeer& p = net_->peer();
    bool finished = end_tick > 0 && p.session().final_tick() >= end_tick;
    for (int s = 0; s < p.session().config().slots && finished; ++s)
      if (s != p.local_slot() && !p.session().dropped(s)) finished = p.compared_up_to(s) >= end_tick;
    if (finished && net_over_at_ < 0) end_net("The match reached tick " + std::to_string(end_tick));
    if (phase == NetMatch::Phase::Over && net_over_at_ < 0) end_net(net_->status());
    const World& w = p.session().game().world();
    if (!net_results_shown_ && w.outcome != Outcome::Undecided && net_over_at_ < 0 &&
        double(w.tick - w.outcome_tick) * w.dt > 3.0) {
      net_results_shown_ = true;
      net_view(true);
      NetLobbyView v;
      v.title = "RESULTS";
      v.status = outcome_text(w);
      v.standalone = net_standalone_;
      fill_net_hud();
      for (const NetHud::Row& r : hud_.net.rows) {
        const Ship& s = w.ships[r.ship];
        v.rows.push_back(padded(r.name, 24) + padded(w.team_name(s.team), 6) + "kills " + std::to_string(s.kills) +
                         "  deaths " + std::to_string(!s.alive && s.death_tick >= 0 ? 1 : 0) + "  damage " +
                         std::to_string(int(s.stats.damage_dealt)));
        v.free.push_back(false);
      }
      menu_->open_lobby(std::move(v));
    }
  }
  if (net_over_at_ >= 0 && now - net_over_at_ > 4.0 && !net_results_shown_) {
    if (net_standalone_ || options_.ticks > 0) {
      window_->request_close();
    } else {
      const std::string why = net_->status();
      net_view(false);
      net_.reset();
      back_to_main_menu();
      menu_->set_message(why);
    }
  }
  if (net_ && net_->peer_ready()) net_view(true);
}

// The match over (by --ticks, the host leaving, a desync or Leave): the record is written and
// the final line printed; the screen says why.
void WindowSession::end_net(const std::string& why) {
  if (!net_ || net_reported_) return;
  net_reported_ = true;
  net_over_at_ = window_->time_seconds();
  net_view(false);
  const int64_t up_to = options_.ticks > 0 ? options_.ticks : net_->peer_ready() ? net_->peer().session().final_tick() : 0;
  std::string record;
  try {
    record = net_->finish(options_.net.match_record, options_.ticks > 0 ? options_.ticks : RollbackSession::kNever);
  } catch (const std::exception& e) {
    notices_.show(e.what(), net_over_at_, 8.0);
  }
  std::printf("%s\n", net_->final_line(up_to).c_str());
  if (!record.empty()) std::printf("net: match record %s\n", record.c_str());
  std::fflush(stdout);
  notices_.show(why + (record.empty() ? "" : "; replay kept in " + record), net_over_at_, 8.0);
}

void WindowSession::step_net_ticks(double frame_seconds) {
  net_view(false);
  const int ticks = clock_->advance(frame_seconds);
  for (int i = 0; i < ticks; ++i) {
    InputFrame frame = input_->take_frame(ticks - i);
    std::vector<Command> commands = input_->take_commands();
    if (menu_->over_game() || net_over_at_ >= 0) frame = InputFrame{}, commands.clear();
    SlotInput in;
    in.input = frame;
    for (Command c : commands)
      if (ship_command(c) && in.commands.size() < 8) in.commands.push_back(c);
    net_->frame(in, wall_ms());
    const World& w = net_->peer().session().game().world();
    const int local = net_->local_slot();
    if (size_t(local) < w.pilots.size() && w.pilots[size_t(local)].ship != w.player) {
      const Ship& me = w.ship(w.pilots[size_t(local)].ship);
      net_prev_camera_ = net_camera_;
      if (me.alive) net_camera_ = chase_rig(net_camera_, me, w.dt);
    }
  }
  net_view(true);
  // Sounds from the world as shown, once a frame: a prediction a rollback undid never sounds.
  if (ticks > 0) audio_->after_tick(net_->peer().session().game().world());
}

// The world as this pilot sees it: its slot's ship is the one the HUD and the camera follow.
// Undone before every step (the player and the camera rig are not the simulation's to change).
void WindowSession::net_view(bool on) {
  if (!net_ || !net_->peer_ready() || on == net_view_on_) return;
  World& w = net_->peer_mut().session_mut().game_mut().world_mut();
  const int local = net_->local_slot();
  if (on) {
    net_saved_player_ = w.player, net_saved_camera_ = w.camera, net_saved_prev_camera_ = w.prev_camera;
    if (size_t(local) < w.pilots.size() && w.pilots[size_t(local)].ship != w.player) {
      w.player = w.pilots[size_t(local)].ship;
      w.camera = net_camera_, w.prev_camera = net_prev_camera_;
    }
  } else {
    w.player = net_saved_player_, w.camera = net_saved_camera_, w.prev_camera = net_saved_prev_camera_;
  }
  net_view_on_ = on;
}

// Names over ships and in the feed, the F3 figures and the scoreboard (held H).
void WindowSession::fill_net_hud() {
  NetHud& n = hud_.net;
  n = NetHud{};
  if (!net_ || !net_->peer_ready()) return;
  const NetPeer& p = net_->peer();
  const World& w = p.session().game().world();
  n.on = true;
  if (p.desync_tick()) hud_.error_banner = "desync at tick " + std::to_string(*p.desync_tick());
  n.scoreboard = devices_.keys[size_t(key_code("H"))];
  const std::vector<NetPilotRow> pilots = net_->pilots();
  double worst_ping = 0;
  for (const NetPilotRow& r : pilots) {
    if (size_t(r.slot) >= w.pilots.size()) continue;
    const uint32_t ship = w.pilots[size_t(r.slot)].ship.index();
    const bool flown = !r.name.empty() && !p.session().dropped(r.slot);
    if (flown) n.names[ship] = r.name;
    n.rows.push_back({ship, flown ? r.name : "AI (" + r.ship + ")", r.ping_ms, r.you});
    if (!r.you && flown) worst_ping = std::max(worst_ping, r.ping_ms);
  }
  const double now = window_->time_seconds();
  net_rollback_samples_.push_back({now, p.session().stats().rollbacks});
  while (net_rollback_samples_.size() > 2 && now - net_rollback_samples_.front().first > 1.0)
    net_rollback_samples_.erase(net_rollback_samples_.begin());
  const auto& [t0, r0] = net_rollback_samples_.front();
  const double rate = now - t0 > 0.05 ? double(p.session().stats().rollbacks - r0) / (now - t0) : 0.0;
  char b[96];
  std::snprintf(b, sizeof b, "ping %.0f ms  rollbacks %.1f/s", worst_ping, rate);
  n.stats = b;
}

void WindowSession::net_escape() {
  const double now = window_->time_seconds();
  if (now - net_escape_at_ < 3.0) {
    end_net("You left the match");
    net_escape_at_ = -1e9;
    return;
  }
  net_escape_at_ = now;
  notices_.show("No pause in a network match: Esc again leaves it", now, 3.0);
}

}  // namespace arc
