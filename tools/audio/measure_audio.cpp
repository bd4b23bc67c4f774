// tools/audio/measure_audio.cpp — the figures of a rendered mix (arcfire --audio-out WAV).
//
// Usage: arcfire_measure_audio FILE.wav [--at SECONDS ...]
// Prints the peak (dBFS), the integrated loudness (ITU-R BS.1770, LUFS), the share of 100 ms
// windows under −50 dBFS and the longest such run, and for each --at time the rise of the
// 300 ms after it over the second before it (dB). Bad input: one line and exit code 2.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "audio/loudness.h"
#include "core/error.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: arcfire_measure_audio FILE.wav [--at SECONDS ...]\n");
    return 2;
  }
  std::vector<double> at;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--at" && i + 1 < argc) {
      char* end = nullptr;
      at.push_back(std::strtod(argv[++i], &end));
      if (!end || *end) {
        std::fprintf(stderr, "arcfire_measure_audio: --at '%s': allowed: a time in seconds\n", argv[i]);
        return 2;
      }
    } else {
      std::fprintf(stderr, "arcfire_measure_audio: '%s': allowed: --at SECONDS\n", a.c_str());
      return 2;
    }
  }
  try {
    const arc::WavStereo w = arc::read_wav_stereo16(argv[1]);
    const arc::SilenceFigures s = arc::silence(w.samples, w.sample_rate);
    std::printf("%s: %.2f s, peak %.2f dBFS, loudness %.2f LUFS, silence %.1f %% (longest %.1f s)\n", argv[1],
                double(w.samples.size() / 2) / w.sample_rate, arc::peak_dbfs(w.samples),
                arc::integrated_lufs(w.samples, w.sample_rate), 100.0 * s.share, s.longest);
    for (double t : at)
      std::printf("  rise at %.3f s: %+.1f dB\n", t, arc::cue_rise_db(w.samples, w.sample_rate, t));
  } catch (const arc::InputError& e) {
    std::fprintf(stderr, "arcfire_measure_audio: %s\n", e.what());
    return 2;
  }
  return 0;
}
