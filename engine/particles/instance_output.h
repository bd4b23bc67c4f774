// particles/instance_output.h — internal: turns one cluster's animated particles into the
// camera-relative ParticleInstances the renderer draws (ParticleWorld::collect's inner loop).
#pragma once
#include <cstdint>
#include <vector>
#include <glm/vec3.hpp>

#include "particles/cluster.h"
#include "particles/particle_world.h"
#include "particles/render_output.h"

namespace arc {

// Appends the visible particles of `pool` (the cluster's state at cluster age `age` ticks),
// placed in `frame`, relative to the camera; `cluster_id` is the cluster's slot + 1.
// Lightning segments and velocity billboards ("billboard": "velocity") go out axis-locked: a
// segment along its own vector, a streak along the particle's velocity relative to the camera
// × the cluster's stretch, ending at the particle (the quad's centre half a streak behind it).
void append_instances(const Cluster& c, const ParticlePool& pool, const Pose& frame, const ParticleCamera& camera,
                      uint32_t age, uint32_t cluster_id, std::vector<ParticleInstance>& out);

}  // namespace arc
