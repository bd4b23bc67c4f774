// particle_scale: how many particles the renderer draws at 1920x1080 within 4 ms. The arena
// battle ten seconds in (its particles, seen from the chase camera) is scaled up by copies of
// its particles, each copy moved by a keyed random offset of up to ±150 m across and ±100 m
// in depth, so the crowd keeps the battle's mix of sizes, blends and soft edges. For doubling
// counts from 4096 to 4 194 304 the frame is timed (fastest of a few, glFinish-bracketed)
// against the same frame without particles; the count at which the particles' share crosses
// 4 ms is interpolated between the two counts around it (in log count).
//   particles_within_4ms_1080p   the count (0 when even 4096 take longer)
// On a hardware rasteriser the particle pass is also timed by GL_TIME_ELAPSED (the depth copy
// and the draws, without the CPU's culling, sorting, budget and upload), and the same
// crossing is reported for it:
//   particles_within_4ms_1080p_gpu_timer
// On a software rasteriser the steps stop once a frame takes more than a second.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench_registry.h"
#include "bench_scenes.h"
#include "core/rng.h"
#include "game/app/all_settings.h"
#include "gfx/image_compare.h"
#include "gfx/renderer.h"
#include "platform/platform.h"

namespace arc {
namespace {

constexpr int kW = 1920, kH = 1080;

struct Timed {
  double ms = 1e30;        // the whole frame, glFinish-bracketed
  double gpu_ms = 1e30;    // the particle pass by GL_TIME_ELAPSED (time_gpu_passes); 1e30 if untimed
};

Timed fastest_frame(Renderer& r, const RenderView& v, int tries) {
  Timed best;
  for (int i = 0; i < tries; ++i) {
    r.restart_smoothing();
    const double t0 = bench::now_seconds();
    r.render(v, kW, kH);
    r.finish();
    best.ms = std::min(best.ms, (bench::now_seconds() - t0) * 1000.0);
    const double gpu = r.last_stats().particle_pass_gpu_ms;
    if (gpu >= 0) best.gpu_ms = std::min(best.gpu_ms, gpu);
  }
  return best;
}

// The count at which `ms` crosses 4 ms, interpolated in log count between the last count under
// it and the first over it; `counts` and `ms` are in doubling order.
double crossing(const std::vector<double>& counts, const std::vector<double>& ms) {
  double within = 0;
  for (size_t i = 0; i < counts.size(); ++i) {
    if (ms[i] > 4.0) {
      if (i > 0)
        within = std::exp(std::log(counts[i - 1]) + (std::log(counts[i]) - std::log(counts[i - 1])) *
                                                        (4.0 - ms[i - 1]) / std::max(ms[i] - ms[i - 1], 1e-9));
      return within;
    }
    within = counts[i];
  }
  return within;
}

RenderView scaled(const RenderView& battle, size_t count) {
  RenderView v = battle;
  v.particles.clear();
  v.particles.reserve(count);
  const size_t n = battle.particles.size();
  Rng rng{7, 3, 0};
  for (size_t i = 0; i < count; ++i) {
    ParticleInstance p = battle.particles[i % n];
    const uint64_t copy = i / n;
    if (copy > 0) {
      p.pos[0] += float(rng.range(copy * 3, -150.0, 150.0));
      p.pos[1] += float(rng.range(copy * 3 + 1, -150.0, 150.0));
      p.pos[2] += float(rng.range(copy * 3 + 2, -100.0, 100.0));
    }
    v.particles.push_back(p);
  }
  return v;
}

}  // namespace

ARCFIRE_SCENE(particle_scale) {
  const std::unique_ptr<HeadlessContext> ctx = bench::context_or_skip();
  if (!ctx) return;
  RendererDesc desc;
  desc.offscreen = true;
  Renderer r(desc);
  const RenderView battle = bench::level_view(r, "levels/arena.json", 600, kW, kH);
  r.apply_settings(all_settings());
  RenderSettings rs = r.render_settings();
  rs.overdraw_budget = 0.0f;  // every particle drawn: this measures the renderer, not the budget
  r.set_render_settings(rs);
  RenderView empty = battle;
  empty.particles.clear();
  const std::string gl = ctx->description();
  const bool software = bench::software_rasteriser(gl);
  r.time_gpu_passes(!software);
  fastest_frame(r, empty, 2);  // warm-up
  const double base = fastest_frame(r, empty, 5).ms;
  std::printf("  %s; arena battle at tick 600: %zu particles; frame without particles %.2f ms\n",
              gl.c_str(), battle.particles.size(), base);
  std::vector<double> counts, frame_ms, gpu_ms;
  for (size_t count = 4096; count <= (size_t(1) << 22); count *= 2) {
    const RenderView v = scaled(battle, count);
    fastest_frame(r, v, 1);
    const Timed t = fastest_frame(r, v, 3);
    const double ms = t.ms - base;
    counts.push_back(double(count));
    frame_ms.push_back(ms);
    gpu_ms.push_back(t.gpu_ms);
    std::printf("  %8zu particles: %.2f ms for the particles (%d drawn, %d draws)", count, ms,
                r.last_stats().particles_drawn, r.last_stats().particle_draw_calls);
    if (t.gpu_ms < 1e29) std::printf(", particle pass %.2f ms by GL_TIME_ELAPSED", t.gpu_ms);
    std::printf("\n");
    if (ms > 4.0 && (software || t.gpu_ms > 4.0)) break;
    if (ms + base > 1000.0) break;
  }
  const double within = crossing(counts, frame_ms);
  bench::report_metric("particles_within_4ms_1080p", within);
  if (!software) bench::report_metric("particles_within_4ms_1080p_gpu_timer", crossing(counts, gpu_ms));
}

}  // namespace arc

namespace arc {

// particle_prep: the particle pass's CPU preparation alone (FrameStats::particle_prep_ms:
// culling, soft-edge flags, the overdraw estimate, sorting, runs; no GL), which is most of a
// frame on a GPU. The gallery at tick 240 with per-effect soft edges and with them off, and
// the arena battle at tick 600 scaled to 65 536 particles as particle_scale scales it; each the
// fastest of 15 frames per path, the two paths interleaved frame by frame, in ns per particle
// the per-particle path keeps (the per-cluster path keeps at least those):
//   particle_prep_ns_gallery, particle_prep_ns_gallery_soft_off, particle_prep_ns_scaled_65536
//     render.particle_prep = cluster, the path a hardware GPU takes by default
//   the same names ending _per_particle: render.particle_prep = particle (a software rasteriser's)
// Then the per-cluster sort's depth-key width (render.particle_sort_bits 11 / 22 / 32) on the
// gallery and the scaled battle, interleaved the same way: the same names ending _sort_bits_N,
// and particle_sort_psnr_db_<scene>_N, the picture against the exact 32-bit order (99: identical).
ARCFIRE_SCENE(particle_prep) {
  const std::unique_ptr<HeadlessContext> ctx = bench::context_or_skip();
  if (!ctx) return;
  RendererDesc desc;
  desc.offscreen = true;
  Renderer r(desc);
  const RenderView gallery = bench::level_view(r, "levels/gallery.json", 240, kW, kH);
  const RenderView battle = bench::level_view(r, "levels/arena.json", 600, kW, kH);
  const RenderView crowd = scaled(battle, 65536);
  r.apply_settings(all_settings());
  const RenderSettings defaults = r.render_settings();
  struct Case {
    const char* metric;
    const RenderView* view;
    int soft_override;
  };
  const Case cases[] = {{"particle_prep_ns_gallery", &gallery, -1},
                        {"particle_prep_ns_gallery_soft_off", &gallery, 0},
                        {"particle_prep_ns_scaled_65536", &crowd, -1}};
  using Prep = RenderSettings::ParticlePrep;
  int kept_per_particle[3] = {1, 1, 1};
  for (const Case& c : cases) {
    double best[2] = {1e30, 1e30};
    int kept[2] = {0, 0};
    for (int i = 0; i < 30; ++i) {
      const int path = i % 2;  // 0 per particle, 1 per cluster
      RenderSettings rs = defaults;
      rs.soft_override = c.soft_override;
      rs.particle_prep = path == 0 ? Prep::PerParticle : Prep::PerCluster;
      r.set_render_settings(rs);
      r.restart_smoothing();
      r.render(*c.view, kW, kH);
      r.finish();
      best[path] = std::min(best[path], r.last_stats().particle_prep_ms);
      kept[path] = r.last_stats().particles_drawn;
    }
    std::printf("  %-36s per particle %7.3f ms for %d kept, per cluster %7.3f ms for %d kept, of %zu (ratio %.1f)\n",
                c.metric, best[0], kept[0], best[1], kept[1], c.view->particles.size(), best[0] / best[1]);
    bench::report_metric(c.metric, best[1] * 1e6 / std::max(kept[0], 1));
    bench::report_metric(std::string(c.metric) + "_per_particle", best[0] * 1e6 / std::max(kept[0], 1));
    kept_per_particle[&c - cases] = std::max(kept[0], 1);
  }
  const int widths[3] = {11, 22, 32};
  for (int ci : {0, 2}) {
    const Case& c = cases[ci];
    double best[3] = {1e30, 1e30, 1e30};
    Image img[3];
    for (int i = 0; i < 45; ++i) {
      const int w = i % 3;
      RenderSettings rs = defaults;
      rs.particle_prep = Prep::PerCluster;
      rs.particle_sort_bits = widths[w];
      r.set_render_settings(rs);
      r.restart_smoothing();
      r.render(*c.view, kW, kH);
      r.finish();
      best[w] = std::min(best[w], r.last_stats().particle_prep_ms);
      if (i < 3) img[w] = r.read_pixels();
    }
    const std::string scene = ci == 0 ? "gallery" : "scaled_65536";
    for (int w = 0; w < 3; ++w) {
      const std::string bits = std::to_string(widths[w]);
      bench::report_metric(std::string(c.metric) + "_sort_bits_" + bits, best[w] * 1e6 / kept_per_particle[ci]);
      const double psnr = psnr_db(img[2], img[w]);
      bench::report_metric("particle_sort_psnr_db_" + scene + "_" + bits, std::isinf(psnr) ? 99.0 : psnr);
    }
  }
}

}  // namespace arc
