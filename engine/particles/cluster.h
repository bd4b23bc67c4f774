// particles/cluster.h — a cluster (Hadwiger 2000 §4.3): the state its particles share.
//
// Centre and orientation (its frame), the animation from its definition, the owner it is
// attached to, the emitter's running state, the lightning channel, and a bounding sphere for
// culling. Its particles live in its own SoA pool. Internal to ParticleWorld.
#pragma once
#include <cstdint>
#include <memory>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "particles/animation.h"
#include "particles/effect_def.h"
#include "particles/lightning_channel.h"
#include "particles/particle_pool.h"

namespace arc {

struct Pose {
  glm::dvec3 position{0.0};
  glm::dquat orientation{1, 0, 0, 0};
};

struct Cluster {
  uint32_t generation = 0;
  bool alive = false;
  uint64_t serial = 0;                  // RNG stream: never reused, unlike the slot
  const EffectDef* effect = nullptr;
  uint32_t def_index = 0;
  const ClusterDef* def = nullptr;
  std::shared_ptr<const MotionTable> motion;  // linear clusters
  uint64_t spawn_tick = 0;              // the tick at which the cluster's age is 0
  uint32_t owner = 0;
  glm::dvec3 local_position{0.0};       // relative to the owner (or the world without one)
  glm::dquat local_orientation{1, 0, 0, 0};
  glm::dvec3 world_origin{0.0};         // frame origin of world-space linear clusters (fixed at spawn)
  glm::dvec3 spawn_velocity{0.0};
  glm::dvec3 last_emit_position{0.0};   // world; trails spread a tick's particles back to here
  double scale = 1.0;
  double intensity = 1.0;
  int priority = 1;
  double emit_accumulator = 0.0;        // fractional particles (of rate and spacing) carried to the next tick
  bool emitting = true;
  uint32_t next_uid = 0;
  glm::dvec3 flash_direction{0.0, 0.0, -1.0};  // cluster frame
  uint64_t flash_tick = 0;
  uint32_t flash_ticks = 0;
  LightningChannel lightning;
  uint64_t animated_tick = 0;           // the tick the pool's current state belongs to
  bool culled = false;
  glm::dvec3 bound_center{0.0};         // cluster frame
  double bound_radius = 0.0;
  uint64_t bound_changes = UINT64_MAX;  // pool.changes() and margin the linear bound was made for
  double bound_margin = -1.0;
  ParticlePool pool;
};

}  // namespace arc
