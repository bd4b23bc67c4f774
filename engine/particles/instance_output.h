// particles/instance_output.h — internal: turns one cluster's animated particles into the
// camera-relative ParticleInstances the renderer draws (ParticleWorld::collect's inner loop).
#pragma once
#include <cstdint>
#include <vector>
#include <glm/vec3.hpp>

#include "particles/cluster.h"
#include "particles/render_output.h"

namespace arc {

// Appends the visible particles of `pool` (the cluster's state at the drawn tick), placed in
// `frame`, relative to `camera_position`; `cluster_id` is the cluster's slot + 1.
void append_instances(const Cluster& c, const ParticlePool& pool, const Pose& frame, const glm::dvec3& camera_position,
                      uint32_t cluster_id, std::vector<ParticleInstance>& out);

}  // namespace arc
