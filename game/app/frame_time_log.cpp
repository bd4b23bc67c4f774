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
                   stats.particles_half_res});
}

void FrameTimeLog::finish() {
  if (!enabled() || rows_.empty()) return;
  std::string csv = "time_s,frame_ms,tick,particles_drawn,budgeted_layers,half_res\n";
  std::vector<double> ms;
  char line[160];
  for (const Row& r : rows_) {
    std::snprintf(line, sizeof line, "%.4f,%.3f,%lld,%d,%.3f,%d\n", r.now_s, r.ms, static_cast<long long>(r.tick),
                  r.particles_drawn, r.layers, int(r.half_res));
    csv += line;
    if (r.now_s - rows_.front().now_s >= kWarmupSeconds) ms.push_back(r.ms);
  }
  write_file_checked(path_, csv);
  const double span = rows_.back().now_s - rows_.front().now_s;
  if (ms.empty()) {
    std::printf("arcfire: %zu frames in %.1f s, under the %.0f s warm-up: no percentiles (%s)\n", rows_.size(), span,
                kWarmupSeconds, path_.c_str());
    return;
  }
  std::printf("arcfire: %zu frames in %.1f s: p50 %.1f ms, p99 %.1f ms, worst %.1f ms (%s)\n", rows_.size(), span,
              percentile(ms, 0.5), percentile(ms, 0.99), percentile(ms, 1.0), path_.c_str());
}

}  // namespace arc
