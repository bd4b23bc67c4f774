#include "audio/sequencer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace arc {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTail = 3.0;  // seconds after a one-shot's last step for releases and echoes

double noise(uint64_t key, uint64_t i) {
  uint64_t x = key * 0x9E3779B97F4A7C15ull + i * 0xBF58476D1CE4E5B9ull;
  x ^= x >> 31;
  x *= 0x94D049BB133111EBull;
  x ^= x >> 29;
  return double(x >> 11) / double(uint64_t(1) << 53) * 2.0 - 1.0;
}

// A naive waveform minus its step discontinuity (polyBLEP), so high notes do not alias harshly.
double blep(double t, double dt) {
  if (t < dt) {
    t /= dt;
    return t + t - t * t - 1.0;
  }
  if (t > 1.0 - dt) {
    t = (t - 1.0) / dt;
    return t * t + t + t + 1.0;
  }
  return 0.0;
}

double oscillator(InstrumentDef::Wave w, double phase, double dt) {
  switch (w) {
    case InstrumentDef::Wave::Sine: return std::sin(2 * kPi * phase);
    case InstrumentDef::Wave::Triangle: return 1.0 - 4.0 * std::abs(phase - 0.5);
    case InstrumentDef::Wave::Square: {
      double v = phase < 0.5 ? 1.0 : -1.0;
      v += blep(phase, dt);
      v -= blep(std::fmod(phase + 0.5, 1.0), dt);
      return v;
    }
    case InstrumentDef::Wave::Saw: return 2.0 * phase - 1.0 - blep(phase, dt);
    case InstrumentDef::Wave::Noise: return 0.0;
  }
  return 0.0;
}

double envelope(const InstrumentDef& in, double t, double gate) {
  auto held = [&](double u) {
    if (u < in.attack) return u / in.attack;
    return in.sustain + (1.0 - in.sustain) * std::exp(-(u - in.attack) / in.decay);
  };
  if (t < gate) return held(t);
  return held(gate) * std::exp(-(t - gate) / (in.release / 3.0));
}

// One note into `out` (stereo, `frames` long, wrapping when `wrap`).
void render_note(const InstrumentDef& in, const MusicNote& n, double step_s, double gain, double pan, uint64_t key,
                 int rate, bool wrap, std::vector<float>& out) {
  const size_t frames = out.size() / 2;
  const double gate = n.length * step_s;
  const double length = gate + in.release * 1.2;
  const double f0 = 440.0 * std::pow(2.0, (n.midi - 69.0) / 12.0);
  const double lg = gain * std::cos((pan + 1) * kPi / 4), rg = gain * std::sin((pan + 1) * kPi / 4);
  const double hp = in.highpass > 0 ? std::exp(-2 * kPi * in.highpass / rate) : 0.0;
  const size_t start = size_t(std::llround(n.start * step_s * rate));
  const size_t count = size_t(length * rate);
  double p1 = 0, p2 = 0.25, lp1 = 0, lp2 = 0, hp_in = 0, hp_out = 0, a = 0, env = 0;
  for (size_t i = 0; i < count; ++i) {
    size_t at = start + i;
    if (at >= frames) {
      if (!wrap) break;
      at %= frames;
    }
    const double t = double(i) / rate;
    const double f = f0 * (in.pitch_drop > 0 ? std::pow(2.0, in.pitch_drop * std::exp(-t / in.pitch_time)) : 1.0);
    double v;
    if (in.wave == InstrumentDef::Wave::Noise) {
      v = noise(key, i);
    } else {
      const double dt1 = std::min(f / rate, 0.5);
      v = oscillator(in.wave, p1, dt1);
      p1 = std::fmod(p1 + dt1, 1.0);
      if (in.detune > 0) {
        const double dt2 = std::min(f * std::pow(2.0, in.detune / 1200.0) / rate, 0.5);
        v = 0.5 * (v + oscillator(in.wave, p2, dt2));
        p2 = std::fmod(p2 + dt2, 1.0);
      }
    }
    // The envelope and the filter move slowly: every 8 samples (1/6 ms) is smooth enough.
    if ((i & 7) == 0) {
      const double cut = std::min(in.lowpass * (1.0 + in.filter_env * std::exp(-t / in.decay)), 0.45 * rate);
      a = 1.0 - std::exp(-2 * kPi * cut / rate);
      env = envelope(in, t, gate) * in.gain;
    }
    lp1 += a * (v - lp1);
    lp2 += a * (lp1 - lp2);
    double s = lp2;
    if (hp > 0) {
      hp_out = hp * (hp_out + s - hp_in);
      hp_in = s;
      s = hp_out;
    }
    s *= env;
    out[2 * at] += float(s * lg);
    out[2 * at + 1] += float(s * rg);
  }
}

// Ping-pong echo: the left's echo returns on the right and back. A loop runs its echo over three
// passes and keeps the last, so the echo of the end sounds at the start.
void echo(const MusicPieceDef& p, int rate, std::vector<float>& out) {
  if (p.echo_mix <= 0) return;
  const size_t frames = out.size() / 2;
  const size_t d = std::max<size_t>(1, size_t(p.echo_beats * p.beat_seconds() * rate));
  std::vector<double> line(2 * d, 0.0);
  std::vector<float> dry = out;
  const int passes = p.loop ? 3 : 1;
  size_t k = 0;
  for (int pass = 0; pass < passes; ++pass)
    for (size_t i = 0; i < frames; ++i, ++k) {
      double* slot = &line[2 * (k % d)];
      const double wl = slot[0], wr = slot[1];
      slot[0] = 0.5 * dry[2 * i + 1] + p.echo_feedback * wr;  // crossed: ping-pong
      slot[1] = 0.5 * dry[2 * i] + p.echo_feedback * wl;
      if (pass == passes - 1) {
        out[2 * i] = float(dry[2 * i] + p.echo_mix * wl);
        out[2 * i + 1] = float(dry[2 * i + 1] + p.echo_mix * wr);
      }
    }
}

}  // namespace

std::vector<float> render_piece(const MusicLibraryDef& lib, const MusicPieceDef& p, int rate) {
  const size_t frames = size_t(std::llround(p.seconds() * rate)) + (p.loop ? 0 : size_t(kTail * rate));
  std::vector<float> out(frames * 2, 0.0f);
  uint64_t key = 1;
  for (const MusicTrackDef& t : p.tracks) {
    const InstrumentDef& in = lib.instruments[size_t(t.instrument)];
    const double step_s = p.beat_seconds() / t.steps_per_beat;
    for (const MusicNote& n : t.notes) render_note(in, n, step_s, t.gain, t.pan, key++, rate, p.loop, out);
  }
  echo(p, rate, out);
  double sum = 0, peak = 0;
  for (float s : out) {
    sum += double(s) * s;
    peak = std::max(peak, double(std::abs(s)));
  }
  const double rms = std::sqrt(sum / double(std::max<size_t>(out.size(), 1)));
  if (rms <= 0) return out;
  // One-shots are measured over their notes only, not the silent tail room.
  const double measured = p.loop ? rms : rms * std::sqrt(double(frames) / (p.seconds() * rate));
  double scale = kMusicRms * p.gain / measured;
  if (peak * scale > 0.95) scale = 0.95 / peak;
  for (float& s : out) s = float(s * scale);
  return out;
}

}  // namespace arc
