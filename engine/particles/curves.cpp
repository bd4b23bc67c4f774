#include "particles/curves.h"

#include <algorithm>

namespace arc {

Curve Curve::flat(float value) { return from_keys({{0.0f, value}}); }

Curve Curve::from_keys(std::vector<CurveKey> keys) {
  Curve c;
  c.keys = std::move(keys);
  for (const CurveKey& k : c.keys) c.constant = c.constant && k.value == c.keys.front().value;
  for (int i = 0; i <= kCurveSamples; ++i) c.table[size_t(i)] = c.exact(float(i) / float(kCurveSamples));
  c.start = c.keys.front().value;
  for (size_t i = 1; i < c.keys.size(); ++i) {
    const CurveKey& a = c.keys[i - 1];
    const CurveKey& b = c.keys[i];
    if (a.value == b.value) continue;
    const float width = b.t - a.t;
    c.ramps.push_back({a.t, width > 0.0f ? 1.0f / width : 1e30f, b.value - a.value});
  }
  return c;
}

float Curve::ramp_value(float t) const {
  float v = start;
  for (const CurveRamp& r : ramps) v += r.delta * std::min(std::max((t - r.t0) * r.inv_width, 0.0f), 1.0f);
  return v;
}

float Curve::exact(float t) const {
  if (t <= keys.front().t) return keys.front().value;
  if (t >= keys.back().t) return keys.back().value;
  size_t i = 1;
  while (keys[i].t < t) ++i;
  const CurveKey& a = keys[i - 1];
  const CurveKey& b = keys[i];
  const float span = b.t - a.t;
  if (span <= 0.0f) return b.value;
  return a.value + (b.value - a.value) * ((t - a.t) / span);
}

}  // namespace arc
