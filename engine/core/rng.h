// core/rng.h — counter-based, keyed random numbers.
//
// A value is a pure function of its key (seed, stream, tick, index): nothing depends on how
// many other values were drawn before it, so update order, culling and skipping ticks cannot
// change a simulation. The mixer is SplitMix64's finaliser applied in a chain over the key
// words (each word is folded in with a distinct odd constant).
//
// Example, compiled as CoreExamples.KeyedRng in tests/unit/core/test_core_examples.cpp:
//   arc::Rng r{seed, stream, tick};         // a generator for one (seed, stream, tick)
//   float u = r.uniform(i);                 // i-th value in [0, 1)
//   glm::dvec3 d = r.unit_vector(i);        // uses indices i*4 and i*4+1
#pragma once
#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>

namespace arc {

constexpr uint64_t mix64(uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

constexpr uint64_t key_hash(uint64_t seed, uint64_t stream, uint64_t tick, uint64_t index) {
  uint64_t h = mix64(seed ^ 0xA0761D6478BD642Full);
  h = mix64(h ^ (stream * 0xE7037ED1A0B428DBull));
  h = mix64(h ^ (tick * 0x8EBC6AF09C88C6E3ull));
  h = mix64(h ^ (index * 0x589965CC75374CC3ull));
  return h;
}

struct Rng {
  uint64_t seed = 0;
  uint64_t stream = 0;
  uint64_t tick = 0;

  uint64_t bits(uint64_t index) const { return key_hash(seed, stream, tick, index); }
  // Uniform in [0, 1) with 53 random bits.
  double uniform(uint64_t index) const { return double(bits(index) >> 11) * 0x1.0p-53; }
  double range(uint64_t index, double lo, double hi) const { return lo + (hi - lo) * uniform(index); }
  // Uniform on the unit sphere (Marsaglia-free: z uniform, angle uniform). Uses index*4 and index*4+1.
  glm::dvec3 unit_vector(uint64_t index) const {
    double z = 2.0 * uniform(index * 4) - 1.0;
    double a = 6.283185307179586 * uniform(index * 4 + 1);
    double r = std::sqrt(std::fmax(0.0, 1.0 - z * z));
    return {r * std::cos(a), r * std::sin(a), z};
  }
};

}  // namespace arc
