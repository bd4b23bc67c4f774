// gfx/frame_time_target.cpp — the smoothed frame time and the level it moves (no GL).
#include "gfx/frame_time_target.h"

#include <algorithm>
#include <cmath>

namespace arc {
namespace {

constexpr double kAttack = 0.25;   // share of the way toward a slower frame's log time
constexpr double kRelease = 0.10;  // and toward a faster one's
constexpr double kFallGain = 0.5;  // log level per log of excess time
constexpr double kRiseGain = 0.25; // log level per log of headroom

}  // namespace

void FrameTimeTarget::set_target(double ms) {
  const double t = std::isfinite(ms) && ms > 0.0 ? ms : 0.0;
  if (t == target_ms_) return;
  target_ms_ = t;
  reset();
}

void FrameTimeTarget::reset() {
  level_ = 1.0;
  has_frame_ = false;
  since_fall_ = kHoldFrames;
}

double FrameTimeTarget::min_px(int rows) const {
  return kMinPxAtFloor * (1.0 - level_) / (1.0 - kMinLevel) * double(rows) / 720.0;
}

double FrameTimeTarget::smoothed_ms() const { return has_frame_ ? std::exp(log_smoothed_) : 0.0; }

void FrameTimeTarget::observe(double frame_ms, bool level_in_use) {
  if (target_ms_ <= 0.0) {
    level_ = 1.0;
    return;
  }
  if (!std::isfinite(frame_ms) || frame_ms <= 0.0) return;
  const double x = std::log(std::clamp(frame_ms, 0.25 * target_ms_, 4.0 * target_ms_));
  if (!has_frame_) log_smoothed_ = x;
  else log_smoothed_ += (x > log_smoothed_ ? kAttack : kRelease) * (x - log_smoothed_);
  has_frame_ = true;
  ++since_fall_;
  const double e = log_smoothed_ - std::log(target_ms_);  // > 0: slower than the target
  double step = 0.0;
  if (e > std::log(kOverShare)) {
    step = -std::min(kFallGain * (e - std::log(kOverShare)), -std::log(1.0 - kMaxFall));
    since_fall_ = 0;
  } else if (since_fall_ >= kHoldFrames) {
    if (e < std::log(kUnderShare)) step = std::min(kRiseGain * (std::log(kUnderShare) - e), std::log(1.0 + kMaxRise));
    else if (e <= 0.0 && !level_in_use) step = std::log(1.0 + kMaxRise);
  }
  level_ = std::clamp(level_ * std::exp(step), kMinLevel, 1.0);
}

}  // namespace arc
