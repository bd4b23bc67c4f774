// The test pilot's duel (tests/unit/game/test_pilot.h): a person who sees only the HUD, reacts
// after 200 ms and aims with a wandering hand, against the AI of levels/duel.json over 20 seeds
// per difficulty, and a pilot who does nothing. Targets: wins >= 90 % on easy,
// 50–80 % on normal, 15–45 % on hard, median time to win under 90 s on normal, and the idle
// pilot loses every fight. Simulation only (no GL); about a minute on two shared cores.
//   test_pilot_win_rate_easy / _normal / _hard   share of fights won
//   test_pilot_median_win_s_normal                median seconds to win on normal
//   test_pilot_idle_loss_rate                     share of all idle fights lost
#include <cstdio>

#include "bench_registry.h"
#include "test_pilot.h"
#include "core/data_root.h"

ARCFIRE_SCENE(test_pilot) {
  const char* names[] = {"easy", "normal", "hard"};
  constexpr int kSeeds = 20;
  int idle_fights = 0, idle_losses = 0;
  for (int d = 0; d < 3; ++d) {
    const double start = arc::bench::now_seconds();
    const arc::DuelRates r = arc::duel_rates(arc::data_root(), d, kSeeds, arc::PilotKind::Person);
    const arc::DuelRates idle = arc::duel_rates(arc::data_root(), d, kSeeds, arc::PilotKind::Idle);
    idle_fights += idle.fights;
    idle_losses += idle.losses;
    std::printf("  %-6s person won %2d, lost %2d, undecided %2d of %d (median win %.1f s); idle lost %d of %d  [%.1f s]\n",
                names[d], r.wins, r.losses, r.fights - r.wins - r.losses, r.fights, r.median_win_s, idle.losses,
                idle.fights, arc::bench::now_seconds() - start);
    arc::bench::report_metric(std::string("test_pilot_win_rate_") + names[d], r.win_rate);
    if (d == 1) arc::bench::report_metric("test_pilot_median_win_s_normal", r.median_win_s);
  }
  arc::bench::report_metric("test_pilot_idle_loss_rate", idle_fights ? double(idle_losses) / idle_fights : 0.0);
}
