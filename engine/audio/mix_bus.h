// audio/mix_bus.h — the master bus's limiter and the group ducker (plain sample math, no OpenAL).
//
// Limiter: a look-ahead peak limiter. Each frame's needed gain (ceiling / peak, at most 1) passes
// an instant-attack, exponential-release follower, then a minimum over the look-ahead window and
// a box average of the same length; the audio is delayed by that window. Every gain averaged for
// a frame is at most the gain that frame needs, so no output sample exceeds the ceiling — a
// guarantee, not a tendency — and the gain still moves smoothly (no clicks).
//
// Ducker: a cue that must cut through (a hit on the player, a missile warning, a kill, a radio
// line) lowers the ducked groups by its depth in dB at once, holds, then returns linearly in dB.
// Several cues take the deepest. Both are pure functions of their inputs, so a replay's mix is
// the same bytes every run.
#pragma once
#include <cstddef>
#include <vector>

namespace arc {

class Limiter {
 public:
  Limiter(int sample_rate, double ceiling_db, double release_seconds, double lookahead_seconds = 0.002);
  // In place, interleaved stereo; the output lags the input by lookahead().
  void process(float* stereo, int frames);
  int lookahead() const { return lookahead_; }
  double ceiling() const { return ceiling_; }

 private:
  int lookahead_;
  double ceiling_, release_;
  double follower_ = 1, box_sum_ = 0;
  std::vector<float> delay_;      // 2 × lookahead samples
  std::vector<double> followed_;  // last lookahead + 1 follower values
  std::vector<double> held_;      // last lookahead minimums, for the box average
  size_t at_ = 0;                 // frames processed
};

class Ducker {
 public:
  // A cue of `depth_db` starts now, holding for `hold` seconds and releasing over `release`.
  void trigger(double depth_db, double hold, double release);
  void advance(double seconds);
  double depth_db() const { return depth_; }
  double gain() const;  // the linear gain of the ducked groups now

 private:
  double depth_ = 0, hold_ = 0, rate_ = 0;  // dB, seconds, dB per second
};

}  // namespace arc
