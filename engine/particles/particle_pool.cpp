#include "particles/particle_pool.h"

#include <algorithm>
#include <type_traits>

#include "core/hash.h"

namespace arc {
namespace {

template <typename Pool, typename F>
void for_each_array(Pool& p, F&& f) {
  f(p.px), f(p.py), f(p.pz), f(p.size), f(p.rotation), f(p.r), f(p.g), f(p.b), f(p.a), f(p.burn);
  f(p.p0x), f(p.p0y), f(p.p0z), f(p.vx), f(p.vy), f(p.vz), f(p.reach), f(p.size0), f(p.rot0), f(p.spin);
  f(p.birth), f(p.death), f(p.uid), f(p.sprite), f(p.flags);
}

}  // namespace

void ParticlePool::reserve(size_t n) {
  for_each_array(*this, [n](auto& v) { v.reserve(n); });
}

void ParticlePool::resize(size_t n) {
  if (n == count()) return;
  if (n < deaths_known_) touch();
  for_each_array(*this, [n](auto& v) { v.resize(n); });
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
