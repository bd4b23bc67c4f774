#include "particles/particle_pool.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#include "core/hash.h"

namespace arc {
namespace {

template <typename Pool, typename F>
void for_each_array(Pool& p, F&& f) {
  f(p.px), f(p.py), f(p.pz), f(p.size), f(p.rotation), f(p.r), f(p.g), f(p.b), f(p.a), f(p.burn);
  f(p.p0x), f(p.p0y), f(p.p0z), f(p.vx), f(p.vy), f(p.vz), f(p.reach), f(p.size0), f(p.rot0), f(p.spin);
  f(p.birth), f(p.death), f(p.uid), f(p.sprite), f(p.flags);
}

// A heap block laid out as a store's columns are, for `capacity` particles.
std::byte* heap_block(size_t capacity) {
  return static_cast<std::byte*>(::operator new(particle_block_bytes(capacity), std::align_val_t{64}));
}
void free_heap_block(std::byte* p) { ::operator delete(p, std::align_val_t{64}); }

template <typename Pool>
std::array<std::byte*, kParticleColumns> column_pointers(Pool& p) {
  std::array<std::byte*, kParticleColumns> out;
  size_t i = 0;
  for_each_array(p, [&](const auto& v) { out[i++] = reinterpret_cast<std::byte*>(const_cast<void*>(static_cast<const void*>(v.data()))); });
  return out;
}

}  // namespace

ParticlePool::ParticlePool(ParticleStore* store) : store_(store) {}

ParticlePool::ParticlePool(const ParticlePool& o) { *this = o; }

ParticlePool& ParticlePool::operator=(const ParticlePool& o) {
  if (this == &o) return *this;
  set_count(0);
  if (o.count() > capacity_) move_to(o.count());
  set_count(o.count());
  const auto to = column_pointers(*this);
  const auto from = column_pointers(o);
  if (count_)
    for (size_t i = 0; i < kParticleColumns; ++i) std::memcpy(to[i], from[i], count_ * kParticleColumnBytes[i]);
  deaths_known_ = o.deaths_known_;
  first_death_ = o.first_death_;
  changes_ = o.changes_;
  return *this;
}

ParticlePool::ParticlePool(ParticlePool&& o) noexcept { take_from(o); }

ParticlePool& ParticlePool::operator=(ParticlePool&& o) noexcept {
  if (this != &o) {
    free_storage();
    take_from(o);
  }
  return *this;
}

ParticlePool::~ParticlePool() { free_storage(); }

void ParticlePool::take_from(ParticlePool& o) {
  set_columns(column_pointers(o));
  store_ = o.store_, block_ = o.block_, heap_ = o.heap_;
  capacity_ = o.capacity_;
  set_count(o.count_);
  deaths_known_ = o.deaths_known_, first_death_ = o.first_death_, changes_ = o.changes_;
  o.block_ = {}, o.heap_ = nullptr, o.capacity_ = 0;
  o.set_columns({});
  o.set_count(0);
  o.deaths_known_ = 0, o.first_death_ = UINT32_MAX;
}

void ParticlePool::set_columns(const std::array<std::byte*, kParticleColumns>& data) {
  size_t i = 0;
  for_each_array(*this, [&](auto& v) { v.data_ = reinterpret_cast<std::remove_reference_t<decltype(v[0])>*>(data[i++]); });
}

void ParticlePool::free_storage() {
  if (block_.capacity) store_->give_back(block_);
  if (heap_) free_heap_block(heap_);
  block_ = {}, heap_ = nullptr, capacity_ = 0;
  set_columns({});
  set_count(0);
}

void ParticlePool::set_count(size_t n) {
  count_ = n;
  for_each_array(*this, [n](auto& v) { v.size_ = n; });
}

void ParticlePool::move_to(size_t capacity, bool heap_allowed) {
  ParticleBlock block;
  if (store_ && capacity <= UINT32_MAX) block = store_->take(uint32_t(capacity));
  if (!block.capacity && !heap_allowed) return;
  std::byte* heap = block.capacity ? nullptr : heap_block(capacity);
  const auto from = column_pointers(*this);
  std::array<std::byte*, kParticleColumns> to;
  for (size_t i = 0; i < kParticleColumns; ++i) {
    const size_t bytes = kParticleColumnBytes[i];
    to[i] = block.capacity ? store_->column(i) + size_t(block.first) * bytes : heap + particle_column_offset(i, capacity);
    if (count_) std::memcpy(to[i], from[i], count_ * bytes);
  }
  set_columns(to);
  if (block_.capacity) store_->give_back(block_);
  if (heap_) free_heap_block(heap_);
  block_ = block, heap_ = heap;
  capacity_ = block.capacity ? block.capacity : capacity;
}

void ParticlePool::reserve(size_t n) {
  if (n > capacity_) move_to(n);
}

void ParticlePool::reserve_in_store(size_t n) {
  if (n > capacity_) move_to(n, false);
}

void ParticlePool::resize(size_t n) {
  if (n == count()) return;
  if (n < deaths_known_) touch();
  if (n > capacity_) move_to(std::max({n, capacity_ * 2, size_t(ParticleStore::kMinBlock)}));
  const size_t old = count_;
  if (n > old) {
    const auto to = column_pointers(*this);
    for (size_t i = 0; i < kParticleColumns; ++i)
      std::memset(to[i] + old * kParticleColumnBytes[i], 0, (n - old) * kParticleColumnBytes[i]);
  }
  set_count(n);
  ++changes_;
}

void ParticlePool::touch() {
  deaths_known_ = 0;
  first_death_ = UINT32_MAX;
  ++changes_;
}

void ParticlePool::clear() { resize(0); }

size_t ParticlePool::retire(uint32_t now) {
  const size_t n = count();
  for (size_t i = deaths_known_; i < n; ++i) first_death_ = std::min(first_death_, death[i]);
  deaths_known_ = n;
  if (first_death_ > now) return 0;
  size_t first = 0;
  while (first < n && death[first] > now) ++first;
  if (first == n) return 0;
  size_t w = first;
  for (size_t i = first; i < n; ++i) {
    if (death[i] <= now) continue;
    for_each_array(*this, [i, w](auto& v) { v[w] = v[i]; });
    ++w;
  }
  resize(w);
  return n - w;
}

void ParticlePool::hash(StateHasher& h) const {
  h.add_u64(count());
  for_each_array(*this, [&h](const auto& v) {
    for (auto x : v) {
      if constexpr (std::is_same_v<std::decay_t<decltype(x)>, float>) h.add_f32(x);
      else h.add_u64(x);
    }
  });
}

}  // namespace arc
