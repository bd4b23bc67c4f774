// app/frame_time_log.h — `arcfire --frame-times FILE`: what a live session's frames took.
//
// The benchmarks time frames headless; a player meets them in a window, where the swap, the
// window system's copy and the simulation's catch-up ticks are part of every frame. With
// --frame-times the window loop hands each frame's wall-clock interval here with the game tick
// and the renderer's particle figures; at the end the file holds one CSV line per frame and
// the session prints its percentiles on stdout:
//
//   arcfire: 3612 frames in 60.1 s: p50 14.2 ms, p99 23.9 ms, worst 41.0 ms (frame-times.csv)
//
// Each line also holds the renderer's own split of the frame (FrameStats: opaque pass, particle
// pass, post pass, HUD, as their CPU time), and a second summary line gives the median frame's
// split against the rest of it (simulation, menus, the swap and the window system's copy):
//
//   arcfire: median frame 14.2 ms: render 11.0 ms (opaque 4.1, particles 5.2, post 1.5, hud 0.2), the rest 3.2 ms
//
// The first second is left out of the percentiles (shader variants compile, buffers grow).
// Written through the checked writer when the session ends (core/file_writer.h); the path is
// checked before the window opens.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace arc {

struct FrameStats;

class FrameTimeLog {
 public:
  explicit FrameTimeLog(std::string path) : path_(std::move(path)) {}
  bool enabled() const { return !path_.empty(); }
  // One frame: the interval since the previous one (s), at window time `now` (s).
  void frame(double interval_s, double now_s, int64_t tick, const FrameStats& stats);
  // Writes the CSV and prints the summary lines; nothing when disabled or no frame was logged.
  void finish();
  // The CSV as finish() writes it, and the median frame's line (empty under the warm-up).
  std::string csv() const;
  std::string median_split() const;

 private:
  struct Row {
    double now_s, ms;
    int64_t tick;
    int particles_drawn;
    double layers;
    bool half_res;
    double opaque_ms, particles_ms, post_ms, hud_ms;  // FrameStats' *_cpu_ms of the frame drawn
  };
  std::vector<const Row*> past_warmup() const;
  std::string path_;
  std::vector<Row> rows_;
};

}  // namespace arc
