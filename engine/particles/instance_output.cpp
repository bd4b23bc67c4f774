// particles/instance_output.cpp — a cluster's particles as camera-relative ParticleInstances.
#include "particles/instance_output.h"

#include <algorithm>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

namespace arc {

void append_instances(const Cluster& c, const ParticlePool& pool, const Pose& frame, const glm::dvec3& camera_position,
                      uint32_t cluster_id, std::vector<ParticleInstance>& out) {
  const glm::vec3 offset(frame.position - camera_position);
  const glm::mat3 rot(glm::mat3_cast(frame.orientation));
  const ClusterDef& d = *c.def;
  const bool lightning = d.animation == AnimationType::Lightning;
  const float soft_extent = float(d.soft_extent * c.scale);
  for (size_t i = 0; i < pool.count(); ++i) {
    const float a = pool.a[i];
    if ((pool.flags[i] & kParticleHidden) || !(a > 0.0f)) continue;
    ParticleInstance p{};
    const glm::vec3 pos = offset + rot * glm::vec3(pool.px[i], pool.py[i], pool.pz[i]);
    p.pos[0] = pos.x, p.pos[1] = pos.y, p.pos[2] = pos.z;
    p.size = std::max(pool.size[i], 1e-4f);
    if (lightning) {
      const glm::vec3 axis = rot * glm::vec3(pool.vx[i], pool.vy[i], pool.vz[i]);
      p.axis[0] = axis.x, p.axis[1] = axis.y, p.axis[2] = axis.z;
    }
    p.rotation = pool.rotation[i];
    p.color[0] = pool.r[i] * a, p.color[1] = pool.g[i] * a, p.color[2] = pool.b[i] * a, p.color[3] = a;
    p.burn = std::clamp(pool.burn[i], 0.0f, 1.0f);
    p.soft_extent = soft_extent;
    p.sprite = pool.sprite[i];
    p.soft_edge = uint8_t(d.soft_edge);
    p.billboard = uint8_t(lightning ? Billboard::AxisLocked : Billboard::CameraFacing);
    p.cluster = cluster_id;
    out.push_back(p);
  }
}

}  // namespace arc
