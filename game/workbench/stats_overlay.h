// game/workbench/stats_overlay.h — what an effect costs, drawn as it is edited.
//
// An ImGui window in the view's corner: live particles per cluster of the effect, particles
// drawn and soft-shaded, the pixels the particle draw blended (the renderer's occlusion query),
// the particle pass's time (CPU, and GPU where the driver times it), the share of the particle
// budget in use, and a graph of the last five seconds of frame times.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gfx/renderer.h"

namespace arc {

struct StageFigures {
  std::vector<std::string> cluster_names;
  std::vector<uint32_t> live_per_cluster;  // same order
  uint32_t live = 0;
  uint32_t budget = 0;
  int scene_pixels = 0;  // width × height of the frame
};

class StatsOverlay {
 public:
  void record_frame(double seconds);  // wall time of the last frame
  // Draws the overlay window at the top right of a screen `width` pixels wide.
  void draw(const StageFigures& stage, const FrameStats& frame, int width) const;

 private:
  static constexpr size_t kFrames = 300;  // five seconds at 60 frames per second
  std::array<float, kFrames> frame_ms_{};
  size_t next_ = 0;
  size_t filled_ = 0;
};

}  // namespace arc
