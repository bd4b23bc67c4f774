// particles/particle_serialize.cpp — ParticleWorld snapshots and hashes.
//
// Format (version 1), inside the frame of core/snapshot_io.h, all little-endian:
//   config: seed u64, budget u32, cull_distance f64, lightning_interval i32, tick_seconds f64
//   counters: tick u64, next_serial u64, live_particles u32, refused u64, skipped u32
//   owners: count u32, then (id u32, position 3×f64, orientation 4×f64, velocity 3×f64)
//   slots: count u32, then each cluster slot's fields in the order of its field visitor
//     (particles/world_state.h); a particle pool is its count u32 and every SoA array in
//     ParticlePool order
//   free list: count u32, then slot indices u32
// Definitions are named, never pointed to: a snapshot loads into any world whose effect
// library has the same effects (cluster names are checked).
#include <algorithm>
#include <cmath>
#include <string_view>
#include <type_traits>

#include "core/hash.h"
#include "core/fast_hash.h"
#include "particles/effect_library.h"
#include "particles/particle_world.h"
#include "core/snapshot_io.h"
#include "core/state_fields.h"
#include "particles/world_state.h"

namespace arc {
namespace {

constexpr uint64_t kMagic = snapshot::magic("ARCPWRLD");
constexpr uint32_t kVersion = 1;

template <typename Pool, typename F>
void for_each_array(Pool& p, F&& f) {
  f(p.px), f(p.py), f(p.pz), f(p.size), f(p.rotation), f(p.r), f(p.g), f(p.b), f(p.a), f(p.burn);
  f(p.p0x), f(p.p0y), f(p.p0z), f(p.vx), f(p.vy), f(p.vz), f(p.reach), f(p.size0), f(p.rot0), f(p.spin);
  f(p.birth), f(p.death), f(p.uid), f(p.sprite), f(p.flags);
}

}  // namespace

// ---------------------------------------------------------------- leaf encodings

// Found by the field visitors' hashing and writing (argument-dependent lookup, hence namespace
// arc rather than an unnamed namespace); read back by ClusterReading below.
template <class Hasher>
static void hash_leaf(Hasher& h, const EffectDef* effect) {
  h.add_str(effect->name);
}
// Every particle: words through a local FastHasher, several times faster than StateHasher.
static void hash_leaf(StateHasher& h, const ParticlePool& pool) {
  FastHasher f;
  f.add_u64(pool.count());
  for_each_array(pool, [&f](const auto& v) {
    for (auto x : v) {
      if constexpr (std::is_same_v<std::decay_t<decltype(x)>, float>) f.add_f32(x);
      else f.add_u64(x);
    }
  });
  h.add_u64(f.value());
}
static void write_leaf(snapshot::Writer& out, const EffectDef* effect) { out.str(effect->name); }
static void write_leaf(snapshot::Writer& out, const ClusterDef* def) { out.str(def->name); }
static void write_leaf(snapshot::Writer& out, const ParticlePool& pool) {
  out.u32(uint32_t(pool.count()));
  for_each_array(pool, [&out](const auto& v) { out.array(std::span(v.data(), v.size())); });
}

namespace {

// Reads a cluster slot (fields::FieldReader's context): definitions by name from this world's
// library, the particle pool, and the checks the engine's indexing and arithmetic rely on.
struct ClusterReading {
  ParticleWorldState& w;
  Cluster* cluster = nullptr;
  size_t slot = 0;

  std::string where() const { return "cluster slot " + std::to_string(slot) + ": "; }

  void read_leaf(snapshot::Reader& in, const char*, const EffectDef*& effect) {
    const std::string name = in.str();
    if (!w.effects || !w.effects->has(name)) in.fail(where() + "effect '" + name + "' is not in this build's effect library");
    effect = &w.effects->get(name);
  }
  void read_leaf(snapshot::Reader& in, const char*, const ClusterDef*& def) {
    const Cluster& c = *cluster;
    if (c.def_index >= c.effect->clusters.size())
      in.fail(where() + "effect '" + c.effect->name + "' has " + std::to_string(c.effect->clusters.size()) +
              " clusters, the snapshot names cluster " + std::to_string(c.def_index));
    def = &c.effect->clusters[c.def_index];
    const std::string name = in.str();
    if (name != def->name)
      in.fail(where() + "cluster " + std::to_string(c.def_index) + " of effect '" + c.effect->name + "' is '" + def->name +
              "' in this build, '" + name + "' in the snapshot");
  }
  void read_leaf(snapshot::Reader& in, const char*, ParticlePool& pool) {
    const size_t n = in.count(kParticleBytes, "particle count");
    pool = ParticlePool(w.store.get());
    pool.resize(n);
    for_each_array(pool, [&in, n](auto& v) { in.array(std::span(v.data(), n)); });
    pool.touch();
  }
  void after_read(snapshot::Reader& in, Cluster& c) {
    if (!c.alive) return;
    c.bound_changes = UINT64_MAX;  // the bound was read with the particles; made anew on the next step
    if (c.serial == 0 || c.serial >= w.next_serial)
      in.fail(where() + "serial " + std::to_string(c.serial) + " is outside 1.." + std::to_string(w.next_serial - 1));
    if (c.def->animation == AnimationType::Linear) c.motion = w.motion_table(*c.def);
    check_values(in, c);
    check_particles(in, c);
  }
  // Values the engine divides by, loops on or counts with: a channel is built by adding
  // segments of seed_length·scale until max_length·scale, an emitter emits intensity·rate.
  void check_values(snapshot::Reader& in, const Cluster& c) const {
    if (!(c.scale > 0.0) || !std::isfinite(c.scale)) in.fail(where() + "scale " + std::to_string(c.scale) + " is not a positive number");
    if (!(c.intensity >= 0.0) || !std::isfinite(c.intensity))
      in.fail(where() + "intensity " + std::to_string(c.intensity) + " is not a number >= 0");
    if (!(c.emit_accumulator >= 0.0 && c.emit_accumulator < 1.0))
      in.fail(where() + "emitter accumulator " + std::to_string(c.emit_accumulator) + " is outside [0, 1)");
    if (std::isnan(c.lightning.cut)) in.fail(where() + "lightning cut is not a number");
    if (c.spawn_tick > w.tick + 1)
      in.fail(where() + "spawn tick " + std::to_string(c.spawn_tick) + " is after the world's tick " + std::to_string(w.tick) + " + 1");
  }
  // The invariants the engine indexes by: a channel has a polyline with a segment per particle.
  void check_particles(snapshot::Reader& in, const Cluster& c) const {
    const size_t points = c.lightning.points.size(), n = c.pool.count();
    if (c.def->animation == AnimationType::Lightning && (points < 2 || n > points - 1))
      in.fail(where() + "lightning channel with " + std::to_string(points) + " points and " + std::to_string(n) + " particles");
    for (size_t i = 0; i < n; ++i) {
      if (c.pool.sprite[i] != c.def->sprite)
        in.fail(where() + "particle " + std::to_string(i) + " has sprite " + std::to_string(c.pool.sprite[i]) + ", its definition " +
                std::to_string(c.def->sprite));
      if (c.pool.flags[i] & ~uint8_t(kParticleHidden))
        in.fail(where() + "particle " + std::to_string(i) + " has unknown flags " + std::to_string(c.pool.flags[i]));
    }
  }
};

// The world's counters, owner transforms and slot table, then every cluster slot: the words
// both hashes take, then those of hash pass `Pass` (summary or full). Hasher is FastHasher or
// StateHasher.
template <int Pass, class Hasher>
void hash_world_state(const ParticleWorldState& w, Hasher& h) {
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
    fields::hash_pass<kClusterHashPass>(h, c);
    fields::hash_pass<Pass>(h, c);
  }
}

}  // namespace

std::vector<uint8_t> ParticleWorld::save() const {
  const ParticleWorldState& w = ParticleWorldAccess::state(*this);
  snapshot::Writer out;
  out.u64(w.config.seed);
  out.u32(w.config.budget);
  out.f64(w.config.cull_distance);
  out.i32(w.config.lightning_interval);
  out.f64(w.config.tick_seconds);
  out.u64(w.tick);
  out.u64(w.next_serial);
  out.u32(w.live_particles);
  out.u64(w.refused);
  out.u32(w.skipped);
  out.u32(uint32_t(w.owners.size()));
  for (const auto& [id, t] : w.owners) {
    out.u32(id);
    out.vec3(t.position);
    out.quat(t.orientation);
    out.vec3(t.velocity);
  }
  out.u32(uint32_t(w.slots.size()));
  for (const Cluster& c : w.slots) fields::write_value(out, c);
  out.u32(uint32_t(w.free_slots.size()));
  for (uint32_t s : w.free_slots) out.u32(s);
  return out.framed(kMagic, kVersion);
}

void ParticleWorld::load(const std::vector<uint8_t>& bytes) { load(bytes.data(), bytes.size()); }

void ParticleWorld::load(const uint8_t* data, size_t size) {
  ParticleWorldState& live = ParticleWorldAccess::state(*this);
  snapshot::Reader in = snapshot::Reader::unframe(data, size, kMagic, kVersion, "particle world");
  // Built aside and swapped in at the end: a bad snapshot leaves this world as it was.
  ParticleWorldState w;
  w.effects = live.effects;
  w.store = live.store;
  w.motion_tables = live.motion_tables;
  w.config.seed = in.u64();
  w.config.budget = in.u32();
  w.config.cull_distance = in.f64();
  w.config.lightning_interval = in.i32();
  w.config.tick_seconds = in.f64();
  if (w.config.budget == 0 || w.config.budget > kMaxParticleBudget)
    in.fail("particle budget " + std::to_string(w.config.budget) + " is outside 1.." + std::to_string(kMaxParticleBudget));
  if (!(w.config.tick_seconds > 0.0) || !std::isfinite(w.config.tick_seconds))
    in.fail("tick length " + std::to_string(w.config.tick_seconds) + " s is not a positive number");
  if (w.config.tick_seconds != live.config.tick_seconds) w.motion_tables.clear();  // tables depend on the tick length
  if (w.config.lightning_interval < 0) in.fail("lightning interval " + std::to_string(w.config.lightning_interval) + " is negative");
  w.tick = in.u64();
  w.next_serial = in.u64();
  w.live_particles = in.u32();
  w.refused = in.u64();
  w.skipped = in.u32();
  const size_t owners = in.count(84, "owner count");
  for (size_t i = 0; i < owners; ++i) {
    const uint32_t id = in.u32();
    OwnerTransform t;
    t.position = in.vec3();
    t.orientation = in.quat();
    t.velocity = in.vec3();
    if (id == 0 || !w.owners.emplace(id, t).second) in.fail("owner id " + std::to_string(id) + " is 0 or repeated");
  }
  const size_t slots = in.count(5, "cluster slot count");
  w.reserve_slots();
  w.slots.resize(slots);
  uint64_t particles = 0;
  size_t dead = 0;
  ClusterReading reading{w};
  fields::FieldReader<ClusterReading> reader(in, reading);
  for (size_t s = 0; s < slots; ++s) {
    Cluster& c = w.slots[s];
    reading.cluster = &c;
    reading.slot = s;
    reader.read("cluster", c);
    if (c.alive) particles += c.pool.count();
    else ++dead;
  }
  if (particles != w.live_particles)
    in.fail("live particle count " + std::to_string(w.live_particles) + " differs from the " + std::to_string(particles) +
            " particles in the clusters");
  const size_t free = in.count(4, "free slot count");
  std::vector<bool> listed(slots, false);
  for (size_t i = 0; i < free; ++i) {
    const uint32_t s = in.u32();
    if (s >= slots || w.slots[s].alive || listed[s])
      in.fail("free list entry " + std::to_string(s) + " is not a dead slot listed once (" + std::to_string(slots) + " slots)");
    listed[s] = true;
    w.free_slots.push_back(s);
  }
  if (free != dead)
    in.fail("free list has " + std::to_string(free) + " entries for " + std::to_string(dead) + " dead slots");
  in.expect_end();
  live = std::move(w);
}

// Flattened, so the local hasher stays in registers through every cluster's words.
[[gnu::flatten]] void ParticleWorld::hash_summary(FastHasher& out) const {
  FastHasher h;  // local: kept in registers (fast_hash.h)
  hash_world_state<kSummaryHashPass>(ParticleWorldAccess::state(*this), h);
  out.add_u64(h.value());
}

void ParticleWorld::hash(StateHasher& h) const { hash_world_state<kFullHashPass>(ParticleWorldAccess::state(*this), h); }

}  // namespace arc
