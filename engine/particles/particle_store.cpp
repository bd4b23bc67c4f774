#include "particles/particle_store.h"

#include <algorithm>
#include <cstring>

namespace arc {

static_assert([] {
  size_t sum = 0;
  for (uint8_t b : kParticleColumnBytes) sum += b;
  return sum == kParticleBytes;
}());

ParticleStore::ParticleStore(uint32_t particles) {
  // The top block is the budget's next power of two when that is smaller, so a small budget
  // does not take a whole kTopBlock.
  top_ = kMinBlock;
  while (top_ < kTopBlock && top_ < particles) top_ *= 2;
  while ((kMinBlock << top_order_) < top_) ++top_order_;
  const uint64_t tops = (uint64_t(std::max<uint32_t>(particles, 1)) + top_ - 1) / top_;
  capacity_ = uint32_t(tops * top_);
  column_offset_.resize(kParticleColumns);
  for (size_t i = 0; i < kParticleColumns; ++i) column_offset_[i] = particle_column_offset(i, capacity_);
  bytes_size_ = particle_block_bytes(capacity_);
  bytes_.reset(new std::byte[bytes_size_]);
  // Written through now: the pages are resident from the first tick, whatever the battle asks later.
  std::memset(bytes_.get(), 0, bytes_size_);
  free_.resize(size_t(top_order_) + 1);
  for (uint64_t t = 0; t < tops; ++t) free_[size_t(top_order_)].insert(uint32_t(t * top_));
}

int ParticleStore::order_of(uint32_t capacity) const {
  int k = 0;
  while ((kMinBlock << k) < capacity) ++k;
  return k;
}

ParticleBlock ParticleStore::take(uint32_t particles) {
  const int want = order_of(std::max(particles, 1u));
  int have = want;
  while (have <= top_order_ && free_[size_t(have)].empty()) ++have;
  if (want > top_order_ || have > top_order_) {
    ++refusals_;
    return {};
  }
  auto& list = free_[size_t(have)];
  const uint32_t first = *list.begin();
  list.erase(list.begin());
  // Split down to the size asked for; the upper halves stay free.
  for (int k = have; k > want; --k) free_[size_t(k - 1)].insert(first + (kMinBlock << (k - 1)));
  const uint32_t capacity = kMinBlock << want;
  in_use_ += capacity;
  return {first, capacity};
}

void ParticleStore::give_back(ParticleBlock block) {
  if (block.capacity == 0) return;
  in_use_ -= block.capacity;
  uint32_t first = block.first;
  int k = order_of(block.capacity);
  const uint32_t top_start = first - first % top_;
  while (k < top_order_) {
    const uint32_t size = kMinBlock << k;
    const uint32_t buddy = top_start + ((first - top_start) ^ size);
    auto it = free_[size_t(k)].find(buddy);
    if (it == free_[size_t(k)].end()) break;
    free_[size_t(k)].erase(it);
    first = std::min(first, buddy);
    ++k;
  }
  free_[size_t(k)].insert(first);
}

}  // namespace arc
