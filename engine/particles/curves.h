// particles/curves.h — per-particle attributes over normalised life t in [0, 1].
//
// A curve is a list of keyframes (t, value), linear between keys and constant beyond the ends.
// For the per-tick update it is also kept as a start value plus one ramp per segment,
//   value(t) = start + Σ delta_k · clamp((t − t_k) · inv_width_k, 0, 1),
// which a loop over particles evaluates with plain SIMD arithmetic (no table gathers). A table
// sampled at kCurveSamples intervals is kept for tools and tests.
#pragma once
#include <array>
#include <vector>

namespace arc {

inline constexpr int kCurveSamples = 128;

struct CurveKey {
  float t = 0.0f;
  float value = 0.0f;
};

struct CurveRamp {
  float t0 = 0.0f;
  float inv_width = 0.0f;  // a step (zero width) uses a very large slope
  float delta = 0.0f;
};

struct Curve {
  std::vector<CurveKey> keys;                  // sorted by t, at least one
  std::array<float, kCurveSamples + 1> table{};  // value at t = i / kCurveSamples
  bool constant = true;                         // all keys equal
  float start = 0.0f;                           // value before the first key
  std::vector<CurveRamp> ramps;                 // one per segment whose ends differ

  static Curve flat(float value);
  static Curve from_keys(std::vector<CurveKey> keys);
  // The exact piecewise-linear value.
  float exact(float t) const;
  // The ramp-sum form used by the per-tick update.
  float ramp_value(float t) const;
};

}  // namespace arc
