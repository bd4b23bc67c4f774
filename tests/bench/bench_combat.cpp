// combat_view: frame rate where the player is. A recorded dogfight (tests/bench/combat_view.replay:
// the duel flown by the test pilot of tests/unit/game/test_pilot.h, 30 s with beams, missiles,
// shield hits and the enemy's explosion) is replayed once and, every second tick, rendered at
// 1280×720 with the default settings, HUD on, from the chase camera and from the cockpit, each
// camera by its own Renderer (the overdraw budget smooths over the frames it has drawn).
// Every frame is timed alone (render + glFinish), and its blended particle pixels are counted
// by the occlusion query. Each camera has a twin renderer, made alike and fed the same frames (so
// its budget smoothing and resolution choice stay the main one's), which draws every timed frame
// again, before the main one on odd samples and after it on even ones: a frame's time is the
// faster of the two. On a shared machine a single draw now and then waits for the CPU (a single
// draw's p99 varies widely from run to run of the same build); the faster of two draws
// rarely does, and the single draws are still reported (_single_). Every sixth sample each
// camera also renders the same frame without the overdraw budget (its image error against the
// budgeted frame, PSNR) and with soft edges off (what soft edges cost), interleaved with the
// timed frames of the same tick; those ratios pair the main draw alone with the variant's draw.
//   combat_frame_p50_ms_<camera>, combat_frame_p99_ms_<camera>   frame time percentiles (faster of two)
//   combat_frame_p50_ms_single_<camera>, combat_frame_p99_ms_single_<camera>   the main draws alone
//   combat_frame_max_ms_<camera>           the slowest frame past the first ten (a compile the warm-up missed)
//   combat_blended_layers_p99_<camera>     blended particle pixels ÷ screen pixels, 99th percentile
//   combat_budget_psnr_db_<camera>         frames the budget reduced against the same frames without
//                                          it: PSNR of their mean squared error (and _min_db: the worst)
//   combat_budget_active_share_<camera>    share of frames the budget reduced anything
//   combat_estimate_over_measured_<camera> estimated blended layers (after the budget) ÷ measured, median
//   combat_particle_draws_max_<camera>     particle draws (runs) in a frame, the most
//   soft_edge_cost_ratio_combat_<camera>   per-effect soft edges ÷ soft edges off, median of pairs
//   combat_trim_pixel_ratio_<camera>       blended pixels with quads trimmed to their sprites (sprite_trim.h)
//                                          ÷ whole quads, median over the frames neither budget reduced;
//   combat_trim_time_ratio_<camera>        the same frames' time, median of pairs (compared frames), and
//   combat_trim_psnr_min_db_<camera>       their worst PSNR (the picture is meant to stay the same). A
//                                          third renderer per camera draws every frame with whole quads.
// ARCFIRE_GFX_DUMP=DIR saves the slowest frame of each camera (combat_slowest_<camera>.png).
// ARCFIRE_BENCH_SET="key=value key=value" measures under other settings (as --set; bad ones exit 2).
// ARCFIRE_BENCH_FRAMES=FILE.csv writes one line per timed frame (camera, tick, ms, single_ms, stats, and the
// frame split by pass: FrameStats' *_cpu_ms). Each camera also prints that split averaged over
// its slowest 1 % of frames: where a p99 frame's time goes.
// ARCFIRE_BENCH_RECORD=1 records the dogfight anew into tests/bench/combat_view.replay first.
// Then two recordings with many particles, from both cameras, each frame timed the same way
// (main and twin, the faster of two; every sixth sample also without the budget and target):
// the arena's merge (tests/bench/arena_merge.replay) and campaign mission 8's fleet battle
// (tests/bench/fleet_battle.replay). Their frames with more than 10 000 live particles give
//   combat_merge_<camera>_frame_p50_ms / _p99_ms, combat_fleet_<camera>_frame_p50_ms / _p99_ms
//   ..._particles_max (the most in a view), ..._level_min (render.target_frame_ms's lowest
//   level), ..._dropped (particles left out), ..._budget_psnr_db (against no budget, no target)
//   combat_merge_live_particles_peak, combat_fleet_live_particles_peak (the world's, any tick)
// Every renderer that mirrors the main one is told each timed frame's time (the faster of two),
// as the window loop tells its renderer each frame interval, so render.target_frame_ms acts as
// it does for a player. ARCFIRE_BENCH_COMBAT=duel, merge or fleet runs one part alone.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <memory>
#include <string>
#include <vector>

#include "bench_registry.h"
#include "bench_scenes.h"
#include "core/file_writer.h"
#include "core/json.h"
#include "game/app/all_settings.h"
#include "game/app/scene_resources.h"
#include "game/app/script_feeder.h"
#include "game/app/session_recorder.h"
#include "game/render/camera_settings.h"
#include "game/render/hud_rules.h"
#include "game/render/render_view_builder.h"
#include "game/sim/world.h"
#include "gfx/image_compare.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "test_pilot.h"
#include "core/data_root.h"

namespace arc {
namespace {

constexpr int kWidth = 1280, kHeight = 720;
constexpr int kSampleEvery = 2;      // ticks between timed frames
constexpr int kCompareEvery = 6;     // samples between budget-off and soft-off comparisons
const char* const kScript = "/tests/bench/combat_view.replay";
// The arena's merge (tests/bench/arena_merge.replay: the arena flown by the autopilot), timed
// where the fleets meet, and the fleet battle of campaign mission 8 at its peak: their frames
// with more than kMergeParticles live particles are reported.
const char* const kMergeScript = "/tests/bench/arena_merge.replay";
const char* const kFleetScript = "/tests/bench/fleet_battle.replay";
constexpr uint64_t kMergeFirstTick = 0, kFleetFirstTick = 0;
constexpr int kMergeParticles = 10000;

// The test pilot flies the duel on normal until a seed gives a win 15–25 s in (the enemy's
// explosion then plays on screen); the session is recorded to 30 s like a live one.
void record_dogfight(const std::string& root, const std::string& path) {
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    GameOptions o;
    o.root_dir = root;
    o.difficulty_override = true;
    o.difficulty = Difficulty::Normal;
    o.seed_override = true;
    o.seed = seed;
    Game g = Game::load_level(root + "/levels/duel.json", o);
    const std::string tmp = path + ".tmp-recording";
    {
      SessionRecorder rec(tmp, "levels/duel.json", g, "combat_view");
      TestPilot pilot(seed);
      InputFrame in;
      std::vector<Command> keys;
      while (g.world().tick < 1800) {
        keys.clear();
        pilot.act(g.world(), in, keys);
        rec.record(g, in, keys);
        g.step(in, keys);
      }
      rec.finish(g);
    }
    const World& w = g.world();
    const bool good = w.outcome == Outcome::Victory && w.outcome_tick >= 900 && w.outcome_tick <= 1500;
    std::printf("  recording: seed %llu %s at tick %lld\n", static_cast<unsigned long long>(seed),
                good ? "won" : "rejected", static_cast<long long>(w.outcome_tick));
    if (!good) continue;
    std::ifstream in_file(tmp, std::ios::binary);
    std::ostringstream text;
    text << in_file.rdbuf();
    const std::string body = text.str();
    std::remove(tmp.c_str());
    write_file_atomic(path, "# combat_view: the duel on normal flown by the test pilot (seed " + std::to_string(seed) +
                                "), won at tick " + std::to_string(w.outcome_tick) +
                                "; recorded by ARCFIRE_BENCH_RECORD=1 build/arcfire-bench --scene combat_view\n" + body);
    return;
  }
  std::printf("  recording: no seed gave a win 15-25 s in; the script is unchanged\n");
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5))];
}

constexpr int kStages = 8;
const char* const kStageNames[kStages] = {"opaque", "particle prep", "particle target", "particle upload+draws",
                                          "composite", "post", "hud", "finish"};

struct CameraRun {
  const char* name = "";
  CameraMode mode = CameraMode::Chase;
  std::unique_ptr<Renderer> main, twin, no_budget, soft_off;  // twin: the main one again, for the faster of two
  std::unique_ptr<Renderer> untrimmed;  // the main one with whole particle quads (render.sprite_trim off), every frame
  std::vector<double> trim_ratio, trim_pixels;  // trimmed ÷ whole quads: frame time (compared frames), blended pixels
  double trim_psnr_min = std::numeric_limits<double>::infinity();
  std::vector<ModelId> models;
  std::vector<double> ms, single_ms, layers, estimate_ratio, soft_ratio, budget_ratio, psnr;
  std::vector<double> particles, levels;  // particles in the view, and the frame-time target's level, per timed frame
  std::vector<double> live;               // the world's live particles at each timed frame
  long long dropped = 0;                  // particles the budget faded out, over the timed frames
  double mse_sum = 0;  // over the compared frames the budget reduced
  double psnr_min = std::numeric_limits<double>::infinity();
  int compared = 0, active = 0, draws_max = 0, samples = 0;
  double slowest_ms = 0;
  Image slowest, worst_budgeted, worst_unbudgeted;  // the slowest frame; the worst-PSNR pair
  uint64_t slowest_tick = 0, worst_tick = 0;
  // Per timed frame, where its time went (FrameStats' *_cpu_ms, the particle preparation and
  // the draws, the rest to glFinish): the slowest frames' split is reported.
  std::vector<std::array<double, kStages>> stages;
};

// The frame split into the passes FrameStats times on the CPU; "finish" is what is left between
// render()'s return and glFinish's (on llvmpipe: rasterising the post pass and the HUD).
std::array<double, kStages> stage_split(const FrameStats& st, double frame_ms) {
  const double draws = st.particle_cpu_ms - st.particle_prep_ms - st.particle_target_cpu_ms - st.particle_composite_cpu_ms;
  std::array<double, kStages> a = {st.opaque_cpu_ms, st.particle_prep_ms, st.particle_target_cpu_ms, draws,
                                   st.particle_composite_cpu_ms, st.post_cpu_ms, st.hud_cpu_ms, 0.0};
  double sum = 0;
  for (int i = 0; i + 1 < kStages; ++i) sum += a[size_t(i)];
  a[kStages - 1] = std::max(0.0, frame_ms - sum);
  return a;
}

std::unique_ptr<Renderer> make_renderer(const std::string& root, Settings settings, const char* key, const char* value,
                                        const World& world, std::vector<ModelId>* models) {
  RendererDesc desc;
  desc.offscreen = true;
  desc.shader_dir = root + "/shaders";
  auto r = std::make_unique<Renderer>(desc);
  if (key) settings.set(key, value, "combat_view");
  r->apply_settings(settings);
  std::vector<ModelId> ids = load_scene_resources(*r, world, root);
  if (models) *models = ids;
  r->count_particle_fragments(true);
  return r;
}

double timed_render(Renderer& r, const RenderView& v) {
  const double t0 = bench::now_seconds();
  r.render(v, kWidth, kHeight);
  r.finish();
  return (bench::now_seconds() - t0) * 1000.0;
}

// The twin's draw of the frame the main renderer draws (its stats read and dropped, as the main
// one's are, so both do the same work).
double twin_render(CameraRun& c, const RenderView& view) {
  const double ms = timed_render(*c.twin, view);
  (void)c.twin->last_stats();
  return ms;
}

// One sampled tick of one camera: the timed frame (the faster of the main and the twin draw,
// taken in alternating order) and, on comparison ticks, its two variants.
void sample(CameraRun& c, const RenderView& view, bool compare, bool reverse, std::FILE* csv, uint64_t tick) {
  const bool twin_first = c.samples % 2 == 1;
  const double twin_before = twin_first ? twin_render(c, view) : 0.0;
  const double whole_before = twin_first && c.untrimmed ? timed_render(*c.untrimmed, view) : 0.0;
  const double single_ms = timed_render(*c.main, view);
  const FrameStats st = c.main->last_stats();
  const double whole_ms = twin_first || !c.untrimmed ? whole_before : timed_render(*c.untrimmed, view);
  const FrameStats whole = c.untrimmed ? c.untrimmed->last_stats() : st;
  const double ms = std::min(single_ms, twin_first ? twin_before : twin_render(c, view));
  // The frame time the renderers' target follows (render.target_frame_ms): the same for all
  // that mirror the main one, so their levels stay alike.
  for (Renderer* r : {c.main.get(), c.twin.get(), c.untrimmed.get(), c.soft_off.get()})
    if (r) r->report_frame_time(ms);
  c.particles.push_back(st.particles_in);
  c.levels.push_back(st.frame_level);
  c.dropped += st.particles_dropped;
  // Trimming is compared where both drew the same particles at the same resolution: the budget
  // estimates the trimmed area, so over budget the two reduce differently.
  const bool alike = st.particles_reduced == 0 && whole.particles_reduced == 0 && st.particles_half_res == whole.particles_half_res;
  if (c.untrimmed && alike && whole.particle_fragments > 0) c.trim_pixels.push_back(double(st.particle_fragments) / double(whole.particle_fragments));
  c.single_ms.push_back(single_ms);
  const std::array<double, kStages> split = stage_split(st, single_ms);  // the main draw's own stats
  if (csv) {
    std::fprintf(csv, "%s,%llu,%.3f,%.3f,%d,%d,%.3f,%.3f,%lld,%d,%d,%d,%.4f,%.3f,%.3f,%.3f,", c.name, static_cast<unsigned long long>(tick),
                 ms, single_ms, st.particles_in, st.particles_drawn, st.overdraw_estimated_layers, st.overdraw_budgeted_layers,
                 st.particle_fragments, st.particle_draw_calls, st.particles_reduced, st.soft_shaded, st.overdraw_cap,
                 st.particle_prep_ms, st.particle_cpu_ms, st.particles_half_res ? st.composite_share : 0.0);
    for (size_t i = 0; i < split.size(); ++i) std::fprintf(csv, "%s%.3f", i ? "," : "", split[i]);
    std::fprintf(csv, "\n");
  }
  ++c.samples;
  c.ms.push_back(ms);
  c.stages.push_back(split);
  // Layers of the target the particles blend into (render.scale and render.particle_resolution
  // size it), the unit the budget's estimate is in.
  const double measured = double(std::max(0LL, st.particle_fragments)) / std::max(1.0, st.particle_target_pixels);
  c.layers.push_back(measured);
  if (measured > 0.01) c.estimate_ratio.push_back(st.overdraw_budgeted_layers / measured);
  c.draws_max = std::max(c.draws_max, st.particle_draw_calls);
  c.active += st.particles_reduced > 0;
  if (c.samples > 10 && ms > c.slowest_ms) {  // past the first frames (shader variants, buffers)
    c.slowest_ms = ms;
    c.slowest = c.main->read_pixels();
    c.slowest_tick = tick;
  }
  if (!compare) return;
  const Image budgeted = c.main->read_pixels();
  if (c.untrimmed && alike && whole.particles_drawn > 0) {
    c.trim_ratio.push_back(single_ms / whole_ms);
    c.trim_psnr_min = std::min(c.trim_psnr_min, psnr_db(budgeted, c.untrimmed->read_pixels()));
  }
  // The soft-off frame and the budget-off frame in alternating order around each other.
  double off_ms = 0, nb_ms = 0;
  if (reverse && c.soft_off) off_ms = timed_render(*c.soft_off, view);
  nb_ms = timed_render(*c.no_budget, view);
  if (!reverse && c.soft_off) off_ms = timed_render(*c.soft_off, view);
  if (c.soft_off) c.soft_ratio.push_back(single_ms / off_ms);  // one draw against one draw
  c.budget_ratio.push_back(single_ms / nb_ms);
  ++c.compared;
  if (st.particles_reduced == 0) return;  // the same frame: nothing to compare
  Image unbudgeted = c.no_budget->read_pixels();
  const double psnr = psnr_db(budgeted, unbudgeted);
  c.psnr.push_back(psnr);
  if (psnr < c.psnr_min) {
    c.psnr_min = psnr;
    c.worst_tick = tick;
    c.worst_budgeted = budgeted;
    c.worst_unbudgeted = std::move(unbudgeted);
  }
  c.mse_sum += 255.0 * 255.0 / std::pow(10.0, psnr / 10.0);
}

void report(CameraRun& c) {
  const std::string n = c.name;
  const double p50 = percentile(c.ms, 0.5), p99 = percentile(c.ms, 0.99);
  const double single_p50 = percentile(c.single_ms, 0.5), single_p99 = percentile(c.single_ms, 0.99);
  std::printf("  %-7s %d frames: p50 %.2f ms, p99 %.2f ms, max %.2f ms (one draw alone: p50 %.2f, p99 %.2f ms); blended layers p50 %.2f p99 %.2f;"
              " budget active in %d; estimate/measured %.2f; draws ≤ %d; soft x%.3f; budget on/off x%.3f;"
              " PSNR (budget against none) worst %.1f dB, median %.1f dB over %zu reduced of %d compared frames\n",
              c.name, c.samples, p50, p99, percentile(c.ms, 1.0), single_p50, single_p99, percentile(c.layers, 0.5), percentile(c.layers, 0.99),
              c.active, bench::median(c.estimate_ratio), c.draws_max, bench::median(c.soft_ratio),
              bench::median(c.budget_ratio), std::isinf(c.psnr_min) ? 99.0 : c.psnr_min, bench::median(c.psnr), c.psnr.size(), c.compared);
  bench::report_metric("combat_frame_p50_ms_" + n, p50);
  bench::report_metric("combat_frame_p99_ms_" + n, p99);
  bench::report_metric("combat_frame_p50_ms_single_" + n, single_p50);
  bench::report_metric("combat_frame_p99_ms_single_" + n, single_p99);
  bench::report_metric("combat_blended_layers_p99_" + n, percentile(c.layers, 0.99));
  const double psnr_all = c.psnr.empty() ? 99.0 : 10.0 * std::log10(255.0 * 255.0 * double(c.psnr.size()) / c.mse_sum);
  bench::report_metric("combat_budget_psnr_db_" + n, psnr_all);
  bench::report_metric("combat_budget_psnr_min_db_" + n, std::isinf(c.psnr_min) ? 99.0 : c.psnr_min);
  bench::report_metric("combat_budget_active_share_" + n, double(c.active) / std::max(1, c.samples));
  bench::report_metric("combat_estimate_over_measured_" + n, bench::median(c.estimate_ratio));
  bench::report_metric("combat_particle_draws_max_" + n, c.draws_max);
  bench::report_metric("soft_edge_cost_ratio_combat_" + n, bench::median(c.soft_ratio));
  std::printf("  %-7s sprite trimming, frames neither budget reduced: blended pixels x%.3f (median of %zu; most trimmed 1 %% x%.3f),"
              " frame time x%.3f (median of %zu pairs), PSNR against whole quads worst %.1f dB\n", c.name, bench::median(c.trim_pixels),
              c.trim_pixels.size(), percentile(c.trim_pixels, 0.01), bench::median(c.trim_ratio), c.trim_ratio.size(),
              std::isinf(c.trim_psnr_min) ? 99.0 : c.trim_psnr_min);
  bench::report_metric("combat_trim_pixel_ratio_" + n, bench::median(c.trim_pixels));
  bench::report_metric("combat_trim_time_ratio_" + n, bench::median(c.trim_ratio));
  bench::report_metric("combat_trim_psnr_min_db_" + n, std::isinf(c.trim_psnr_min) ? 99.0 : c.trim_psnr_min);
  // Where the slowest 1 % of frames spend their time: each stage's mean over the frames at or
  // above the 99th percentile (past the first frames, which compile shader variants).
  std::array<double, kStages> slow{};
  int slow_n = 0;
  for (size_t i = 10; i < c.ms.size(); ++i) {
    if (c.ms[i] < p99) continue;
    for (int k = 0; k < kStages; ++k) slow[size_t(k)] += c.stages[i][size_t(k)];
    ++slow_n;
  }
  std::printf("  %-7s the %d frames at or above p99, mean ms:", c.name, slow_n);
  for (int k = 0; k < kStages; ++k) std::printf(" %s %.2f%s", kStageNames[k], slow[size_t(k)] / std::max(1, slow_n), k + 1 < kStages ? "," : "\n");
  std::printf("  %-7s slowest frame at tick %llu (%.2f ms); worst budgeted frame at tick %llu\n", c.name,
              static_cast<unsigned long long>(c.slowest_tick), c.slowest_ms, static_cast<unsigned long long>(c.worst_tick));
  // The worst hitch a player meets after the first frames: with the shader cache off (bench_main),
  // a state the renderer's warm-up missed shows here as a compile (tens of ms on llvmpipe).
  bench::report_metric("combat_frame_max_ms_" + n, c.slowest_ms);
  if (const char* dir = std::getenv("ARCFIRE_GFX_DUMP")) {
    if (c.slowest.width > 0) save_image(std::string(dir) + "/combat_slowest_" + n + ".png", c.slowest);
    if (c.worst_budgeted.width > 0) {
      save_image(std::string(dir) + "/combat_budget_worst_" + n + ".png", c.worst_budgeted);
      save_image(std::string(dir) + "/combat_budget_worst_" + n + "_unbudgeted.png", c.worst_unbudgeted);
    }
  }
}

// The frames of a recording where the particles are many: p50/p99 of their time, the most
// particles in one, the lowest level of the frame-time target, and what the budget dropped.
void report_merge(CameraRun& c, const char* prefix) {
  const std::string n = std::string(prefix) + c.name;
  std::vector<double> heavy;
  double most = 0, lowest = 1;
  for (size_t i = 0; i < c.ms.size(); ++i) {
    if (c.live[i] > kMergeParticles) heavy.push_back(c.ms[i]);
    most = std::max(most, c.particles[i]);
    lowest = std::min(lowest, c.levels[i]);
  }
  const double psnr_all = c.psnr.empty() ? 99.0 : 10.0 * std::log10(255.0 * 255.0 * double(c.psnr.size()) / c.mse_sum);
  std::printf("  %-7s %zu of %d frames with more than %d live particles: p50 %.2f ms, p99 %.2f ms (all frames p50 %.2f, p99 %.2f);"
              " most particles in a view %.0f; target level lowest %.2f, median %.2f; budget active in %d, dropped %lld;"
              " PSNR (budget against none) %.1f dB, worst %.1f dB over %zu frames\n",
              c.name, heavy.size(), c.samples, kMergeParticles, percentile(heavy, 0.5), percentile(heavy, 0.99),
              percentile(c.ms, 0.5), percentile(c.ms, 0.99), most, lowest, bench::median(c.levels), c.active, c.dropped,
              psnr_all, std::isinf(c.psnr_min) ? 99.0 : c.psnr_min, c.psnr.size());
  bench::report_metric(n + "_frame_p50_ms", percentile(heavy, 0.5));
  bench::report_metric(n + "_frame_p99_ms", percentile(heavy, 0.99));
  bench::report_metric(n + "_frames_heavy", double(heavy.size()));
  bench::report_metric(n + "_particles_max", most);
  bench::report_metric(n + "_level_min", lowest);
  bench::report_metric(n + "_budget_psnr_db", psnr_all);
  bench::report_metric(n + "_budget_psnr_min_db", std::isinf(c.psnr_min) ? 99.0 : c.psnr_min);
  bench::report_metric(n + "_dropped", double(c.dropped));
}

Settings bench_settings(const replay::Script& script, const std::string& root) {
  Settings settings = script_settings(script, all_settings(), root);
  if (const char* extra = std::getenv("ARCFIRE_BENCH_SET")) {
    std::istringstream words(extra);
    for (std::string kv; words >> kv;) {
      try {
        settings.set_from_text(kv, "ARCFIRE_BENCH_SET");
      } catch (const std::exception& e) {
        std::fprintf(stderr, "arcfire-bench: %s\n", e.what());
        std::exit(2);
      }
    }
  }
  return settings;
}

// Replays one recording, both cameras sampled every second tick from `first` on. `variants`:
// the soft-off and whole-quad renderers as well (the duel's trade-off figures).
void play(const std::string& root, const char* script_path, const char* metric_prefix, bool variants, uint64_t first,
          CameraRun (&cams)[2], std::FILE* csv) {
  const replay::Script script = replay::load_script(root + script_path, all_settings());
  Settings settings = bench_settings(script, root);
  GameOptions base;
  base.root_dir = root;
  Game game = Game::load_level(resolve_script_level(script, root), script_game_options(script, settings, base));
  ScriptFeeder feeder(script);
  HudState hud;
  hud.rules = load_hud_rules(root + "/assets/settings/hud.json");
  cams[0].name = "chase", cams[0].mode = CameraMode::Chase;
  cams[1].name = "cockpit", cams[1].mode = CameraMode::Cockpit;
  for (CameraRun& c : cams) {
    c.main = make_renderer(root, settings, nullptr, nullptr, game.world(), &c.models);
    c.twin = make_renderer(root, settings, nullptr, nullptr, game.world(), nullptr);
    Settings none = settings;  // the reference: no budget, and no target to lower anything
    none.set("render.target_frame_ms", "0", "combat_view");
    c.no_budget = make_renderer(root, none, "render.overdraw_budget", "0", game.world(), nullptr);
    if (!variants) continue;
    c.soft_off = make_renderer(root, settings, "render.soft_edges", "off", game.world(), nullptr);
    c.untrimmed = make_renderer(root, settings, nullptr, nullptr, game.world(), nullptr);
    RenderSettings whole = c.untrimmed->render_settings();
    whole.sprite_trim = false;
    c.untrimmed->set_render_settings(whole);
  }
  const uint64_t end = script.end_tick.value_or(1800);
  RenderView view;
  int samples = 0;
  uint32_t peak = 0;
  uint64_t peak_tick = 0;
  for (uint64_t tick = 0; tick < end; ++tick) {
    feeder.step(game, tick);
    const uint32_t live = uint32_t(game.world().particles->stats().live_particles);
    if (live > peak) peak = live, peak_tick = tick + 1;
    if (tick < first || (tick + 1) % kSampleEvery) continue;
    const bool compare = samples % kCompareEvery == 0;
    for (int k = 0; k < 2; ++k) {
      CameraRun& c = cams[samples % 2 ? 1 - k : k];
      build_render_view(game.world(), c.models, 1.0, CameraSettings{c.mode, 0}, hud, kWidth, kHeight, view);
      sample(c, view, compare, (samples / kCompareEvery) % 2 == 1, csv, tick + 1);
      c.live.push_back(live);
    }
    ++samples;
  }
  std::printf("  %s: %llu ticks, from tick %llu; peak %u live particles at tick %llu\n", script_path,
              static_cast<unsigned long long>(end), static_cast<unsigned long long>(first), peak,
              static_cast<unsigned long long>(peak_tick));
  bench::report_metric(std::string(metric_prefix) + "live_particles_peak", peak);
}

}  // namespace

ARCFIRE_SCENE(combat_view) {
  const std::string root = arc::data_root();
  if (std::getenv("ARCFIRE_BENCH_RECORD")) record_dogfight(root, root + kScript);
  const std::unique_ptr<HeadlessContext> ctx = bench::context_or_skip();
  if (!ctx) return;
  const std::string part = std::getenv("ARCFIRE_BENCH_COMBAT") ? std::getenv("ARCFIRE_BENCH_COMBAT") : "";
  if (!part.empty() && part != "duel" && part != "merge" && part != "fleet") {
    std::fprintf(stderr, "arcfire-bench: ARCFIRE_BENCH_COMBAT='%s' is not a part; use duel, merge or fleet (unset: all)\n", part.c_str());
    std::exit(2);
  }
  std::FILE* csv = nullptr;
  if (const char* f = std::getenv("ARCFIRE_BENCH_FRAMES")) {
    csv = std::fopen(f, "w");
    if (!csv) {
      std::fprintf(stderr, "arcfire-bench: ARCFIRE_BENCH_FRAMES='%s' cannot be written; name a file in a folder that exists\n", f);
      std::exit(2);
    }
    std::fprintf(csv, "camera,tick,ms,single_ms,particles_in,drawn,estimated_layers,budgeted_layers,fragments,draws,reduced,soft,cap,prep_ms,cpu_ms,composite_share,"
                      "opaque_ms,particle_prep_ms,particle_target_ms,particle_draws_ms,composite_ms,post_ms,hud_ms,finish_ms\n");
  }
  std::printf("  %s\n", ctx->description().c_str());
  if (part.empty() || part == "duel") {
    CameraRun cams[2];
    play(root, kScript, "combat_duel_", true, 0, cams, csv);
    for (CameraRun& c : cams) report(c);
  }
  if (part.empty() || part == "merge") {
    CameraRun cams[2];
    play(root, kMergeScript, "combat_merge_", false, kMergeFirstTick, cams, csv);
    for (CameraRun& c : cams) report_merge(c, "combat_merge_");
  }
  if (part.empty() || part == "fleet") {
    CameraRun cams[2];
    play(root, kFleetScript, "combat_fleet_", false, kFleetFirstTick, cams, csv);
    for (CameraRun& c : cams) report_merge(c, "combat_fleet_");
  }
  if (csv) std::fclose(csv);
}

}  // namespace arc
