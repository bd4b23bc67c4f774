// particles/instance_output.cpp — a cluster's particles as camera-relative ParticleInstances.
#include "particles/instance_output.h"

#include <algorithm>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

namespace arc {
namespace {

// The axis of a velocity billboard: velocity relative to the camera × stretch. A linear
// particle's velocity in closed form from the motion table: x' = v0·e^(−k t) + a·g(t) with
// e^(−k t) = 1 − k·g(t) (animation.h), so no exponential per particle.
struct StreakAxis {
  float drag;
  glm::vec3 acceleration, camera_velocity;
  float stretch;
  const MotionTable* motion;

  glm::vec3 at(const ParticlePool& pool, size_t i, uint32_t age) const {
    const uint32_t n = std::min(age - std::min(pool.birth[i], age), motion->last());
    const float g = motion->g[n];
    const glm::vec3 v0(pool.vx[i], pool.vy[i], pool.vz[i]);
    return (v0 * (1.0f - drag * g) + acceleration * g - camera_velocity) * stretch;
  }
};

}  // namespace

void append_instances(const Cluster& c, const ParticlePool& pool, const Pose& frame, const ParticleCamera& camera,
                      uint32_t age, uint32_t cluster_id, std::vector<ParticleInstance>& out) {
  const glm::vec3 offset(frame.position - camera.position);
  const glm::mat3 rot(glm::mat3_cast(frame.orientation));
  const ClusterDef& d = *c.def;
  const bool lightning = d.animation == AnimationType::Lightning;
  // The loader allows velocity billboards on world-space linear clusters only: identity frame.
  const bool streak = d.billboard == ClusterBillboard::Velocity && c.motion;
  const StreakAxis streak_axis{float(d.linear.drag), glm::vec3(d.linear.acceleration * c.scale), glm::vec3(camera.velocity),
                               float(d.stretch), c.motion.get()};
  const float soft_extent = float(d.soft_extent * c.scale);
  for (size_t i = 0; i < pool.count(); ++i) {
    const float a = pool.a[i];
    if ((pool.flags[i] & kParticleHidden) || !(a > 0.0f)) continue;
    ParticleInstance p{};
    glm::vec3 pos = offset + rot * glm::vec3(pool.px[i], pool.py[i], pool.pz[i]);
    glm::vec3 axis(0.0f);
    if (lightning) axis = rot * glm::vec3(pool.vx[i], pool.vy[i], pool.vz[i]);
    if (streak) {
      axis = streak_axis.at(pool, i, age);
      pos -= 0.5f * axis;
    }
    p.pos[0] = pos.x, p.pos[1] = pos.y, p.pos[2] = pos.z;
    p.size = std::max(pool.size[i], 1e-4f);
    p.axis[0] = axis.x, p.axis[1] = axis.y, p.axis[2] = axis.z;
    p.rotation = pool.rotation[i];
    p.color[0] = pool.r[i] * a, p.color[1] = pool.g[i] * a, p.color[2] = pool.b[i] * a, p.color[3] = a;
    p.burn = std::clamp(pool.burn[i], 0.0f, 1.0f);
    p.soft_extent = soft_extent;
    p.sprite = uint8_t(pool.sprite[i]);
    p.screen_priority = uint8_t(d.screen_priority);
    p.soft_edge = uint8_t(d.soft_edge);
    p.billboard = uint8_t(lightning || streak ? Billboard::AxisLocked : Billboard::CameraFacing);
    p.cluster = cluster_id;
    out.push_back(p);
  }
}

}  // namespace arc
