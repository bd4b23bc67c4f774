// particles/world_state.h — the dynamic state of a ParticleWorld as plain data (internal).
//
// ParticleWorld::Impl (particle_world.cpp) derives from this struct, so the snapshot and hash
// code (particle_serialize.cpp) can read and replace the whole state without seeing the rest of
// the implementation. Everything here is simulation state except `effects` (the immutable
// library the clusters' definitions live in) and `motion_tables` (a cache: each table is a
// pure function of its key). The queries on it (owner and emitter poses, budget limits) are
// shared by the world and the emission code (emission.cpp). A cluster's fields are listed once,
// by its field visitor below.
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
#include "core/state_fields.h"

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
  // Where the clusters' pools take their storage (particle_store.h), made at the budget with the
  // world. Shared, not copied: a copied world's pools are copies on the heap, and a snapshot
  // read builds its clusters aside in the same store. Declared before the slots, so it
  // outlives every pool that gives a block back to it.
  std::shared_ptr<ParticleStore> store;
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

  // The slot table is taken for a full budget's clusters (at 64 particles each, within
  // [256, 16384] slots) and written through at once, like the particle store: grown by
  // doubling, it would take a new block at each power of two of clusters seen, and the heap
  // would step up in the middle of a battle.
  void reserve_slots() {
    const size_t n = std::clamp<size_t>(config.budget / 64, 256, 16384);
    if (slots.capacity() >= n) return;
    const size_t used = slots.size();
    slots.resize(n);
    slots.resize(used);
  }

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

// Where the particle world's hashes take a cluster's fields: words both hashes take, then the
// words only the per-tick summary (ParticleWorld::hash_summary) or only the full hash
// (ParticleWorld::hash) adds. Word numbers are frozen: replays store these hashes.
inline constexpr int kClusterHashPass = 0;
inline constexpr int kSummaryHashPass = 1;
inline constexpr int kFullHashPass = 2;
template <int W, fields::HashAs As = fields::HashAs::value>
inline constexpr fields::HashAt<kClusterHashPass, W, As> cluster_hash;
template <int W, fields::HashAs As = fields::HashAs::value>
inline constexpr fields::HashAt<kSummaryHashPass, W, As> summary_only_hash;
template <int W, fields::HashAs As = fields::HashAs::value>
inline constexpr fields::HashAt<kFullHashPass, W, As> full_only_hash;

template <fields::MaybeConst<LightningChannel> L, class V>
void visit_fields(L& l, V&& v) {
  v("origin", l.origin, fields::saved, cluster_hash<2>);
  v("direction", l.direction, fields::saved, cluster_hash<3>);
  v("points", l.points, fields::saved, cluster_hash<4, fields::HashAs::count>, full_only_hash<0>);
  v("epoch", l.epoch, fields::saved, cluster_hash<0>);
  v("cut", l.cut, fields::saved, cluster_hash<1>);
}

// A cluster slot in snapshot order: a free slot keeps only its generation. Everything a live
// cluster's particles are a closed-form function of (RNG stream, definition, age origin, frame,
// emitter state, counters) is in both hashes; the full hash adds the lightning polyline, the
// bounds and every particle. Definitions are saved by name: a snapshot loads into any world
// whose effect library has the same effects.
template <fields::MaybeConst<Cluster> C, class V>
void visit_fields(C& c, V&& v) {
  v("generation", c.generation, fields::saved, cluster_hash<0, fields::HashAs::high_bits>);
  v("alive", c.alive, fields::saved, cluster_hash<0, fields::HashAs::low_bit>);
  if (!c.alive) return;
  v("serial", c.serial, fields::saved, cluster_hash<1>);
  v("effect", c.effect, fields::saved, cluster_hash<2>);
  v("def_index", c.def_index, fields::saved, cluster_hash<3>);
  v("def", c.def, fields::saved, fields::unhashed);            // its name, checked on load
  v("motion", c.motion, fields::not_saved, fields::unhashed);  // a table shared by definition and tick length
  v("spawn_tick", c.spawn_tick, fields::saved, cluster_hash<4>);
  v("owner", c.owner, fields::saved, cluster_hash<5>);
  v("local_position", c.local_position, fields::saved, cluster_hash<6>);
  v("local_orientation", c.local_orientation, fields::saved, cluster_hash<7>);
  v("world_origin", c.world_origin, fields::saved, cluster_hash<8>);
  v("spawn_velocity", c.spawn_velocity, fields::saved, cluster_hash<9>);
  v("last_emit_position", c.last_emit_position, fields::saved, cluster_hash<10>);
  v("scale", c.scale, fields::saved, cluster_hash<11>);
  v("intensity", c.intensity, fields::saved, cluster_hash<12>);
  v("priority", c.priority, fields::saved, cluster_hash<13>);
  v("emit_accumulator", c.emit_accumulator, fields::saved, cluster_hash<15>);
  v("emitting", c.emitting, fields::saved, cluster_hash<14, fields::HashAs::low_bit>);
  v("next_uid", c.next_uid, fields::saved, cluster_hash<14, fields::HashAs::high_bits>);
  v("flash_direction", c.flash_direction, fields::saved, cluster_hash<18>);
  v("flash_tick", c.flash_tick, fields::saved, cluster_hash<16>);
  v("flash_ticks", c.flash_ticks, fields::saved, cluster_hash<17>);
  v("lightning", c.lightning, fields::saved, cluster_hash<19>, full_only_hash<0>);
  v("animated_tick", c.animated_tick, fields::saved, cluster_hash<20, fields::HashAs::high_bits>);
  v("culled", c.culled, fields::saved, cluster_hash<20, fields::HashAs::low_bit>);
  v("bound_center", c.bound_center, fields::saved, full_only_hash<1>);
  v("bound_radius", c.bound_radius, fields::saved, full_only_hash<2>);
  v("bound_changes", c.bound_changes, fields::not_saved, fields::unhashed);  // when the bound was made
  v("bound_margin", c.bound_margin, fields::not_saved, fields::unhashed);
  v("pool", c.pool, fields::saved, summary_only_hash<0, fields::HashAs::count>, full_only_hash<3>);
}

// The snapshot code's way in (a friend of ParticleWorld); defined in particle_world.cpp.
struct ParticleWorldAccess {
  static ParticleWorldState& state(ParticleWorld& w);
  static const ParticleWorldState& state(const ParticleWorld& w);
};

}  // namespace arc
