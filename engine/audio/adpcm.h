// audio/adpcm.h — decodes IMA ADPCM WAV files (format 0x11, mono), the radio lines' codec.
//
// IMA ADPCM keeps 4 bits a sample (a quarter of 16-bit PCM), is written by sox (`-e ima-adpcm`)
// and read by every audio tool, and decodes in a few dozen lines with no library: enough for
// band-limited radio speech. Errors are one line naming the file (InputError).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace arc {

struct DecodedAudio {
  int sample_rate = 0;
  std::vector<int16_t> samples;  // mono
};

DecodedAudio decode_ima_adpcm_wav(const std::string& bytes, const std::string& path);
DecodedAudio load_ima_adpcm_wav(const std::string& path);

}  // namespace arc
