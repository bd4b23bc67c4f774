#include "audio/synth.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"

namespace arc {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kGateRamp = 0.002;  // seconds: a burst opens and closes this smoothly
constexpr double kPeak = 0.9;        // every sound peaks here; the def's gain applies at playback

double oscillator(SoundLayerDef::Source src, double phase) {
  const double t = phase - std::floor(phase);
  switch (src) {
    case SoundLayerDef::Source::Sine: return std::sin(kTwoPi * t);
    case SoundLayerDef::Source::Square: return t < 0.5 ? 1.0 : -1.0;
    case SoundLayerDef::Source::Saw: return 2.0 * t - 1.0;
    case SoundLayerDef::Source::Triangle: return t < 0.5 ? 4.0 * t - 1.0 : 3.0 - 4.0 * t;
    case SoundLayerDef::Source::Noise: return 0.0;
  }
  return 0.0;
}

double envelope(const SoundLayerDef& l, double t, bool loop) {
  if (loop) return 1.0;
  if (t < 0) return 0.0;
  if (t < l.attack) return t / l.attack;
  t -= l.attack;
  if (t < l.hold) return 1.0;
  t -= l.hold;
  if (t >= l.decay) return 0.0;
  return std::pow(1.0 - t / l.decay, l.decay_curve);
}

// The burst gate at time t: 1 inside a burst, 0 between, with short linear ramps. Burst k
// starts at k·period plus a keyed jitter, so the rhythm is irregular but repeatable.
double gate(const SoundLayerDef& l, double t, uint64_t seed, uint64_t layer) {
  if (l.burst_period <= 0) return 1.0;
  const int64_t k = int64_t(std::floor(t / l.burst_period));
  double best = 0;
  for (int64_t b = k - 1; b <= k; ++b) {
    const double shift = l.jitter * l.burst_period * 0.5 * Rng{seed, 1000 + layer, uint64_t(b + 1)}.uniform(0);
    const double local = t - (double(b) * l.burst_period + shift);
    if (local < 0 || local > l.burst_length) continue;
    const double ramp = std::min({1.0, local / kGateRamp, (l.burst_length - local) / kGateRamp});
    best = std::max(best, ramp);
  }
  return best;
}

// One-pole filter coefficient for a cut-off in Hz.
double pole(double cutoff, int rate) { return 1.0 - std::exp(-kTwoPi * cutoff / double(rate)); }

void add_layer(const SoundDef& def, size_t index, int rate, std::vector<double>& out) {
  const SoundLayerDef& l = def.layers[index];
  const double total = double(out.size()) / rate;
  const double lp = l.lowpass > 0 ? pole(l.lowpass, rate) : 1.0;
  const double hp = l.highpass > 0 ? pole(l.highpass, rate) : 0.0;
  double phase = 0, low = 0, high_state = 0;
  const Rng noise{def.seed, index, 0};
  for (size_t i = 0; i < out.size(); ++i) {
    const double t = double(i) / rate;
    const double u = std::clamp((t - l.delay) / std::max(total - l.delay, 1e-6), 0.0, 1.0);
    const double freq = l.freq_start * std::pow(l.freq_end / l.freq_start, u);
    double x = l.source == SoundLayerDef::Source::Noise ? 2.0 * noise.uniform(i) - 1.0 : oscillator(l.source, phase);
    phase += freq / rate;
    high_state += hp * (x - high_state);
    x -= high_state;
    low += lp * (x - low);
    out[i] += l.gain * low * gate(l, t - l.delay, def.seed, index) * envelope(l, t - l.delay, def.loop);
  }
}

// A loop's last `fade` samples are blended into its first ones, so sample N−1 flows into 0.
void crossfade_seam(std::vector<double>& s, size_t loop_length) {
  const size_t fade = s.size() - loop_length;
  for (size_t i = 0; i < fade; ++i) {
    const double a = double(i) / double(fade);
    s[i] = s[i] * a + s[loop_length + i] * (1.0 - a);
  }
  s.resize(loop_length);
}

}  // namespace

std::vector<float> synthesise(const SoundDef& def, int sample_rate) {
  const size_t length = std::max<size_t>(1, size_t(std::llround(def.duration * sample_rate)));
  const size_t fade = def.loop ? std::min(length / 4, size_t(0.02 * sample_rate)) : 0;
  std::vector<double> mix(length + fade, 0.0);
  for (size_t i = 0; i < def.layers.size(); ++i) add_layer(def, i, sample_rate, mix);
  if (def.loop) crossfade_seam(mix, length);
  if (!def.loop) mix.back() = 0.0;
  double peak = 0;
  for (double v : mix) peak = std::max(peak, std::abs(v));
  const double scale = peak > 1e-9 ? kPeak / peak : 0.0;
  std::vector<float> out(mix.size());
  for (size_t i = 0; i < mix.size(); ++i) out[i] = float(mix[i] * scale);
  return out;
}

}  // namespace arc
