// particles/world_state.h — the dynamic state of a ParticleWorld as plain data (internal).
//
// ParticleWorld::Impl (particle_world.cpp) derives from this struct, so the snapshot code
// (particle_serialize.cpp) can read and replace the whole state without seeing the rest of
// the implementation. Everything here is simulation state except `effects` (the immutable
// library the clusters' definitions live in) and `motion_tables` (a cache: each table is a
// pure function of its key).
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "particles/animation.h"
#include "particles/cluster.h"
#include "particles/particle_world.h"

namespace arc {

struct ParticleWorldState {
  ParticleConfig config;
  const EffectLibrary* effects = nullptr;
  std::vector<Cluster> slots;
  std::vector<uint32_t> free_slots;
  std::map<uint32_t, OwnerTransform> owners;
  std::map<std::pair<double, double>, std::shared_ptr<const MotionTable>> motion_tables;  // by (drag, longest life)
  uint64_t tick = 0;
  uint64_t next_serial = 1;
  uint32_t live_particles = 0;
  uint64_t refused = 0;
  uint32_t skipped = 0;

  double h() const { return config.tick_seconds; }

  // The motion table of a linear cluster definition, shared by every cluster with the same key.
  std::shared_ptr<const MotionTable> motion_table(const ClusterDef& d) {
    const auto key = std::make_pair(d.linear.drag, d.particles.lifetime.max);
    auto it = motion_tables.find(key);
    if (it != motion_tables.end()) return it->second;
    auto t = MotionTable::build(d.linear.drag, h(), d.particles.lifetime.max);
    motion_tables.emplace(key, t);
    return t;
  }
};

// Every particle of a pool folded into `h` (the full hash); particle_serialize.cpp. Words go
// through a local FastHasher (particles/fast_hash.h), several times faster than StateHasher.
void hash_pool(const ParticlePool& pool, StateHasher& h);

// The snapshot code's way in (a friend of ParticleWorld); defined in particle_world.cpp.
struct ParticleWorldAccess {
  static ParticleWorldState& state(ParticleWorld& w);
  static const ParticleWorldState& state(const ParticleWorld& w);
};

}  // namespace arc
