// sim_threads: the simulation's particle update on one thread and on every core (sim.threads,
// oneTBB; particles/particle_world.h). Two copies of each scene are stepped tick by tick in
// turn, one with sim.threads=1 and one with every core, every step timed; the figures are the
// medians per tick:
//   sim_arena_tick_ms_1_thread, sim_arena_tick_ms_all_threads   the arena battle's first 600 ticks
//   particle_update_1m_ms_1_thread, particle_update_1m_ms_all_threads
//       1 048 576 live particles (256 clusters of smoke in view) advanced one tick
// and the cores used. The hashes of both copies are compared at the end (they must be equal).
#include <algorithm>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "bench_registry.h"
#include "bench_scenes.h"
#include "core/data_root.h"
#include "game/sim/game.h"
#include "game/sim/input.h"
#include "game/sim/world.h"
#include "particles/effect_library.h"
#include "particles/particle_world.h"

namespace arc {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

constexpr const char* kSmoke = R"({
  "description": "a long-lived smoke cluster for the update bench",
  "clusters": [{
    "name": "smoke", "sprite": "smoke", "soft_edge": "linear",
    "animation": { "type": "linear", "drag": 1.2 },
    "emitter": { "shape": "sphere", "radius": 4, "burst": 4096 },
    "particles": { "speed": [1, 5], "lifetime": [600, 600], "size": [0.8, 1.4] },
    "curves": { "size": [[0, 1], [1, 3]], "alpha": [[0, 0.7], [1, 0]], "burn": [[0, 0.9], [0.2, 0]] }
  }]
})";

}  // namespace

ARCFIRE_SCENE(sim_threads) {
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  std::printf("  %d cores\n", cores);
  // The arena battle.
  {
    const std::string root = data_root();
    std::vector<Game> games;
    for (int threads : {1, 0}) {
      GameOptions o;
      o.root_dir = root;
      o.sim_threads = threads;
      games.push_back(Game::load_level(root + "/levels/arena.json", o));
    }
    std::vector<double> ms[2];
    for (int t = 0; t < 600; ++t)
      for (int k = 0; k < 2; ++k) {
        const int i = t % 2 ? 1 - k : k;
        const double t0 = bench::now_seconds();
        games[size_t(i)].step(InputFrame{});
        ms[i].push_back((bench::now_seconds() - t0) * 1000.0);
      }
    const bool same = games[0].full_hash() == games[1].full_hash();
    std::printf("  arena, 600 ticks: median %.3f ms a tick on 1 thread, %.3f ms on %d; hashes %s\n", median(ms[0]),
                median(ms[1]), cores, same ? "equal" : "DIFFER");
    bench::report_metric("sim_arena_tick_ms_1_thread", median(ms[0]));
    bench::report_metric("sim_arena_tick_ms_all_threads", median(ms[1]));
  }
  // A million particles.
  {
    EffectLibrary fx;
    fx.load_text(kSmoke, "bench/smoke.json");
    std::vector<ParticleWorld> worlds;
    worlds.reserve(2);  // no copies: each has its own store
    for (int threads : {1, 0}) {
      ParticleConfig pc;
      pc.budget = 1u << 20;
      pc.threads = threads;
      worlds.emplace_back(pc, &fx);
    }
    ParticleCamera cam;
    for (ParticleWorld& w : worlds) {
      for (int c = 0; c < 256; ++c) {
        SpawnParams sp;
        sp.position = glm::dvec3(double(c % 16) * 20.0 - 150.0, double(c / 16) * 12.0 - 90.0, -400.0);
        w.spawn("smoke", sp);
      }
      w.step(1, cam);
    }
    std::vector<double> ms[2];
    for (uint64_t t = 2; t < 42; ++t)
      for (int k = 0; k < 2; ++k) {
        const int i = t % 2 ? 1 - k : k;
        const double t0 = bench::now_seconds();
        worlds[size_t(i)].step(t, cam);
        ms[i].push_back((bench::now_seconds() - t0) * 1000.0);
      }
    const ParticleStats st = worlds[0].stats();
    std::printf("  %u live particles, %u animated a tick: median %.2f ms a tick on 1 thread, %.2f ms on %d\n",
                st.live_particles, st.animated_particles, median(ms[0]), median(ms[1]), cores);
    bench::report_metric("particle_update_1m_ms_1_thread", median(ms[0]));
    bench::report_metric("particle_update_1m_ms_all_threads", median(ms[1]));
  }
}

}  // namespace arc
