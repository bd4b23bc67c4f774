// netplay: what rollback costs and what a network match sends. The arena battle with its eight
// slots (the player's piloted, the rest flown by the AI), 600 ticks in:
//   net_save_state_us      keeping one tick's state (copy into a kept Game)
//   net_rollback_8_ms      restoring a kept state and re-simulating 8 ticks
//   *_cpu_*                the same in the thread's CPU time, which other processes on a
//                          shared machine do not inflate
// then 600-tick duels between two peers over the link simulator, through the host, at 50, 100
// and 200 ms round trip (±10 % jitter), with 0 and 5 % loss:
//   net_resim_share_RTT_LOSS   re-simulated ticks as a share of ticks advanced (both peers)
//   net_bytes_per_s            bytes a peer sends per second at 60 Hz (100 ms, 5 % loss)
//   net_max_correction_m       the farthest a ship jumped on a rollback there
#include <algorithm>
#include <cstdio>
#include <string>
#include <ctime>
#include <vector>

#include "bench_registry.h"
#include "core/data_root.h"
#include "game/net/rollback.h"
#include "game/sim/game.h"
#include "net_match_harness.h"

namespace arc {
namespace {

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

ARCFIRE_SCENE(netplay) {
  const std::string root = arc::data_root();
  GameOptions options;
  options.root_dir = root;
  Game game = Game::load_level(root + "/levels/arena.json", options);
  std::vector<bool> piloted(game.slot_count(), false);
  piloted[0] = true;
  game.set_pilots(piloted);
  std::vector<SlotInput> in(game.slot_count());
  in[0].input.throttle = 64;
  in[0].input.buttons = kFirePrimary;
  for (int t = 0; t < 600; ++t) game.step_slots(in);
  Game kept(game);
  std::vector<double> save_us, rollback_ms, save_cpu_us, rollback_cpu_ms;
  for (int i = 0; i < 60; ++i) {
    const double t0 = bench::now_seconds(), c0 = thread_cpu_seconds();
    kept.copy_state_from(game);
    save_us.push_back((bench::now_seconds() - t0) * 1e6);
    save_cpu_us.push_back((thread_cpu_seconds() - c0) * 1e6);
  }
  Game live(game);
  for (int i = 0; i < 20; ++i) {
    const double t0 = bench::now_seconds(), c0 = thread_cpu_seconds();
    live.copy_state_from(kept);
    for (int k = 0; k < 8; ++k) live.step_slots(in);
    rollback_ms.push_back((bench::now_seconds() - t0) * 1e3);
    rollback_cpu_ms.push_back((thread_cpu_seconds() - c0) * 1e3);
  }
  bench::report_metric("net_save_state_us", bench::median(save_us));
  bench::report_metric("net_rollback_8_ms", bench::median(rollback_ms));
  bench::report_metric("net_save_state_cpu_us", bench::median(save_cpu_us));
  bench::report_metric("net_rollback_8_cpu_ms", bench::median(rollback_cpu_ms));

  for (double rtt : {50.0, 100.0, 200.0}) {
    for (double loss : {0.0, 0.05}) {
      nettest::MatchSetup m;
      m.level = root + "/levels/duel.json";
      m.root = root;
      m.ticks = 600;
      // Pilot to pilot through the host: four one-way legs.
      m.link = {.latency_ms = rtt / 4, .jitter_ms = rtt / 40, .loss = loss, .seed = 11};
      const nettest::MatchResult r = nettest::run_match(m);
      double advanced = 0, resim = 0;
      for (const RollbackStats& s : r.stats) advanced += double(s.ticks), resim += double(s.resimulated);
      char name[64];
      std::snprintf(name, sizeof name, "net_resim_share_%d_%d", int(rtt), int(loss * 100));
      bench::report_metric(name, advanced > 0 ? resim / advanced : 0.0);
      if (rtt == 100.0 && loss > 0) {
        bench::report_metric("net_bytes_per_s", r.seconds > 0 ? double(r.counters[1].bytes_out) / r.seconds : 0.0);
        double jump = 0;
        for (const RollbackStats& s : r.stats) jump = std::max(jump, s.max_correction_m);
        bench::report_metric("net_max_correction_m", jump);
      }
    }
  }
}

}  // namespace
}  // namespace arc
