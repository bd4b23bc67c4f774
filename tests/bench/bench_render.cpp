// Renderer headline scenes through EGL at 1280×720, in one run:
//  - the effect gallery level (levels/gallery.json, every effect, some cutting a ship hull and
//    the wall) a few seconds in: soft edges off against each method (soft_edge_cost_ratio, the
//    worst method), burn blending against plain alpha blending (burn_blend_cost_ratio), and
//    the particle pass's blended pixels per second against the raw blended fill rate of the
//    same context (particle_fill_efficiency);
//  - a stress scene where all 4000 particles crowd a wall that fills the screen (the same
//    figures with the suffix _wall_stress): the worst case for soft edges, every particle near
//    opaque geometry;
//  - the arena battle ten seconds in from the player's chase camera (suffix _battle): what
//    soft edges cost in ordinary play.
// Each also times the frame without particles with the nebula evaluated per pixel against the
// baked cube map (render.sky exact against baked: sky_exact_frame_ratio).
// On a hardware rasteriser each also reports particle_fill_efficiency_gpu_timer: the same
// pixels over the particle pass's and the fill reference's GL_TIME_ELAPSED, which leaves out
// the CPU's share of the pass (culling, sorting, upload) that the frame clock includes, and
// soft_edge_cost_ratio_gpu_timer: the worst soft-edge method's particle pass (its depth copy
// and draws) over the pass with soft edges off, by GL_TIME_ELAPSED. On a GPU the frame clock
// is mostly the CPU's preparation, so the two ratios say different things; each soft line
// prints the CPU's preparation and depth-copy submission beside the frame.
// Every configuration is timed one glFinish-bracketed frame at a time, interleaved with all the
// others over many rounds, because the machine is shared and noisy: frame times are the fastest
// frame of each, ratios the median over rounds of the two frames' ratio within a round. The
// soft-edge ratios come from rounds of their own, each method's frames side by side with soft
// edges off (off, method, method, off, mirrored every other round), and a control of off
// against itself the same way (soft_edge_cost_ratio_control, 1 when the timing is fair). Where
// soft particles read the depth from the framebuffer (RenderSettings::depth_fetch), each method
// is also timed so with the depth read from a copy (soft_edge_cost_ratio_copy, the worst).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <memory>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "bench_registry.h"
#include "bench_scenes.h"
#include "core/rng.h"
#include "gfx/gl_features.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "scene_models.h"
#include "core/data_root.h"

namespace arc {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

// A wall of effects: smoke (alpha), fire (half burn), sparks and beams (additive), every soft
// method, all within a few units of a wall that fills the screen, some behind it.
RenderView wall_stress(ModelId wall_model) {
  RenderView v;
  v.camera.position = {0, 2, 18};
  v.camera.fov_y_radians = 0.9;
  v.camera.near_plane = 0.1;
  v.meshes.push_back({wall_model, {0, 0, -6}});
  Rng rng{42, 7, 0};
  const int count = 4000;
  for (int i = 0; i < count; ++i) {
    int effect = i % 8;
    float cx = -12.0f + 3.4f * effect;
    glm::vec3 pos(cx + float(rng.range(i * 8, -1.6, 1.6)), float(rng.range(i * 8 + 1, -3.0, 6.0)),
                  -6.0f + float(rng.range(i * 8 + 2, -1.2, 3.0)));
    const float size = float(rng.range(i * 8 + 3, 0.25, 0.7));
    const float alpha = float(rng.range(i * 8 + 4, 0.3, 0.8));
    glm::vec3 rgb = effect < 3 ? glm::vec3(0.5f, 0.5f, 0.55f) : effect < 6 ? glm::vec3(1.0f, 0.55f, 0.2f) : glm::vec3(0.6f, 0.8f, 1.0f);
    const float burn = effect < 3 ? 0.0f : effect < 6 ? 0.5f : 1.0f;
    ParticleInstance p = scenes::particle(pos - glm::vec3(v.camera.position), size, rgb, alpha, burn, SoftEdge(effect % 5));
    p.sprite = uint16_t(effect < 3 ? 0 : effect < 6 ? 1 : 2);
    p.cluster = uint32_t(effect);
    if (effect >= 6) {
      p.billboard = uint8_t(Billboard::AxisLocked);
      p.axis[1] = float(rng.range(i * 8 + 5, 0.5, 1.5));
      p.axis[0] = float(rng.range(i * 8 + 6, -0.3, 0.3));
      p.size *= 0.3f;
    }
    v.particles.push_back(p);
  }
  return v;
}

// A bad benchmark environment variable: one line naming it and what is allowed, exit 2.
[[noreturn]] void bad_env(const char* name, const std::string& value, const char* allowed) {
  std::fprintf(stderr, "arcfire-bench: %s='%s' is not allowed; use %s\n", name, value.c_str(), allowed);
  std::exit(2);
}

// ARCFIRE_BENCH_ROUNDS=N (1..10000, default 32) interleaved rounds; ARCFIRE_BENCH_FILTER=
// nearest|linear|mipmap measures with another sprite filter (default mipmap, the high
// preset's), to tell the filtering's share of the cost from the rest. Read before any work.
struct BenchEnv {
  int rounds = 32;
  RenderSettings::Filter filter = RenderSettings::Filter::Mipmap;
};

BenchEnv read_env() {
  BenchEnv e;
  e.rounds = bench::rounds_from_env(e.rounds);
  if (const char* v = std::getenv("ARCFIRE_BENCH_FILTER")) {
    const std::string f = v;
    if (f == "nearest") e.filter = RenderSettings::Filter::Nearest;
    else if (f == "linear") e.filter = RenderSettings::Filter::Linear;
    else if (f == "mipmap_nearest") e.filter = RenderSettings::Filter::MipmapNearest;
    else if (f != "mipmap") bad_env("ARCFIRE_BENCH_FILTER", f, "nearest, linear, mipmap_nearest or mipmap");
  }
  return e;
}

struct Figures {
  double hard_ms = 0, alpha_ms = 0, empty_ms = 0, effect_ms = 0, big_ms = 0, fill_ms = 0;  // fastest frames
  double exact_sky_ms = 0;
  double particle_gpu_ms = -1, fill_gpu_ms = -1;  // GL_TIME_ELAPSED, fastest of the timer rounds
  double prep_ms = 0;                             // FrameStats::particle_prep_ms, fastest
  double worst_soft_ratio = 0, burn_ratio = 0, sky_ratio = 0;  // medians of same-round ratios
  double soft_control_ratio = 0;  // soft edges off against itself, side by side (worst_soft_ratio's method)
  double worst_soft_copy_ratio = 0;  // the same as worst_soft_ratio with the depth read from a copy (0: not measured)
  double worst_soft_gpu_ratio = 0;  // the worst method's particle pass ÷ soft edges off, GL_TIME_ELAPSED (0: untimed)
  long long fragments = 0;  // blended by the particle draw, soft edges per effect
};

Figures measure(Renderer& r, const RenderView& view, const BenchEnv& env) {
  RenderView no_particles = view;
  no_particles.particles.clear();
  RenderView alpha_only = view;
  for (auto& p : alpha_only.particles) p.burn = 0.0f;
  // The same fill through the particle pipeline (shader, sprite array, blend): full-screen
  // particles, which separates the shader's cost from the cost of many small quads.
  const int quads = 40;
  RenderView big = no_particles;
  for (int i = 0; i < quads; ++i) {
    ParticleInstance p{};
    glm::dvec3 ahead = view.camera.orientation * glm::dvec3(0, 0, -1);
    p.pos[0] = float(ahead.x);
    p.pos[1] = float(ahead.y);
    p.pos[2] = float(ahead.z);
    p.size = 2.0f;
    p.color[0] = p.color[1] = p.color[2] = 0.01f;
    p.color[3] = 0.05f;
    big.particles.push_back(p);
  }
  RenderSettings base;
  base.filter = env.filter;
  auto with_soft = [&](int m) {
    RenderSettings s = base;
    s.soft_override = m;
    return s;
  };
  RenderSettings big_settings = with_soft(0);
  big_settings.size_clamp = 4.0f;
  struct Config {
    const char* name;
    const RenderView* view;
    RenderSettings settings;
    bool fill_reference = false;  // time draw_fill_reference(quads) after an empty frame
    std::vector<double> ms;       // one frame per round
    double best_ms = 1e30;
    double prep_ms = 1e30;        // FrameStats::particle_prep_ms (CPU, no GL), fastest
    double target_ms = 1e30;      // FrameStats::particle_target_cpu_ms (the depth copy's submission), fastest
  };
  // Ratios pair frames of the same round, taken a few frames apart, and keep the median: load
  // that comes and goes then falls on both sides of a ratio alike.
  const char* names[] = {"off", "linear", "contrast", "average_density", "density_extent"};
  std::vector<Config> configs;
  auto add = [&](const char* name, const RenderView* v, const RenderSettings& settings, bool fill = false) {
    configs.push_back(Config{name, v, settings, fill, {}, 1e30});
    return configs.size() - 1;
  };
  add(names[0], &view, with_soft(0));
  const size_t kAlpha = add("burn forced 0", &alpha_only, with_soft(0));
  const size_t kSoft = configs.size();  // linear, contrast, average density, density extent
  for (int m = 1; m < 5; ++m) add(names[m], &view, with_soft(m));
  // Where soft particles read the depth from the framebuffer (RenderSettings::depth_fetch), each
  // method again with the depth read from a copy: what the fetch saves, in the same rounds.
  const bool fetch = has_depth_fetch();
  const size_t kCopy = configs.size();
  const int methods = fetch ? 9 : 5;
  for (int m = 1; fetch && m < 5; ++m) {
    RenderSettings s = with_soft(m);
    s.depth_fetch = false;
    add(names[m], &view, s);
  }
  // The configuration of soft-edge method names[m] (0: off; 5..8: methods 1..4 with the copy).
  auto soft_config = [&](int m) {
    return m == 0 ? size_t(0) : m < 5 ? kSoft + size_t(m - 1) : kCopy + size_t(m - 5);
  };
  const size_t kEmpty = add("no particles", &no_particles, base);
  RenderSettings exact_sky = base;
  exact_sky.sky_exact = true;
  const size_t kExactSky = add("no particles, exact sky", &no_particles, exact_sky);
  const size_t kEffect = add("per-effect soft", &view, base);
  const size_t kBig = add("full-screen particles", &big, big_settings);
  const size_t kFill = add("fill reference", &no_particles, base, true);

  const int rounds = env.rounds;
  for (Config& c : configs) {  // warm-up: shader variants compiled, buffers sized
    r.set_render_settings(c.settings);
    r.render(*c.view, kWidth, kHeight);
  }
  r.finish();
  for (int round = 0; round < rounds; ++round)
    for (size_t k = 0; k < configs.size(); ++k) {
      // Odd rounds run the list backwards, so no configuration always comes first or last.
      Config& c = configs[round % 2 ? configs.size() - 1 - k : k];
      r.set_render_settings(c.settings);
      double t0 = bench::now_seconds();
      r.render(*c.view, kWidth, kHeight);
      if (c.fill_reference) {
        r.finish();
        t0 = bench::now_seconds();
        r.draw_fill_reference(quads);
      }
      r.finish();
      c.ms.push_back((bench::now_seconds() - t0) * 1000.0);
      c.best_ms = std::min(c.best_ms, c.ms.back());
      c.prep_ms = std::min(c.prep_ms, r.last_stats().particle_prep_ms);
      c.target_ms = std::min(c.target_ms, r.last_stats().particle_target_cpu_ms);
    }
  // Soft-edge ratios from frames side by side: for each method, every round, soft edges off,
  // the method, the method again and off again (the order mirrored every other round), the
  // ratio of the method's two frames to off's two. In the interleaved rounds above a ratio's two
  // frames lie several configurations apart, and a configuration's place in that list alone
  // moves a ratio by as much as the 10 % it is meant to tell. Method 0 is the control: off
  // against itself, reported as soft_edge_cost_ratio_control (docs/performance.md gives its
  // spread). Twice as many rounds as the list above, which narrows the control's spread.
  std::vector<double> side_by_side[9];
  const int side_rounds = 2 * rounds;
  auto frame_ms = [&](size_t k) {
    r.set_render_settings(configs[k].settings);
    const double t0 = bench::now_seconds();
    r.render(*configs[k].view, kWidth, kHeight);
    r.finish();
    return (bench::now_seconds() - t0) * 1000.0;
  };
  for (int round = 0; round < side_rounds; ++round)
    for (int m = 0; m < methods; ++m) {
      const size_t off = 0, soft = soft_config(m);
      const bool soft_first = (round + m) % 2 == 1;
      const double t0 = frame_ms(soft_first ? soft : off), t1 = frame_ms(soft_first ? off : soft);
      const double t2 = frame_ms(soft_first ? off : soft), t3 = frame_ms(soft_first ? soft : off);
      side_by_side[m].push_back(soft_first ? (t0 + t3) / (t1 + t2) : (t1 + t2) / (t0 + t3));
    }
  auto paired = [&](size_t a, size_t b) {
    std::vector<double> q;
    for (int i = 0; i < rounds; ++i) q.push_back(configs[a].ms[size_t(i)] / configs[b].ms[size_t(i)]);
    return bench::median(q);
  };

  Figures f;
  for (int m = 0; m < methods; ++m) {
    const size_t i = soft_config(m);
    r.set_render_settings(configs[i].settings);
    r.render(view, kWidth, kHeight);
    const double ratio = bench::median(side_by_side[m]);
    const FrameStats& st = r.last_stats();
    std::printf("  soft %-16s %8.2f ms/frame, x%.3f, %d of %d particles read the depth %s; CPU: preparation %.2f ms,"
                " depth copy %.2f ms\n",
                configs[i].name, configs[i].best_ms, ratio, st.soft_shaded, st.particles_drawn,
                st.depth_fetched ? "from the framebuffer" : "from a copy", configs[i].prep_ms, configs[i].target_ms);
    if (m == 0) f.soft_control_ratio = ratio;
    else if (m < 5) f.worst_soft_ratio = std::max(f.worst_soft_ratio, ratio);
    else f.worst_soft_copy_ratio = std::max(f.worst_soft_copy_ratio, ratio);
  }
  f.burn_ratio = paired(0, kAlpha);
  f.sky_ratio = paired(kExactSky, kEmpty);
  f.exact_sky_ms = configs[kExactSky].best_ms;
  f.hard_ms = configs[0].best_ms;
  f.alpha_ms = configs[kAlpha].best_ms;
  f.empty_ms = configs[kEmpty].best_ms;
  f.effect_ms = configs[kEffect].best_ms;
  f.big_ms = configs[kBig].best_ms;
  f.fill_ms = configs[kFill].best_ms;
  r.set_render_settings(base);
  r.count_particle_fragments(true);
  r.render(view, kWidth, kHeight);
  f.fragments = r.last_stats().particle_fragments;
  r.count_particle_fragments(false);
  // The pass's own CPU work (culling, soft-edge flags, sorting; no GL), fastest of a few frames.
  for (int i = 0; i < 8; ++i) {
    r.render(view, kWidth, kHeight);
    r.finish();
    f.prep_ms = i == 0 ? r.last_stats().particle_prep_ms : std::min(f.prep_ms, r.last_stats().particle_prep_ms);
  }
  // The same pair timed by GL_TIME_ELAPSED in rounds of their own (reading a query back
  // stalls mid-frame, which the rounds above must not pay): on a GPU the pass's own time,
  // without the CPU's culling, sorting and upload. Not on Mesa's software rasterisers, whose
  // timer does not cover rasterisation (it reports a small fraction of the clock's time).
  const std::string gl = r.gl_version();
  const bool software = bench::software_rasteriser(gl);
  r.time_gpu_passes(!software);
  // Each soft-edge method's particle pass (the depth copy and the draws) is timed the same way.
  double soft_gpu_ms[5] = {1e30, 1e30, 1e30, 1e30, 1e30};
  for (int round = 0; !software && round < std::max(4, rounds / 4); ++round) {
    r.render(view, kWidth, kHeight);
    const double p = r.last_stats().particle_pass_gpu_ms;
    const double q = r.draw_fill_reference(quads);
    r.finish();
    if (p > 0) f.particle_gpu_ms = f.particle_gpu_ms < 0 ? p : std::min(f.particle_gpu_ms, p);
    if (q > 0) f.fill_gpu_ms = f.fill_gpu_ms < 0 ? q : std::min(f.fill_gpu_ms, q);
    for (int m = 0; m < 5; ++m) {
      r.set_render_settings(configs[soft_config(m)].settings);
      r.render(view, kWidth, kHeight);
      r.finish();
      const double g = r.last_stats().particle_pass_gpu_ms;
      if (g > 0) soft_gpu_ms[m] = std::min(soft_gpu_ms[m], g);
    }
    r.set_render_settings(base);
  }
  r.time_gpu_passes(false);
  if (soft_gpu_ms[0] < 1e29) {
    std::printf("  soft edges by GL_TIME_ELAPSED (particle pass with its depth copy):");
    for (int m = 0; m < 5; ++m) {
      std::printf(" %s %.3f ms%s", names[m], soft_gpu_ms[m], m < 4 ? "," : "\n");
      if (m > 0 && soft_gpu_ms[m] < 1e29) f.worst_soft_gpu_ratio = std::max(f.worst_soft_gpu_ratio, soft_gpu_ms[m] / soft_gpu_ms[0]);
    }
  }
  std::printf("  burn blend %.2f ms, burn forced 0 %.2f ms, no particles %.2f ms, per-effect soft %.2f ms"
              " (fastest of %d interleaved rounds)\n",
              f.hard_ms, f.alpha_ms, f.empty_ms, f.effect_ms, rounds);
  std::printf("  no particles: nebula baked %.2f ms, exact %.2f ms, x%.3f\n", f.empty_ms, f.exact_sky_ms, f.sky_ratio);
  double raw_px_per_s = double(quads) * kWidth * kHeight / (f.fill_ms * 1e-3);
  double particle_s = std::max(1e-9, (f.effect_ms - f.empty_ms) * 1e-3);
  double big_px_per_s = double(quads) * kWidth * kHeight / std::max(1e-9, (f.big_ms - f.empty_ms) * 1e-3);
  std::printf("  particle pass %.2f ms for %lld blended pixels: %.3g px/s; full-screen particles %.3g px/s;"
              " raw blended fill %.3g px/s\n",
              particle_s * 1e3, f.fragments, double(f.fragments) / particle_s, big_px_per_s, raw_px_per_s);
  std::printf("  of it preparation on the CPU (culling, soft-edge flags, sorting): %.2f ms\n", f.prep_ms);
  if (f.particle_gpu_ms > 0 && f.fill_gpu_ms > 0)
    std::printf("  by GL_TIME_ELAPSED: particle pass %.2f ms, fill reference %.2f ms\n", f.particle_gpu_ms, f.fill_gpu_ms);
  return f;
}

void report(const Figures& f, const std::string& suffix) {
  const double quads_px = 40.0 * kWidth * kHeight;
  double raw_px_per_s = quads_px / (f.fill_ms * 1e-3);
  double particle_s = std::max(1e-9, (f.effect_ms - f.empty_ms) * 1e-3);
  double big_s = std::max(1e-9, (f.big_ms - f.empty_ms) * 1e-3);
  bench::report_metric("soft_edge_cost_ratio" + suffix, f.worst_soft_ratio);
  bench::report_metric("soft_edge_cost_ratio_control" + suffix, f.soft_control_ratio);
  if (f.worst_soft_copy_ratio > 0) bench::report_metric("soft_edge_cost_ratio_copy" + suffix, f.worst_soft_copy_ratio);
  bench::report_metric("burn_blend_cost_ratio" + suffix, f.burn_ratio);
  bench::report_metric("particle_fill_efficiency" + suffix, double(f.fragments) / particle_s / raw_px_per_s);
  bench::report_metric("particle_shader_fill_ratio" + suffix, quads_px / big_s / raw_px_per_s);
  bench::report_metric("render_gallery_frame_ms" + suffix, f.effect_ms);
  bench::report_metric("sky_exact_frame_ratio" + suffix, f.sky_ratio);
  if (f.worst_soft_gpu_ratio > 0) bench::report_metric("soft_edge_cost_ratio_gpu_timer" + suffix, f.worst_soft_gpu_ratio);
  if (f.particle_gpu_ms > 0 && f.fill_gpu_ms > 0)
    bench::report_metric("particle_fill_efficiency_gpu_timer" + suffix,
                         double(f.fragments) / (f.particle_gpu_ms * 1e-3) / (quads_px / (f.fill_gpu_ms * 1e-3)));
}

}  // namespace

ARCFIRE_SCENE(render_particle_gallery) {
  const BenchEnv env = read_env();
  const std::unique_ptr<HeadlessContext> ctx = bench::context_or_skip();
  if (!ctx) return;
  const std::string root = arc::data_root();
  RendererDesc desc;
  desc.offscreen = true;
  desc.shader_dir = root + "/shaders";
  Renderer r(desc);
  std::printf("context: %s\n", ctx->description().c_str());

  const RenderView gallery = bench::level_view(r, "levels/gallery.json", 240, kWidth, kHeight);
  if (const char* dir = std::getenv("ARCFIRE_GFX_DUMP")) {
    r.render(gallery, kWidth, kHeight);
    save_image(std::string(dir) + "/bench_gallery.png", r.read_pixels());
  }
  std::printf(" gallery level (levels/gallery.json at tick 240, %zu particles, %zu meshes):\n", gallery.particles.size(),
              gallery.meshes.size());
  report(measure(r, gallery, env), "");

  RenderView stress = wall_stress(r.add_model(scenes::wall_model(60, 30, {0.45f, 0.47f, 0.5f, 1}, glm::vec3(0.02f))));
  if (const char* dir = std::getenv("ARCFIRE_GFX_DUMP")) {
    r.render(stress, kWidth, kHeight);
    save_image(std::string(dir) + "/bench_wall_stress.png", r.read_pixels());
  }
  std::printf(" wall stress (%zu particles crowding a wall that fills the screen):\n", stress.particles.size());
  report(measure(r, stress, env), "_wall_stress");

  // Ordinary play: the arena battle ten seconds in, from the player's chase camera. Most
  // particles are out in space; soft edges cost only where one meets a hull.
  Renderer battle_renderer(desc);
  const RenderView arena = bench::level_view(battle_renderer, "levels/arena.json", 600, kWidth, kHeight);
  if (const char* dir = std::getenv("ARCFIRE_GFX_DUMP")) {
    battle_renderer.render(arena, kWidth, kHeight);
    save_image(std::string(dir) + "/bench_battle.png", battle_renderer.read_pixels());
  }
  std::printf(" arena battle (levels/arena.json at tick 600, chase camera, %zu particles, %zu meshes):\n",
              arena.particles.size(), arena.meshes.size());
  report(measure(battle_renderer, arena, env), "_battle");
}

}  // namespace arc
