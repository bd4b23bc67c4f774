#include "audio/mix_bus.h"

#include <algorithm>
#include <cmath>

namespace arc {

Limiter::Limiter(int sample_rate, double ceiling_db, double release_seconds, double lookahead_seconds)
    : lookahead_(std::max(1, int(std::lround(lookahead_seconds * sample_rate)))),
      ceiling_(std::pow(10.0, ceiling_db / 20.0)),
      release_(1.0 - std::exp(-1.0 / (std::max(release_seconds, 1e-4) * sample_rate))),
      delay_(size_t(lookahead_) * 2, 0.0f),
      followed_(size_t(lookahead_) + 1, 1.0),
      held_(size_t(lookahead_), 1.0) {
  box_sum_ = double(lookahead_);
}

void Limiter::process(float* stereo, int frames) {
  const size_t n = size_t(lookahead_);
  for (int f = 0; f < frames; ++f) {
    float* s = stereo + 2 * size_t(f);
    const double peak = std::max(std::abs(double(s[0])), std::abs(double(s[1])));
    const double need = peak > ceiling_ ? ceiling_ / peak : 1.0;
    follower_ = std::min(need, follower_ + (1.0 - follower_) * release_);
    followed_[at_ % (n + 1)] = follower_;
    const double held = *std::min_element(followed_.begin(), followed_.end());
    double& slot = held_[at_ % n];
    box_sum_ += held - slot;
    slot = held;
    // The sum drifts by rounding over hours; recompute it once per window.
    if (at_ % n == n - 1) {
      box_sum_ = 0;
      for (double h : held_) box_sum_ += h;
    }
    const double gain = std::min(1.0, box_sum_ / double(n));
    float* d = &delay_[2 * (at_ % n)];
    const float in_l = s[0], in_r = s[1];
    s[0] = float(std::clamp(double(d[0]) * gain, -ceiling_, ceiling_));
    s[1] = float(std::clamp(double(d[1]) * gain, -ceiling_, ceiling_));
    d[0] = in_l;
    d[1] = in_r;
    ++at_;
  }
}

void Ducker::trigger(double depth_db, double hold, double release) {
  if (depth_db <= 0) return;
  if (depth_db >= depth_) {
    depth_ = depth_db;
    rate_ = depth_db / std::max(release, 1e-3);
    hold_ = hold;
  } else {
    hold_ = std::max(hold_, hold);
  }
}

void Ducker::advance(double seconds) {
  if (hold_ > 0) {
    const double used = std::min(hold_, seconds);
    hold_ -= used;
    seconds -= used;
  }
  depth_ = std::max(0.0, depth_ - rate_ * seconds);
}

double Ducker::gain() const { return std::pow(10.0, -depth_ / 20.0); }

}  // namespace arc
