// core/fast_hash.h — a 64-bit hash of a stream of words, fast enough to run every tick.
//
// Same interface as core/hash.h's StateHasher. StateHasher mixes each word into the running
// value, so every word waits for the previous one's full mix (a chain of multiplies). Here the
// i-th word w is mixed on its own, as mix64(w ^ i·K), and the results are summed: the words
// are mixed in parallel and only an add is serial, several times the throughput. mix64 is a
// bijection, so changing any one word always changes the sum; position i keys each word, so
// order matters. value() mixes the sum with the word count.
//
// Use a local FastHasher in a hot loop (not one reached through a reference), so the compiler
// keeps its two words in registers, and fold it into an outer hasher with add_u64(value()).
#pragma once
#include <bit>
#include <cstdint>
#include <string_view>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "core/rng.h"

namespace arc {

class FastHasher {
 public:
  void add_u64(uint64_t v) {
    sum_ += mix64(v ^ (n_ * 0xD1342543DE82EF95ull));
    ++n_;
  }
  void add_i64(int64_t v) { add_u64(static_cast<uint64_t>(v)); }
  void add_bool(bool v) { add_u64(v ? 1 : 0); }
  void add_f64(double v) { add_u64(std::bit_cast<uint64_t>(v)); }
  void add_f32(float v) { add_u64(std::bit_cast<uint32_t>(v)); }
  void add_vec(const glm::dvec3& v) { add_f64(v.x), add_f64(v.y), add_f64(v.z); }
  void add_quat(const glm::dquat& q) { add_f64(q.w), add_f64(q.x), add_f64(q.y), add_f64(q.z); }
  // Eight characters per word, the length first.
  void add_str(std::string_view s) {
    add_u64(s.size());
    for (size_t i = 0; i < s.size(); i += 8) {
      uint64_t w = 0;
      for (size_t k = 0; k < 8 && i + k < s.size(); ++k) w |= uint64_t(uint8_t(s[i + k])) << (8 * k);
      add_u64(w);
    }
  }
  uint64_t value() const { return mix64(sum_ ^ mix64(n_ + 0x243F6A8885A308D3ull)); }

 private:
  uint64_t sum_ = 0;
  uint64_t n_ = 0;
};

}  // namespace arc
