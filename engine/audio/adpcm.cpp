#include "audio/adpcm.h"

#include <algorithm>
#include <cstring>

#include "core/error.h"
#include "core/json.h"

namespace arc {
namespace {

constexpr int kIndex[16] = {-1, -1, -1, -1, 2, 4, 6, 8, -1, -1, -1, -1, 2, 4, 6, 8};
constexpr int kStep[89] = {
    7,     8,     9,     10,    11,    12,    13,    14,    16,    17,    19,    21,    23,    25,    28,
    31,    34,    37,    41,    45,    50,    55,    60,    66,    73,    80,    88,    97,    107,   118,
    130,   143,   157,   173,   190,   209,   230,   253,   279,   307,   337,   371,   408,   449,   494,
    544,   598,   658,   724,   796,   876,   963,   1060,  1166,  1282,  1411,  1552,  1707,  1878,  2066,
    2272,  2499,  2749,  3024,  3327,  3660,  4026,  4428,  4871,  5358,  5894,  6484,  7132,  7845,  8630,
    9493,  10442, 11487, 12635, 13899, 15289, 16818, 18500, 20350, 22385, 24623, 27086, 29794, 32767};

uint32_t u32(const std::string& b, size_t at) {
  uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}
uint16_t u16(const std::string& b, size_t at) {
  uint16_t v;
  std::memcpy(&v, b.data() + at, 2);
  return v;
}

[[noreturn]] void bad(const std::string& path, const std::string& what) {
  throw InputError(path + ": " + what + "; allowed: a mono IMA ADPCM WAV (sox -e ima-adpcm)");
}

}  // namespace

DecodedAudio decode_ima_adpcm_wav(const std::string& b, const std::string& path) {
  if (b.size() < 12 || b.compare(0, 4, "RIFF") != 0 || b.compare(8, 4, "WAVE") != 0) bad(path, "not a RIFF WAVE file");
  DecodedAudio out;
  size_t block_align = 0, data_at = 0, data_size = 0, total = 0;
  for (size_t at = 12; at + 8 <= b.size();) {
    const std::string id = b.substr(at, 4);
    const size_t size = u32(b, at + 4);
    if (at + 8 + size > b.size()) bad(path, "chunk '" + id + "' runs past the end");
    if (id == "fmt ") {
      if (size < 16 || u16(b, at + 8) != 0x11) bad(path, "format is not IMA ADPCM (0x11)");
      if (u16(b, at + 10) != 1) bad(path, "not mono");
      out.sample_rate = int(u32(b, at + 12));
      block_align = u16(b, at + 20);
    } else if (id == "fact" && size >= 4) {
      total = u32(b, at + 8);
    } else if (id == "data") {
      data_at = at + 8;
      data_size = size;
    }
    at += 8 + size + (size & 1);
  }
  if (!out.sample_rate || block_align <= 4 || !data_at) bad(path, "no fmt or data chunk");
  for (size_t blk = data_at; blk + 4 <= data_at + data_size; blk += block_align) {
    const size_t end = std::min(blk + block_align, data_at + data_size);
    int pred = int16_t(u16(b, blk));
    int index = std::clamp(int(uint8_t(b[blk + 2])), 0, 88);
    out.samples.push_back(int16_t(pred));
    for (size_t i = blk + 4; i < end; ++i)
      for (int half = 0; half < 2; ++half) {
        const int nib = (uint8_t(b[i]) >> (4 * half)) & 15;
        const int step = kStep[index];
        int diff = step >> 3;
        if (nib & 4) diff += step;
        if (nib & 2) diff += step >> 1;
        if (nib & 1) diff += step >> 2;
        pred = std::clamp(nib & 8 ? pred - diff : pred + diff, -32768, 32767);
        index = std::clamp(index + kIndex[nib], 0, 88);
        out.samples.push_back(int16_t(pred));
      }
  }
  if (total && total < out.samples.size()) out.samples.resize(total);
  return out;
}

DecodedAudio load_ima_adpcm_wav(const std::string& path) {
  return decode_ima_adpcm_wav(read_text_file(path, size_t(64) << 20), path);
}

}  // namespace arc
