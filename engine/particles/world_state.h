// particles/world_state.h — the dynamic state of a ParticleWorld as plain data (internal).
//
// ParticleWorld::Impl (particle_world.cpp) derives from this struct, so the snapshot code
// (particle_serialize.cpp) can read and replace the whole state without seeing the rest of
// the implementation. Everything here is simulation state except `effects` (the immutable
// library the clusters' definitions live in) and `motion_tables` (a cache: each table is a
// pure function of its key). The queries on it (owner and emitter poses, budget limits) are
// shared by the world and the emission code (emission.cpp).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "particles/animation.h"
#include "particles/cluster.h"
#include "particles/particle_world.h"

namespace arc {

// Clusters whose particles live in a moving frame: owner-space linear, spheres and lightning.
inline bool moves_with_frame(const Cluster& c) { return c.def->owner_space || c.def->animation != AnimationType::Linear; }

// A duration in whole ticks (at least one); 0 s or less is kNeverDies.
inline uint32_t life_ticks(double seconds, double h) {
  if (seconds <= 0.0) return kNeverDies;
  return uint32_t(std::clamp<double>(std::llround(seconds / h), 1.0, double(kNeverDies / 2)));
}

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

  Pose owner_pose(uint32_t owner) const {
    if (owner == 0) return {};
    auto it = owners.find(owner);
    if (it == owners.end()) return {};
    return {it->second.position, it->second.orientation};
  }
  glm::dvec3 owner_velocity(const Cluster& c) const {
    if (c.owner == 0) return c.spawn_velocity;
    auto it = owners.find(c.owner);
    return it == owners.end() ? glm::dvec3(0.0) : it->second.velocity;
  }
  Pose emitter_pose(const Cluster& c) const {
    const Pose o = owner_pose(c.owner);
    return {o.position + o.orientation * c.local_position, o.orientation * c.local_orientation};
  }

  uint32_t budget_limit(int priority) const {
    // Policy: cosmetic particles (priority 0) are refused once 90% of the budget is live, so
    // explosions and beams keep the last tenth; everything is refused at the budget.
    return priority == 0 ? uint32_t(uint64_t(config.budget) * 9 / 10) : config.budget;
  }

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

// The world's counters, owner transforms and slot table, then for every live cluster all that
// its particles are a closed-form function of (RNG stream, definition, age origin, frame,
// emitter state, counters). Shared by the full hash (ParticleWorld::hash, which adds the
// lightning polylines, bounds and every particle) and the per-tick summary
// (ParticleWorld::hash_summary, which adds the particle counts); Hasher is StateHasher or
// FastHasher. `per_cluster(c)` runs after each live cluster's fields.
template <class Hasher, class PerCluster>
void hash_world_state(const ParticleWorldState& w, Hasher& h, PerCluster&& per_cluster) {
  h.add_u64(w.tick);
  h.add_u64(w.next_serial);
  h.add_u64(w.live_particles);
  h.add_u64(w.refused);
  h.add_u64(w.skipped);
  h.add_u64(w.owners.size());
  for (const auto& [id, t] : w.owners) {
    h.add_u64(id);
    h.add_vec(t.position);
    h.add_quat(t.orientation);
    h.add_vec(t.velocity);
  }
  h.add_u64(w.slots.size());
  h.add_u64(w.free_slots.size());
  for (uint32_t s : w.free_slots) h.add_u64(s);
  for (const Cluster& c : w.slots) {
    h.add_u64((uint64_t(c.generation) << 1) | uint64_t(c.alive));
    if (!c.alive) continue;
    h.add_u64(c.serial);
    h.add_str(c.effect->name);
    h.add_u64(c.def_index);
    h.add_u64(c.spawn_tick);
    h.add_u64(c.owner);
    h.add_vec(c.local_position);
    h.add_quat(c.local_orientation);
    h.add_vec(c.world_origin);
    h.add_vec(c.spawn_velocity);
    h.add_vec(c.last_emit_position);
    h.add_f64(c.scale);
    h.add_f64(c.intensity);
    h.add_i64(c.priority);
    h.add_u64((uint64_t(c.next_uid) << 1) | uint64_t(c.emitting));
    h.add_f64(c.emit_accumulator);
    h.add_u64(c.flash_tick);
    h.add_u64(c.flash_ticks);
    h.add_vec(c.flash_direction);
    h.add_u64(c.lightning.epoch);
    h.add_f64(c.lightning.cut);
    h.add_vec(c.lightning.origin);
    h.add_vec(c.lightning.direction);
    h.add_u64(c.lightning.points.size());
    h.add_u64((c.animated_tick << 1) | uint64_t(c.culled));
    per_cluster(c);
  }
}

// Every particle of a pool folded into `h` (the full hash); particle_serialize.cpp. Words go
// through a local FastHasher (core/fast_hash.h), several times faster than StateHasher.
void hash_pool(const ParticlePool& pool, StateHasher& h);

// The snapshot code's way in (a friend of ParticleWorld); defined in particle_world.cpp.
struct ParticleWorldAccess {
  static ParticleWorldState& state(ParticleWorld& w);
  static const ParticleWorldState& state(const ParticleWorld& w);
};

}  // namespace arc
