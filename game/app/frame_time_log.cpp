// app/frame_time_log.cpp — per-frame rows, percentiles and the CSV of --frame-times.
#include "game/app/frame_time_log.h"

#include <algorithm>
#include <cstdio>

#include "core/file_writer.h"
#include "gfx/renderer.h"

namespace arc {
namespace {

constexpr double kWarmupSeconds = 1.0;

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5))];
}

}  // namespace

void FrameTimeLog::frame(double interval_s, double now_s, int64_t tick, const FrameStats& stats) {
  if (!enabled()) return;
  rows_.push_back({now_s, interval_s * 1000.0, tick, stats.particles_drawn, stats.overdraw_budgeted_layers,
                   stats.particles_half_res, stats.opaque_cpu_ms, stats.particle_cpu_ms, stats.post_cpu_ms,
                   stats.hud_cpu_ms});
}

std::vector<const FrameTimeLog::Row*> FrameTimeLog::past_warmup() const {
  std::vector<const Row*> out;
  for (const Row& r : rows_)
    if (r.now_s - rows_.front().now_s >= kWarmupSeconds) out.push_back(&r);
  return out;
}

std::string FrameTimeLog::csv() const {
  std::string csv = "time_s,frame_ms,tick,particles_drawn,budgeted_layers,half_res,render_opaque_ms,render_particles_ms,"
                    "render_post_ms,render_hud_ms\n";
  char line[224];
  for (const Row& r : rows_) {
    std::snprintf(line, sizeof line, "%.4f,%.3f,%lld,%d,%.3f,%d,%.3f,%.3f,%.3f,%.3f\n", r.now_s, r.ms,
                  static_cast<long long>(r.tick), r.particles_drawn, r.layers, int(r.half_res), r.opaque_ms,
                  r.particles_ms, r.post_ms, r.hud_ms);
    csv += line;
  }
  return csv;
}

// The frame at the median frame time (past the warm-up), split as the renderer timed it.
std::string FrameTimeLog::median_split() const {
  std::vector<const Row*> rows = past_warmup();
  if (rows.empty()) return {};
  std::sort(rows.begin(), rows.end(), [](const Row* a, const Row* b) { return a->ms < b->ms; });
  const Row& m = *rows[(rows.size() - 1) / 2];
  const double render = m.opaque_ms + m.particles_ms + m.post_ms + m.hud_ms;
  char line[224];
  std::snprintf(line, sizeof line,
                "arcfire: median frame %.1f ms: render %.1f ms (opaque %.1f, particles %.1f, post %.1f, hud %.1f), the rest %.1f ms",
                m.ms, render, m.opaque_ms, m.particles_ms, m.post_ms, m.hud_ms, std::max(0.0, m.ms - render));
  return line;
}

void FrameTimeLog::finish() {
  if (!enabled() || rows_.empty()) return;
  write_file_checked(path_, csv());
  std::vector<double> ms;
  for (const Row* r : past_warmup()) ms.push_back(r->ms);
  const double span = rows_.back().now_s - rows_.front().now_s;
  if (ms.empty()) {
    std::printf("arcfire: %zu frames in %.1f s, under the %.0f s warm-up: no percentiles (%s)\n", rows_.size(), span,
                kWarmupSeconds, path_.c_str());
    return;
  }
  std::printf("arcfire: %zu frames in %.1f s: p50 %.1f ms, p99 %.1f ms, worst %.1f ms (%s)\n", rows_.size(), span,
              percentile(ms, 0.5), percentile(ms, 0.99), percentile(ms, 1.0), path_.c_str());
  std::printf("%s\n", median_split().c_str());
}

}  // namespace arc
