// particles/animation.h — the animation types of Hadwiger 2000 §4.2 as closed forms and kernels.
//
// Every state is a pure function of a particle's birth state and its age in ticks, so a
// cluster that skipped ticks (culled) is brought to the current tick by the same arithmetic
// that animates a visible one — bit for bit the same result.
//   linear:   x(t) = x0 + v0·g(t) + a·f(t), g = −expm1(−k t)/k, f = (t − g)/k (exact drag k)
//   sphere:   p = R(t) · Rot(n) · d0, with stochastic d0 re-drawn every tick, rotational
//             Rot(n) = the per-tick pitch/yaw/roll rotation applied n times (one angle-axis)
//   radius:   constant, pulsating (sine), contracting (grow, hold, shrink), exploding (linear growth)
// The kernels are plain loops over the pool's float arrays.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "particles/effect_def.h"
#include "particles/particle_pool.h"

namespace arc {

// Drag coefficient functions (limits taken as k → 0).
double drag_g(double k, double t);  // displacement per unit initial velocity
double drag_f(double k, double t);  // displacement per unit acceleration
double drag_velocity_factor(double k, double t);  // e^(−k t)

// g and f for ages 0..N ticks, shared by every cluster of one definition.
struct MotionTable {
  std::vector<float> g, f;
  static std::shared_ptr<const MotionTable> build(double drag, double tick_seconds, double max_lifetime_seconds);
  uint32_t last() const { return uint32_t(g.size() - 1); }
};

double sphere_radius(const SphereDef& s, double scale, double age_seconds, double cluster_lifetime);
// Rotation after n ticks of fixed per-tick pitch (x), yaw (y) and roll (z) angles.
glm::dquat sphere_rotation(const glm::dvec3& rate_per_second, double tick_seconds, uint64_t n);

struct CurveSet {
  const Curve* size;
  const Curve* red;
  const Curve* green;
  const Curve* blue;
  const Curve* alpha;
  const Curve* burn;
};

// Linear motion of particles [0, n): positions from birth state and the motion table.
void animate_linear(ParticlePool& pool, uint32_t now, const MotionTable& table, const glm::vec3& acceleration);
// Sphere cluster positions: radius · rotation · direction.
void animate_sphere(ParticlePool& pool, float radius, const glm::mat3& rotation);
// Stochastic sphere: directions re-drawn on the sphere for this tick from (seed, stream, tick, uid).
void animate_sphere_stochastic(ParticlePool& pool, float radius, uint64_t seed, uint64_t stream, uint64_t tick);
// Size, rotation, colour, alpha and burn over each particle's life.
void animate_attributes(ParticlePool& pool, uint32_t now, double tick_seconds, const CurveSet& curves, float intensity,
                        float cluster_life_t);

}  // namespace arc
