// particles/curves.h — per-particle attributes over normalised life t in [0, 1].
//
// A curve is a list of keyframes (t, value), linear between keys and constant beyond the ends.
// For the per-tick update it is also sampled into a small table (kCurveSamples intervals) so the
// SoA loop can evaluate it with one index and one lerp, shared by all curves of a cluster.
#pragma once
#include <array>
#include <vector>

namespace arc {

inline constexpr int kCurveSamples = 128;

struct CurveKey {
  float t = 0.0f;
  float value = 0.0f;
};

struct Curve {
  std::vector<CurveKey> keys;                  // sorted by t, at least one
  std::array<float, kCurveSamples + 1> table{};  // value at t = i / kCurveSamples
  bool constant = true;                         // all keys equal: the table is not needed

  static Curve flat(float value);
  static Curve from_keys(std::vector<CurveKey> keys);
  // The exact piecewise-linear value.
  float exact(float t) const;
};

}  // namespace arc
