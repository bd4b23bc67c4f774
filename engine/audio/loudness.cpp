#include "audio/loudness.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/error.h"
#include "core/json.h"

namespace arc {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Biquad {
  double b0, b1, b2, a1, a2;
  double x1 = 0, x2 = 0, y1 = 0, y2 = 0;
  double run(double x) {
    const double y = b0 * x + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
    x2 = x1, x1 = x, y2 = y1, y1 = y;
    return y;
  }
};

// BS.1770's two K-weighting stages at `rate` (the constants are the standard's 48 kHz design).
void k_weighting(int rate, Biquad& shelf, Biquad& highpass) {
  double f0 = 1681.974450955533, q = 0.7071752369554196;
  double k = std::tan(kPi * f0 / rate);
  const double vh = std::pow(10.0, 3.999843853973347 / 20.0), vb = std::pow(vh, 0.4996667741545416);
  double a0 = 1.0 + k / q + k * k;
  shelf = {(vh + vb * k / q + k * k) / a0, 2.0 * (k * k - vh) / a0, (vh - vb * k / q + k * k) / a0,
           2.0 * (k * k - 1.0) / a0, (1.0 - k / q + k * k) / a0};
  f0 = 38.13547087602444, q = 0.5003270373238773;
  k = std::tan(kPi * f0 / rate);
  a0 = 1.0 + k / q + k * k;
  highpass = {1.0, -2.0, 1.0, 2.0 * (k * k - 1.0) / a0, (1.0 - k / q + k * k) / a0};
}

double to_db(double power) { return power > 0 ? 10.0 * std::log10(power) : -200.0; }

}  // namespace

WavStereo read_wav_stereo16(const std::string& path) {
  const std::string b = read_text_file(path, size_t(1) << 30, "a WAV file");
  auto u32 = [&](size_t at) { uint32_t v; std::memcpy(&v, b.data() + at, 4); return v; };
  auto u16 = [&](size_t at) { uint16_t v; std::memcpy(&v, b.data() + at, 2); return v; };
  if (b.size() < 44 || b.compare(0, 4, "RIFF") != 0 || b.compare(8, 4, "WAVE") != 0 || u16(20) != 1 || u16(22) != 2 ||
      u16(34) != 16 || b.compare(36, 4, "data") != 0)
    throw InputError(path + ": not a 16-bit PCM stereo WAV as --audio-out writes it");
  WavStereo w;
  w.sample_rate = int(u32(24));
  const size_t n = std::min<size_t>(u32(40), b.size() - 44) / 2;
  w.samples.resize(n);
  for (size_t i = 0; i < n; ++i) w.samples[i] = float(int16_t(u16(44 + 2 * i))) / 32767.0f;
  return w;
}

double peak_dbfs(const std::vector<float>& stereo) {
  double peak = 0;
  for (float s : stereo) peak = std::max(peak, double(std::abs(s)));
  return peak > 0 ? 20.0 * std::log10(peak) : -200.0;
}

double integrated_lufs(const std::vector<float>& stereo, int rate) {
  const size_t frames = stereo.size() / 2, hop = size_t(rate / 10);
  std::vector<double> z(frames / hop, 0.0);  // K-weighted energy summed over both channels, per 100 ms
  for (int ch = 0; ch < 2; ++ch) {
    Biquad shelf{}, hp{};
    k_weighting(rate, shelf, hp);
    for (size_t i = 0; i < z.size() * hop; ++i) {
      const double y = hp.run(shelf.run(stereo[2 * i + size_t(ch)]));
      z[i / hop] += y * y;
    }
  }
  std::vector<double> blocks;  // mean square of each 400 ms block, 75 % overlap
  for (size_t q = 0; q + 4 <= z.size(); ++q) blocks.push_back((z[q] + z[q + 1] + z[q + 2] + z[q + 3]) / double(4 * hop));
  auto gated_mean = [&](double gate_lufs) {
    double sum = 0;
    size_t n = 0;
    for (double b : blocks)
      if (-0.691 + to_db(b) > gate_lufs) sum += b, ++n;
    return n ? sum / double(n) : 0.0;
  };
  const double absolute = gated_mean(-70.0);
  if (absolute <= 0) return -200.0;
  return -0.691 + to_db(gated_mean(-0.691 + to_db(absolute) - 10.0));
}

double rms_dbfs(const std::vector<float>& stereo, int rate, double from, double to) {
  const size_t a = size_t(std::max(0.0, from) * rate) * 2, b = std::min(stereo.size(), size_t(std::max(0.0, to) * rate) * 2);
  if (b <= a) return -200.0;
  double sum = 0;
  for (size_t i = a; i < b; ++i) sum += double(stereo[i]) * stereo[i];
  return to_db(sum / double(b - a));
}

double k_weighted_lufs(const std::vector<float>& stereo, int rate, double from, double to) {
  const size_t frames = stereo.size() / 2;
  const size_t settle = size_t(std::max(0.0, from - 0.2) * rate), a = size_t(std::max(0.0, from) * rate);
  const size_t b = std::min(frames, size_t(std::max(0.0, to) * rate));
  if (b <= a) return -200.0;
  double sum = 0;
  for (int ch = 0; ch < 2; ++ch) {
    Biquad shelf{}, hp{};
    k_weighting(rate, shelf, hp);
    for (size_t i = settle; i < b; ++i) {
      const double y = hp.run(shelf.run(stereo[2 * i + size_t(ch)]));
      if (i >= a) sum += y * y;
    }
  }
  return -0.691 + to_db(sum / double(b - a));
}

double cue_rise_db(const std::vector<float>& stereo, int rate, double at, double window) {
  return rms_dbfs(stereo, rate, at, at + window) - rms_dbfs(stereo, rate, at - 1.0, at);
}

SilenceFigures silence(const std::vector<float>& stereo, int rate, double threshold) {
  SilenceFigures f;
  const double w = 0.1;
  const int windows = int(double(stereo.size() / 2) / rate / w);
  int quiet = 0, run = 0, longest = 0;
  for (int i = 0; i < windows; ++i) {
    if (rms_dbfs(stereo, rate, i * w, (i + 1) * w) < threshold) {
      ++quiet;
      longest = std::max(longest, ++run);
    } else {
      run = 0;
    }
  }
  f.share = windows ? double(quiet) / windows : 0.0;
  f.longest = longest * w;
  return f;
}

}  // namespace arc
