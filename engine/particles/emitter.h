// particles/emitter.h — where a new particle starts and which way it goes.
//
// Shapes (particle slides): point, sphere volume, sphere surface, cone, box, line and mesh
// surface (triangle list, area-weighted). A sample is a pure function of the keyed RNG and a
// base index, so spawning order cannot change it. Positions and directions are in the
// emitter's frame; cones open around −Z ("forward").
#pragma once
#include <cstdint>
#include <glm/vec3.hpp>

#include "core/rng.h"
#include "particles/effect_def.h"

namespace arc {

struct EmitSample {
  glm::dvec3 position{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};  // unit
};

// Uses rng.uniform(base) .. rng.uniform(base + 7).
EmitSample sample_emitter(const EmitterDef& e, const Rng& rng, uint64_t base);

// Uniform direction from two uniforms in [0, 1).
glm::dvec3 uniform_direction(double u1, double u2);
// Uniform direction within `half_angle` of −Z.
glm::dvec3 cone_direction(double half_angle, double u1, double u2);

}  // namespace arc
