// particles/particle_pool.h — one cluster's particles as structure-of-arrays.
//
// Every attribute is its own contiguous array, so each per-tick kernel streams exactly the
// arrays it needs and the compiler can vectorise it. Positions are floats in the cluster's
// frame (the cluster origin is double precision). Particles stay in spawn order: removal is a
// stable compaction, so the layout never depends on when a cluster was animated. Capacity is
// kept while the cluster lives (particles dying and being born allocate nothing) and given
// back when it is released.
//
// The columns of one pool are one block: of a world's ParticleStore (particle_store.h) when
// the pool is made with it and the store has room, else of the heap (a pool made without a
// store: scratch copies, tests). A column is a view (pointer, count) into that block; growing
// the pool moves every column to a larger block at once.
//
// Bytes per particle: 20 floats + 3 uint32 + uint16 + uint8 = 95 (kParticleBytes).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "particles/particle_store.h"

namespace arc {

class StateHasher;

inline constexpr uint32_t kNeverDies = std::numeric_limits<uint32_t>::max();

enum ParticleFlags : uint8_t {
  kParticleHidden = 1,  // beyond a lightning cut: kept, not drawn
};

// One attribute of every particle of a pool: contiguous, count() elements. Indexing, data()
// and iteration as a std::vector's; the size changes only through the pool.
template <typename T>
class ParticleColumn {
 public:
  T& operator[](size_t i) { return data_[i]; }
  const T& operator[](size_t i) const { return data_[i]; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }

 private:
  friend struct ParticlePool;
  T* data_ = nullptr;
  size_t size_ = 0;
};

struct ParticlePool {
  // Current state, written by the animation kernels.
  ParticleColumn<float> px, py, pz;        // position in the cluster frame
  ParticleColumn<float> size;              // half-width, m
  ParticleColumn<float> rotation;          // radians
  ParticleColumn<float> r, g, b, a, burn;  // straight (not premultiplied) colour, alpha, burn
  // Birth state, from which every later state is computed in closed form.
  ParticleColumn<float> p0x, p0y, p0z;     // linear: birth position; sphere: unit direction; lightning: segment start
  ParticleColumn<float> vx, vy, vz;        // linear: birth velocity; lightning: segment vector
  ParticleColumn<float> reach;             // linear: farthest distance from the birth position over life
  ParticleColumn<float> size0, rot0, spin; // initial size, initial rotation, radians per second
  ParticleColumn<uint32_t> birth, death;   // ticks since the cluster's spawn; death = kNeverDies for cluster-long life
  ParticleColumn<uint32_t> uid;            // spawn number within the cluster: the RNG index of this particle
  ParticleColumn<uint16_t> sprite;
  ParticleColumn<uint8_t> flags;

  ParticlePool() = default;                     // storage from the heap
  explicit ParticlePool(ParticleStore* store);  // storage from `store` while it has room
  ParticlePool(const ParticlePool& o);          // the same particles, in storage from the heap
  ParticlePool& operator=(const ParticlePool& o);  // the same particles; this pool's storage source kept
  ParticlePool(ParticlePool&& o) noexcept;
  ParticlePool& operator=(ParticlePool&& o) noexcept;
  ~ParticlePool();

  size_t count() const { return count_; }
  size_t capacity() const { return capacity_; }
  bool in_store() const { return block_.capacity != 0; }
  void reserve(size_t n);
  // Room for `n` particles only where the store has it: a world holding more clusters than its
  // store would otherwise take heap for particles its budget never admits.
  void reserve_in_store(size_t n);
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
  void set_count(size_t n);
  void set_columns(const std::array<std::byte*, kParticleColumns>& data);
  // New storage of at least `capacity`, the particles copied over; with `heap` false, only a
  // block of the store (else nothing changes).
  void move_to(size_t capacity, bool heap = true);
  void free_storage();
  void take_from(ParticlePool& o);

  ParticleStore* store_ = nullptr;
  ParticleBlock block_;             // in store_, when capacity != 0
  std::byte* heap_ = nullptr;       // otherwise: this pool's own allocation
  size_t capacity_ = 0, count_ = 0;
  // Particles [0, deaths_known_) die no earlier than first_death_. Deaths are written only
  // for particles appended by resize(), or raised to kNeverDies, so the bound stays safe.
  size_t deaths_known_ = 0;
  uint32_t first_death_ = UINT32_MAX;
  uint64_t changes_ = 0;
};

}  // namespace arc
