// particles/particle_store.h — one particle world's storage, taken and written once at the budget.
//
// Pools that take their arrays from the heap make the process's resident memory follow the
// busiest moment seen so far: the heap keeps what a battle's peak asked for. A game holds its
// particle memory at the budget instead: the store is every ParticlePool column laid out for the
// whole budget (rounded up to whole top blocks), allocated and written through when the world is
// made, so resident memory is what the budget promises from the first tick and never grows.
//
// Pools take blocks of it: a block is the same particle range in every column, a power of two
// from kMinBlock particles up to the top block, handed out by a buddy allocator (lowest address
// first; two free neighbours of one size merge again). A request the store cannot meet (larger
// than a top block, or the store full: pow2 rounding lets pools hold up to twice their
// particles) is left to the heap by the pool, and counted. Where a pool's arrays live changes
// no simulated value: each pool's columns are contiguous either way.
//
// Example, compiled as ParticleStoreExample.TakeAndGiveBack in tests/unit/particles/test_examples.cpp:
//   ParticleStore store(budget);
//   ParticleBlock b = store.take(300);           // b.capacity == 512, or 0 when none is free
//   std::byte* px = store.column(0);              // ParticlePool binds its columns (particle_pool.h)
//   store.give_back(b);
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <set>
#include <vector>

namespace arc {

// Bytes per element of each ParticlePool column, in its order (particle_pool.h): 20 floats,
// 3 uint32, a uint16 and a uint8. Sizes fall, so a column laid out after another stays aligned.
inline constexpr uint8_t kParticleColumnBytes[] = {4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4,
                                                   4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 2, 1};
inline constexpr size_t kParticleColumns = sizeof(kParticleColumnBytes);
inline constexpr size_t kParticleBytes = 95;  // the sum of kParticleColumnBytes

// Where column `i` starts in a block laid out for `capacity` particles (the store's, or a heap
// pool's), and the block's size. Each column is set 320 bytes further on than the columns
// before it end: with a power-of-two stride all 25 columns of a particle fall in one cache set
// and alias in the low address bits, and the compaction in ParticlePool::retire ran 3x slower.
inline constexpr size_t kParticleColumnStagger = 320;
inline size_t particle_column_offset(size_t i, size_t capacity) {
  size_t at = 0;
  for (size_t c = 0; c < i; ++c) at += kParticleColumnBytes[c] * capacity + kParticleColumnStagger;
  return at;
}
inline size_t particle_block_bytes(size_t capacity) { return particle_column_offset(kParticleColumns, capacity); }

// A range of particles [first, first + capacity) in every column of a store; capacity 0 = none.
struct ParticleBlock {
  uint32_t first = 0;
  uint32_t capacity = 0;
};

class ParticleStore {
 public:
  static constexpr uint32_t kMinBlock = 16;     // particles; keeps every column's block 64-byte aligned
  static constexpr uint32_t kTopBlock = 16384;  // the largest block (1.5 MiB): larger pools use the heap

  // Room for `particles` (at least one block), rounded up to whole top blocks of the budget's size.
  explicit ParticleStore(uint32_t particles);
  ParticleStore(const ParticleStore&) = delete;
  ParticleStore& operator=(const ParticleStore&) = delete;

  // The smallest free block of at least `particles`, or {0, 0} when none is free.
  ParticleBlock take(uint32_t particles);
  void give_back(ParticleBlock block);

  // Column `i` (ParticlePool's order) of the whole store: `capacity()` elements of its type.
  std::byte* column(size_t i) const { return bytes_.get() + column_offset_[i]; }
  uint32_t capacity() const { return capacity_; }
  uint32_t top_block() const { return top_; }
  uint32_t in_use() const { return in_use_; }    // particles' room handed out now
  uint64_t refusals() const { return refusals_; }  // take() calls answered with no block
  size_t bytes() const { return bytes_size_; }

 private:
  int order_of(uint32_t capacity) const;

  uint32_t top_ = kTopBlock;
  uint32_t capacity_ = 0;
  int top_order_ = 0;
  std::unique_ptr<std::byte[]> bytes_;
  size_t bytes_size_ = 0;
  std::vector<size_t> column_offset_;
  std::vector<std::set<uint32_t>> free_;  // by order: first particle of each free block
  uint32_t in_use_ = 0;
  uint64_t refusals_ = 0;
};

}  // namespace arc
