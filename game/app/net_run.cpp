// game/app/net_run.cpp — `--headless --host` / `--join`: the window's NetMatch run in a blocking
// loop at 60 Hz, flown by the scripted test pilot or by no input; the lines it prints, the
// record and the exit code.
#include "game/app/net_run.h"

#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <thread>

#include "core/error.h"
#include "core/settings.h"
#include "game/app/app_options.h"
#include "game/app/net_match.h"
#include "game/net/scripted_pilot.h"
#include "platform/stop_request.h"

namespace arc {
namespace {

constexpr int64_t kDefaultTicks = 3600;  // a 60-second match
constexpr double kFrameMs = 1000.0 / 60.0;

double now_ms() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

// Sleeps to the next frame; after a long stall it starts afresh rather than catching up in a burst.
void pace(double& next) {
  next += kFrameMs;
  const double wait = next - now_ms();
  if (wait > 0) std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(wait));
  else if (wait < -250) next = now_ms();
}

NetMatch::Config config_of(const AppOptions& o) {
  NetMatch::Config c;
  c.host = o.net.host, c.level = o.level, c.join = o.net.join, c.port = o.net.port, c.players = o.net.players;
  c.name = checked_pilot_name(o.net.name.empty() ? "Pilot" : o.net.name, "--name");
  c.host_flies = !o.net.pilot.empty();
  c.game = o.game;
  c.input_delay = int(o.settings.integer("net.input_delay"));
  c.timeout_s = o.settings.number("net.timeout");
  c.sim_latency_ms = o.settings.number("net.sim_latency_ms");
  c.sim_jitter_ms = o.settings.number("net.sim_jitter_ms");
  c.sim_loss = o.settings.number("net.sim_loss");
  return c;
}

void say(const std::string& line) {
  std::printf("net: %s\n", line.c_str());
  std::fflush(stdout);
}

// The lobby: the host launches when --players pilots are in; a pilot waits for the launch.
// A refusal, no host, or no launch in time is bad input (exit 2) in one line; false when
// SIGINT or SIGTERM stopped the wait.
bool lobby(NetMatch& m, const AppOptions& o) {
  const std::string who = o.net.host ? "--host" : "--join";  // a pilot's lines name the address
  const double limit_s = o.net.host ? 120 : 130;
  const double give_up = now_ms() + limit_s * 1000;
  std::string said;
  while (m.phase() != NetMatch::Phase::Playing) {
    if (stop_requested()) return false;
    m.poll(now_ms());
    for (const std::string& line : m.take_messages()) say(line);
    std::string why = m.status();
    if (m.phase() == NetMatch::Phase::Over) {
      if (!why.empty()) why[0] = char(std::tolower(static_cast<unsigned char>(why[0])));
      throw InputError(who + ": " + why);
    }
    if (why != said && m.phase() != NetMatch::Phase::Playing) say(said = why);
    if (now_ms() > give_up)
      throw InputError(who + ": " + (o.net.host ? std::to_string(m.pilots_in()) + " of " + std::to_string(o.net.players) + " pilots" : "no launch") +
                       " after " + std::to_string(int(limit_s)) + " s; no match");
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

}  // namespace

int run_net(const AppOptions& o) {
  if (o.net.host && !o.net.join.empty()) throw InputError("--host and --join: one at a time");
  if (!o.headless) throw InputError("--host / --join: the headless match runs with --headless");
  NetMatch m(config_of(o));
  if (!lobby(m, o)) return report_stop("in the lobby");
  const int64_t ticks = o.ticks > 0 ? o.ticks : kDefaultTicks;
  const bool scripted = o.net.pilot == "scripted";
  const int local = m.local_slot();
  double next = now_ms(), done_at = -1;
  for (;;) {
    m.poll(now_ms());
    const NetPeer& p = m.peer();
    const int64_t next_tick = int64_t(p.session().inputs(local).size()) + 1;
    m.frame(scripted && next_tick <= ticks ? scripted_pilot_input(local, next_tick) : SlotInput{}, now_ms());
    for (const std::string& line : m.take_messages()) say(line);
    bool finished = p.session().final_tick() >= ticks;
    for (int s = 0; s < p.session().config().slots && finished; ++s)
      if (s != local && !p.session().dropped(s)) finished = p.compared_up_to(s) >= ticks;
    if ((finished || m.phase() == NetMatch::Phase::Over || stop_requested()) && done_at < 0) done_at = now_ms();
    // The host lingers so every pilot can compare its last hashes; a pilot leaves at once.
    if (done_at >= 0 && (!o.net.host || m.pilots_connected() == 0 || now_ms() - done_at > 3000 || p.desync_tick() ||
                         stop_requested()))
      break;
    pace(next);
  }
  const std::string record = m.finish(o.net.match_record, ticks);
  std::printf("%s\n", m.final_line(ticks).c_str());
  const NetPeer& p = m.peer();
  if (p.desync_tick()) {
    std::fprintf(stderr, "arcfire: desync at tick %lld; state in net_dump_%d.txt, match in %s\n", (long long)*p.desync_tick(),
                 local, record.c_str());
    return 1;
  }
  // SIGINT or SIGTERM: the others were told (a Bye) and the record holds the match so far.
  if (stop_requested()) return report_stop("at tick " + std::to_string(p.session().final_tick()) + " of " + std::to_string(ticks));
  return 0;
}

}  // namespace arc
