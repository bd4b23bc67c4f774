// core/hash.h — a 64-bit streaming hash of simulation state.
//
// StateHasher folds values in one at a time; doubles are hashed by their bit pattern
// (+0.0 and -0.0 differ, as they can lead to different futures). Used for the per-tick
// replay hash and the determinism tests.
#pragma once
#include <bit>
#include <cstdint>
#include <string_view>
#include <glm/vec3.hpp>
#include <glm/gtc/quaternion.hpp>
#include "core/rng.h"

namespace arc {

class StateHasher {
 public:
  void add_u64(uint64_t v) { h_ = mix64(h_ ^ (v + 0x9E3779B97F4A7C15ull + (h_ << 6) + (h_ >> 2))); }
  void add_i64(int64_t v) { add_u64(static_cast<uint64_t>(v)); }
  void add_bool(bool v) { add_u64(v ? 1 : 0); }
  void add_f64(double v) { add_u64(std::bit_cast<uint64_t>(v)); }
  void add_f32(float v) { add_u64(std::bit_cast<uint32_t>(v)); }
  void add_vec(const glm::dvec3& v) { add_f64(v.x); add_f64(v.y); add_f64(v.z); }
  void add_quat(const glm::dquat& q) { add_f64(q.w); add_f64(q.x); add_f64(q.y); add_f64(q.z); }
  void add_str(std::string_view s) {
    add_u64(s.size());
    for (unsigned char c : s) add_u64(c);
  }
  uint64_t value() const { return h_; }

 private:
  uint64_t h_ = 0x243F6A8885A308D3ull;
};

}  // namespace arc
