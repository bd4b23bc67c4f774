#include "core/clock.h"

#include <algorithm>
#include <cmath>

namespace arc {

FixedStepClock::FixedStepClock(int tick_rate_hz, double max_frame_seconds)
    : rate_(std::max(1, tick_rate_hz)), dt_(1.0 / rate_), max_frame_(max_frame_seconds) {}

int FixedStepClock::advance(double frame_seconds) {
  if (paused_) return 0;
  if (std::isnan(frame_seconds) || frame_seconds < 0.0) frame_seconds = 0.0;
  if (frame_seconds > max_frame_) {
    frame_seconds = max_frame_;
    ++clamped_;
  }
  accumulator_ += frame_seconds;
  // A remainder within a few ulps of a whole tick counts as that tick (1/60 is inexact).
  int ticks = static_cast<int>(std::floor(accumulator_ / dt_ + 1e-9));
  accumulator_ -= ticks * dt_;
  // Guard against rounding leaving accumulator_ a hair below zero or at dt_.
  if (accumulator_ < 0.0) accumulator_ = 0.0;
  if (accumulator_ >= dt_) { accumulator_ -= dt_; ++ticks; }
  return ticks;
}

}  // namespace arc
