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
  // Writes the CSV and prints the summary line; nothing when disabled or no frame was logged.
  void finish();

 private:
  struct Row {
    double now_s, ms;
    int64_t tick;
    int particles_drawn;
    double layers;
    bool half_res;
  };
  std::string path_;
  std::vector<Row> rows_;
};

}  // namespace arc
