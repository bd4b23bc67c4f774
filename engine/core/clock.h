// core/clock.h — the fixed-timestep loop arithmetic.
//
// The simulation runs at a fixed tick (60 Hz by default); the renderer draws as often as it
// can and interpolates between the last two simulated states by `alpha`. A long frame (a
// hitch, a breakpoint) is clamped to `max_frame` seconds so the loop cannot spiral.
//
// Example, compiled as CoreExamples.FixedStepClock in tests/unit/core/test_core_examples.cpp:
//   FixedStepClock clock{60};
//   int n = clock.advance(frame_seconds);   // run n ticks now
//   double a = clock.alpha();               // interpolation factor in [0, 1)
#pragma once
#include <cstdint>

namespace arc {

class FixedStepClock {
 public:
  explicit FixedStepClock(int tick_rate_hz = 60, double max_frame_seconds = 0.25);

  // Feeds real elapsed time; returns the number of fixed ticks to simulate now.
  int advance(double frame_seconds);
  double alpha() const { return accumulator_ / dt_; }
  double dt() const { return dt_; }
  int tick_rate() const { return rate_; }
  bool paused() const { return paused_; }
  void set_paused(bool p) { paused_ = p; accumulator_ = 0.0; }
  uint64_t clamped_frames() const { return clamped_; }

 private:
  int rate_;
  double dt_;
  double max_frame_;
  double accumulator_ = 0.0;
  bool paused_ = false;
  uint64_t clamped_ = 0;
};

}  // namespace arc
