// particles/particle_world.h — the particle engine's public interface (no GL).
//
// Particles live in structure-of-arrays pools and belong to clusters (Hadwiger 2000 §4.3). A
// cluster shares centre, radius, animation and owner; clusters are named by typed handles
// {index, generation}, zero is null. Effects (assets/effects/*.json) are composites of
// emitters and clusters; the game spawns them by EffectId (resolved once from the name by the
// EffectLibrary) and may attach them to an OwnerId it allocates (a ship, a missile): an owner's
// transform moves and turns its clusters, and destroying the owner destroys them in the same
// tick. Ids are typed (particles/particle_ids.h), so an owner cannot be passed as an effect.
//
// Randomness is keyed by (seed, cluster id, tick, particle index), so results do not depend on
// update order, and clusters far from the camera may skip ticks and catch up exactly.
//
// Example, compiled as ParticleWorldExample.SpawnStepCollect in tests/unit/particles/test_examples.cpp:
//   EffectLibrary fx;
//   fx.load_directory("assets/effects");
//   ParticleWorld world(ParticleConfig{.seed = level_seed}, &fx);
//   const EffectId explosion = fx.id("ship_explosion");   // once, at load
//   EffectHandle boom = world.spawn(explosion, SpawnParams{.position = where});
//   ClusterHandle beam = world.spawn_lightning(fx.id("lightning_beam"), ship_owner, mount, forward);
//   world.set_owner_transform(ship_owner, OwnerTransform{ship_position, ship_rotation, ship_velocity});
//   world.step(tick, camera);
//   world.collect(camera, particles, drawn_owners);
#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "particles/particle_ids.h"
#include "particles/render_output.h"

namespace arc {

class StateHasher;
class FastHasher;
class EffectLibrary;

template <typename Tag>
struct Handle {
  uint32_t index = 0;       // slot + 1; 0 is null
  uint32_t generation = 0;
  explicit operator bool() const { return index != 0; }
  bool operator==(const Handle&) const = default;
};
struct ClusterTag;
using ClusterHandle = Handle<ClusterTag>;

// All clusters created by one spawn of a composite effect.
struct EffectHandle {
  std::vector<ClusterHandle> clusters;
};

struct OwnerTransform {
  glm::dvec3 position{0.0};
  glm::dquat orientation{1, 0, 0, 0};
  glm::dvec3 velocity{0.0};
};

struct SpawnParams {
  glm::dvec3 position{0.0};              // world, or owner-local when owner != 0
  glm::dquat orientation{1, 0, 0, 0};    // emitter frame (cone axis is local −Z, "forward")
  glm::dvec3 velocity{0.0};              // inherited by emitted particles
  OwnerId owner{};                       // null = free-floating; otherwise attached to that owner
  double scale = 1.0;                    // scales sizes, radii, speeds
  double intensity = 1.0;                // scales alpha and spawn counts
  int priority = 1;                      // 0 = cosmetic (refused first when the budget is full)
};

// The largest particle budget: the settings' range for particles.budget (core/settings.cpp), and
// what a snapshot may ask for, since a world writes its particle store through at its budget.
inline constexpr uint32_t kMaxParticleBudget = 4'000'000;

struct ParticleConfig {
  uint64_t seed = 1;
  uint32_t budget = 200000;          // live particles at most
  double cull_distance = 20000.0;    // clusters beyond this (or outside the frustum) skip ticks
  int lightning_interval = 0;        // 0 = each effect's own sizzle interval
  double tick_seconds = 1.0 / 60.0;
  // Clusters animated at once by step() on a oneTBB arena (0: every core). Clusters are
  // independent and keyed, so the state and its hash do not depend on it.
  int threads = 1;
};

struct ParticleStats {
  uint32_t live_particles = 0;
  uint32_t live_clusters = 0;
  uint64_t refused_particles = 0;  // spawns refused because the budget was full
  uint32_t skipped_clusters = 0;   // clusters not animated in the last step (culled)
  // What the last step did and left out ("model only what a scene requires"); diagnostics, not
  // state: not saved, not hashed.
  uint32_t skipped_particles = 0;  // particles of the culled clusters: none of them evaluated
  uint32_t animated_particles = 0; // particles the last step evaluated (position, size, colour)
  uint32_t caught_up_clusters = 0; // clusters animated after skipping one tick or more
  // The particle store (particle_store.h): room handed to pools now, the whole store, and the
  // live pools whose storage came from the heap (the store full, or a pool over a top block).
  uint32_t store_in_use = 0;
  uint32_t store_capacity = 0;
  uint32_t pools_on_heap = 0;
};

// Where an owner is drawn this frame: the renderer interpolates meshes between the last two
// ticks, so collect() can be told the same in-between pose for the owners it draws.
struct DrawnOwner {
  OwnerId owner{};
  glm::dvec3 position{0.0};
  glm::dquat orientation{1, 0, 0, 0};
};

// The view used for culling and for camera-relative output.
struct ParticleCamera {
  glm::dvec3 position{0.0};
  glm::dquat orientation{1, 0, 0, 0};
  double fov_y_radians = 1.0;
  double aspect = 16.0 / 9.0;
  double near_plane = 0.5;
  glm::dvec3 velocity{0.0};  // m/s: velocity-stretched particles streak along their motion relative to it
};

class ParticleStore;

class ParticleWorld {
 public:
  // The world makes its particle store (particle_store.h) at the budget, or takes `store` when
  // given one at least that large: a tool that remakes its world often (the workbench's
  // timeline, on every scrub back) keeps one store instead of writing a new one through each time.
  ParticleWorld(const ParticleConfig& config, const EffectLibrary* effects, std::shared_ptr<ParticleStore> store = nullptr);
  ~ParticleWorld();
  // The store its pools take their room from, to hand to the next world a tool makes.
  std::shared_ptr<ParticleStore> store() const;
  ParticleWorld(const ParticleWorld&);             // deep copy (serialization test)
  ParticleWorld& operator=(const ParticleWorld&);

  // Spawns every emitter and cluster of an effect of this world's library (InputError if the
  // id is not one of its effects). The by-name overloads look the name up on every call (tests,
  // tools); the game resolves its names to EffectIds once.
  EffectHandle spawn(EffectId effect, const SpawnParams& params);
  EffectHandle spawn(const std::string& effect, const SpawnParams& params);
  // A lightning channel (Hadwiger §5.2) from an owner-local origin along an owner-local direction.
  ClusterHandle spawn_lightning(EffectId effect, OwnerId owner, const glm::dvec3& local_origin,
                                const glm::dvec3& local_direction);
  ClusterHandle spawn_lightning(const std::string& effect, OwnerId owner, const glm::dvec3& local_origin,
                                const glm::dvec3& local_direction);
  void destroy(ClusterHandle cluster);
  void destroy(const EffectHandle& effect);
  void destroy_owner(OwnerId owner);  // every cluster attached to it, now
  // The owner is gone but its trail may fade: clusters that move with it are destroyed, the
  // others stop emitting and are detached, and the owner's transform is forgotten.
  void release_owner(OwnerId owner);
  bool alive(ClusterHandle cluster) const;
  uint32_t particle_count(ClusterHandle cluster) const;  // live particles of a cluster; 0 once it is gone

  // Owners' transforms for this tick; call before step().
  void set_owner_transform(OwnerId owner, const OwnerTransform& t);
  // Stops emitters of a cluster (particles already out live on); the cluster dies when empty.
  void stop_emitting(ClusterHandle cluster);
  void set_intensity(ClusterHandle cluster, double intensity);  // e.g. shield brightness
  // Shield flash: brightens particles of a sphere cluster near a world point, fading over `seconds`.
  void flash(ClusterHandle cluster, const glm::dvec3& world_point, double seconds);

  // Lightning: world-space polyline of the channel (seed segment first), the uncut length, and
  // the cut: particles farther than `distance` along the channel are not drawn.
  std::vector<glm::dvec3> lightning_points(ClusterHandle channel) const;
  double lightning_length(ClusterHandle channel) const;
  void cut_lightning(ClusterHandle channel, double distance);
  glm::dvec3 lightning_point_at(ClusterHandle channel, double distance) const;

  // Advances everything to `tick` (normally the previous tick + 1).
  void step(uint64_t tick, const ParticleCamera& camera);
  // Appends visible particles, camera-relative, culled by cluster. `drawn` (sorted by owner)
  // gives owners' drawn poses: clusters that move with an owner listed there are placed in
  // that pose instead of this tick's, so they sit on the owner's interpolated mesh.
  void collect(const ParticleCamera& camera, std::vector<ParticleInstance>& out,
               std::span<const DrawnOwner> drawn = {}) const;

  ParticleStats stats() const;
  void hash(StateHasher& h) const;  // everything, every particle included
  // Cheap: counters, owners and a per-cluster summary (serial, definition, spawn tick, owner,
  // frame, particle count, RNG and lightning-epoch counters, emitter accumulator). Particle
  // state is a closed-form function of these, so this is what a per-tick replay hash needs.
  void hash_summary(FastHasher& h) const;  // core/fast_hash.h
  uint64_t tick() const;

  // Snapshot of the whole dynamic state (particle_serialize.cpp): every cluster slot with its
  // generation, serial, owner, definition (by effect name and cluster index), pool and
  // lightning channel, the owners' transforms, the free list and the budget counters.
  // Versioned little-endian bytes with a checksum.
  std::vector<uint8_t> save() const;
  // Replaces the state with a snapshot's; definitions are looked up in this world's effect
  // library. A truncated, corrupt or foreign snapshot throws InputError("snapshot: ...") and
  // leaves the world unchanged.
  void load(const std::vector<uint8_t>& bytes);
  void load(const uint8_t* data, size_t size);

 private:
  friend struct ParticleWorldAccess;  // particles/world_state.h
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace arc
