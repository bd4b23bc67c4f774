// soak (on request: arcfire-bench --scene soak): does the game hold up for an hour? The arena
// battle runs for an hour of game time headless without rendering, then ten minutes of game time
// rendered at 640×360 (every tick, chase camera), sampling resident memory every game minute. The
// player holds half throttle and the beam; a decided battle is restarted with the next seed five
// seconds later, as a player would from the results screen. Every ten game seconds the whole
// simulation state (Game::state_dump) and every particle of the view are checked for NaN and
// infinity; one is a failure (exit 1).
//   soak_rss_growth_fraction         headless hour: resident memory at the end ÷ after the first minute, − 1
//                                    (the heap's bytes in use are printed beside it, each game minute)
//   soak_rss_growth_second_half_fraction  headless hour: at the end ÷ at half time, − 1 (a leak
//                                    grows on; pools and buffers reaching their high-water mark stop)
//   soak_render_rss_growth_fraction  the same over the rendered ten minutes
//   soak_max_particles               live particles, the most at any tick
//   soak_max_pools_on_heap           live pools the particle store could not serve, the most at any tick
//   soak_restarts                    battles decided and restarted
//   soak_game_minutes                game minutes run in all (ARCFIRE_SOAK_MINUTES=N shortens the hour,
//                                    ARCFIRE_SOAK_RENDER_MINUTES=N sets the rendered part, 0 skips it)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <malloc.h>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

#include "bench_registry.h"
#include "bench_scenes.h"
#include "core/settings.h"
#include "game/app/all_settings.h"
#include "game/app/scene_resources.h"
#include "game/render/render_view_builder.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "gfx/renderer.h"
#include "core/data_root.h"

namespace arc {
namespace {

constexpr int kWidth = 640, kHeight = 360;
constexpr int kCheckEvery = 600;  // ticks between NaN checks (ten seconds at 60 Hz)

double resident_mib() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return double(resident) * double(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// The heap's bytes in use (glibc), beside the resident size: a step of the resident size with
// no step here is memory the allocator keeps, not memory the game holds.
double heap_in_use_mib() {
  const struct mallinfo2 m = ::mallinfo2();
  return double(m.uordblks + m.hblkhd) / (1024.0 * 1024.0);
}

bool finite_text(const std::string& dump) {
  // The dump prints doubles with operator<<: a non-finite one reads nan, -nan, inf or -inf.
  size_t i = 0;
  while (i < dump.size()) {
    const size_t start = dump.find_first_not_of(" \n\t[]{}():,=", i);
    if (start == std::string::npos) break;
    size_t end = dump.find_first_of(" \n\t[]{}():,=", start);
    if (end == std::string::npos) end = dump.size();
    std::string word = dump.substr(start, end - start);
    if (!word.empty() && word[0] == '-') word.erase(0, 1);
    if (word == "nan" || word == "inf") return false;
    i = end;
  }
  return true;
}

bool finite_view(const RenderView& view) {
  for (const ParticleInstance& p : view.particles) {
    const float v[] = {p.pos[0], p.pos[1], p.pos[2], p.size, p.axis[0], p.axis[1], p.axis[2], p.rotation,
                       p.color[0], p.color[1], p.color[2], p.color[3], p.burn, p.soft_extent};
    for (float x : v)
      if (!std::isfinite(x)) return false;
  }
  return true;
}

struct SoakRun {
  std::string root = arc::data_root();
  uint64_t seed = 1;
  int restarts = 0;
  int64_t decided_at = -1;  // game tick (of the soak) a battle was decided
  size_t max_particles = 0;
  uint32_t max_pools_on_heap = 0;  // pools the particle store could not serve (particle_store.h)
  bool failed = false;
  Game game = load(1);

  Game load(uint64_t s) const {
    GameOptions o;
    o.root_dir = root;
    o.seed_override = true;
    o.seed = s;
    return Game::load_level(root + "/levels/arena.json", o);
  }

  // One tick of play; restarts a decided battle after five seconds.
  void step(int64_t soak_tick) {
    InputFrame in{};
    in.throttle = 64;
    in.buttons = kFirePrimary;
    game.step(in);
    const ParticleStats st = game.world().particles->stats();
    max_particles = std::max<size_t>(max_particles, st.live_particles);
    max_pools_on_heap = std::max(max_pools_on_heap, st.pools_on_heap);
    if (game.world().outcome == Outcome::Undecided) return;
    if (decided_at < 0) decided_at = soak_tick;
    if (soak_tick - decided_at < 300) return;
    // The decided battle is given back before the next is built, so the two are never alive
    // together: their sum would set the heap's high-water mark at every restart.
    { const Game decided = std::move(game); }
    game = load(++seed);
    ++restarts;
    decided_at = -1;
  }

  void check(const RenderView& view, int64_t soak_tick) {
    if (failed || (finite_text(game.state_dump()) && finite_view(view))) return;
    failed = true;
    bench::report_failure("soak: NaN or infinity in the state at soak tick " + std::to_string(soak_tick) + " (seed " +
                          std::to_string(seed) + ", game tick " + std::to_string(game.tick()) + ")");
  }
};

// Resident memory at the end of a phase ÷ after its first game minute, − 1.
double growth(const std::vector<double>& mib) { return mib.size() < 2 ? 0.0 : mib.back() / mib[1] - 1.0; }

void print_samples(const char* phase, const std::vector<double>& mib) {
  std::printf("  %s MiB by game minute:", phase);
  for (size_t i = 0; i < mib.size(); ++i) std::printf("%s%.1f", i % 10 ? " " : (i ? "\n    " : " "), mib[i]);
  std::printf("\n");
}

ARCFIRE_SCENE_ON_REQUEST(soak) {
  const char* env = std::getenv("ARCFIRE_SOAK_MINUTES");
  const int headless_minutes = env ? std::max(2, std::atoi(env)) : 60;
  const char* render_env = std::getenv("ARCFIRE_SOAK_RENDER_MINUTES");
  const int render_minutes = render_env ? std::max(0, std::atoi(render_env)) : std::max(2, headless_minutes / 6);
  const int64_t per_minute = 3600;  // ticks at the arena's 60 Hz
  SoakRun run;
  const std::vector<ModelId> no_models(run.game.world().model_paths.size());
  RenderView view;
  std::vector<double> headless_mib{resident_mib()}, render_mib, heap_mib{heap_in_use_mib()};
  const double t0 = bench::now_seconds();
  int64_t tick = 0;
  for (; tick < headless_minutes * per_minute && !run.failed; ++tick) {
    run.step(tick);
    if ((tick + 1) % kCheckEvery == 0) {
      build_render_view(run.game.world(), no_models, 1.0, CameraSettings{}, HudState{}, kWidth, kHeight, view);
      run.check(view, tick);
    }
    if ((tick + 1) % per_minute == 0) {
      headless_mib.push_back(resident_mib());
      heap_mib.push_back(heap_in_use_mib());
    }
  }
  const double headless_s = bench::now_seconds() - t0;
  std::printf("  headless: %d game minutes in %.0f s, resident %.1f -> %.1f MiB (after minute 1: %.1f)\n", headless_minutes,
              headless_s, headless_mib.front(), headless_mib.back(), headless_mib.size() > 1 ? headless_mib[1] : 0.0);
  std::fflush(stdout);
  const std::unique_ptr<HeadlessContext> ctx = render_minutes > 0 ? bench::context_or_skip() : nullptr;
  if (ctx && !run.failed) {
    RendererDesc desc;
    desc.offscreen = true;
    desc.shader_dir = run.root + "/shaders";
    Renderer renderer(desc);
    renderer.apply_settings(all_settings());
    const std::vector<ModelId> models = load_scene_resources(renderer, run.game.world(), run.root);
    render_mib.push_back(resident_mib());
    const double t1 = bench::now_seconds();
    for (int64_t i = 0; i < render_minutes * per_minute && !run.failed; ++i, ++tick) {
      run.step(tick);
      build_render_view(run.game.world(), models, 1.0, CameraSettings{}, HudState{}, kWidth, kHeight, view);
      renderer.render(view, kWidth, kHeight);
      if ((i + 1) % kCheckEvery == 0) {
        renderer.finish();
        run.check(view, tick);
      }
      if ((i + 1) % per_minute == 0) render_mib.push_back(resident_mib());
    }
    std::printf("  rendered: %d game minutes at %dx%d in %.0f s, resident %.1f -> %.1f MiB (after minute 1: %.1f)\n",
                render_minutes, kWidth, kHeight, bench::now_seconds() - t1, render_mib.front(), render_mib.back(),
                render_mib.size() > 1 ? render_mib[1] : 0.0);
  }
  print_samples("headless resident", headless_mib);
  print_samples("headless heap in use", heap_mib);
  if (!render_mib.empty()) print_samples("rendered resident", render_mib);
  bench::report_metric("soak_rss_growth_fraction", growth(headless_mib));
  bench::report_metric("soak_rss_growth_second_half_fraction", headless_mib.back() / headless_mib[headless_mib.size() / 2] - 1.0);
  if (!render_mib.empty()) bench::report_metric("soak_render_rss_growth_fraction", growth(render_mib));
  bench::report_metric("soak_max_particles", double(run.max_particles));
  bench::report_metric("soak_max_pools_on_heap", double(run.max_pools_on_heap));
  bench::report_metric("soak_restarts", run.restarts);
  bench::report_metric("soak_game_minutes", double(tick) / double(per_minute));
}

}  // namespace
}  // namespace arc
