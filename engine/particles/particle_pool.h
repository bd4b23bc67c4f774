// particles/particle_pool.h — one cluster's particles as structure-of-arrays.
//
// Every attribute is its own contiguous array, so each per-tick kernel streams exactly the
// arrays it needs and the compiler can vectorise it. Positions are floats in the cluster's
// frame (the cluster origin is double precision). Particles stay in spawn order: removal is a
// stable compaction, so the layout never depends on when a cluster was animated. Capacity is
// kept while the cluster lives (particles dying and being born allocate nothing) and given
// back when it is released, so memory follows the live clusters.
//
// Bytes per particle: 20 floats + 3 uint32 + uint16 + uint8 = 95.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace arc {

class StateHasher;

inline constexpr uint32_t kNeverDies = std::numeric_limits<uint32_t>::max();

enum ParticleFlags : uint8_t {
  kParticleHidden = 1,  // beyond a lightning cut: kept, not drawn
};

struct ParticlePool {
  // Current state, written by the animation kernels.
  std::vector<float> px, py, pz;        // position in the cluster frame
  std::vector<float> size;              // half-width, m
  std::vector<float> rotation;          // radians
  std::vector<float> r, g, b, a, burn;  // straight (not premultiplied) colour, alpha, burn
  // Birth state, from which every later state is computed in closed form.
  std::vector<float> p0x, p0y, p0z;     // linear: birth position; sphere: unit direction; lightning: segment start
  std::vector<float> vx, vy, vz;        // linear: birth velocity; lightning: segment vector
  std::vector<float> reach;             // linear: farthest distance from the birth position over life
  std::vector<float> size0, rot0, spin; // initial size, initial rotation, radians per second
  std::vector<uint32_t> birth, death;   // ticks since the cluster's spawn; death = kNeverDies for cluster-long life
  std::vector<uint32_t> uid;            // spawn number within the cluster: the RNG index of this particle
  std::vector<uint16_t> sprite;
  std::vector<uint8_t> flags;

  size_t count() const { return px.size(); }
  void reserve(size_t n);
  void resize(size_t n);  // new particles are zeroed
  void clear();
  // Removes particles whose death tick has come, keeping order; returns how many died. Reads
  // only the particles born since the last call while none is due (a cluster beyond the cull
  // distance costs no pass over its particles per tick).
  size_t retire(uint32_t now);
  void hash(StateHasher& h) const;
  // Counts every change of which particles exist (births, deaths, resizes), so a value computed
  // from the birth state (the cluster's bound) can be kept until the next change.
  uint64_t changes() const { return changes_; }
  // The arrays were written directly (a snapshot read): forget what retire() and changes() knew.
  void touch();

 private:
  // Particles [0, deaths_known_) die no earlier than first_death_. Deaths are written only
  // for particles appended by resize(), or raised to kNeverDies, so the bound stays safe.
  size_t deaths_known_ = 0;
  uint32_t first_death_ = UINT32_MAX;
  uint64_t changes_ = 0;
};

}  // namespace arc
