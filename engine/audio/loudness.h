// audio/loudness.h — measures a stereo mix: peak, ITU-R BS.1770 loudness, cue rises, silence.
//
// integrated_lufs() is BS.1770-4: K-weighting (the high-shelf pre-filter and the RLB high-pass,
// their coefficients derived for any rate), mean squares over 400 ms blocks every 100 ms, the
// absolute gate at −70 LUFS and the relative gate 10 LU under the gated mean. The tests and
// `arcfire --measure-audio` use these on rendered WAVs; nothing here runs while the game plays.
#pragma once
#include <string>
#include <vector>

namespace arc {

struct WavStereo {
  int sample_rate = 0;
  std::vector<float> samples;  // interleaved stereo, −1..1
};

// A 16-bit PCM stereo WAV as write_wav_stereo16() writes it; InputError names the file otherwise.
WavStereo read_wav_stereo16(const std::string& path);

double peak_dbfs(const std::vector<float>& stereo);
double integrated_lufs(const std::vector<float>& stereo, int sample_rate);
// RMS of both channels over [from, to) seconds, in dBFS (−200 for silence).
double rms_dbfs(const std::vector<float>& stereo, int sample_rate, double from, double to);
// K-weighted loudness (BS.1770's filter, no gating) of [from, to) seconds, in LUFS.
double k_weighted_lufs(const std::vector<float>& stereo, int sample_rate, double from, double to);
// How far a cue starting at `at` seconds stands out: the RMS of the `window` after it over the
// RMS of the second before it, in dB.
double cue_rise_db(const std::vector<float>& stereo, int sample_rate, double at, double window = 0.3);

struct SilenceFigures {
  double share = 0;    // of 100 ms windows whose RMS is under the threshold
  double longest = 0;  // seconds of the longest run of such windows
};
SilenceFigures silence(const std::vector<float>& stereo, int sample_rate, double threshold_dbfs = -50);

}  // namespace arc
