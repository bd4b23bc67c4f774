// particles/emission.h — internal: the new particles of one cluster for one tick.
//
// Burst at the cluster's first tick, then `rate` per second plus one per `spacing` metres the
// emitter travelled; world-space particles are laid along the emitter's path since the previous
// tick. The fraction of a particle not yet emitted carries over in the cluster's accumulator
// (hashed and saved with it). Every new particle's birth state is drawn from the keyed RNG
// (seed, cluster serial, tick, particle index), so emission does not depend on the order
// clusters are stepped in. Refused particles (budget full) are counted.
#pragma once
#include <cstdint>

#include "particles/world_state.h"

namespace arc {

// Emits cluster `c`'s particles for tick `t` (its age in ticks) into its pool.
void emit_particles(ParticleWorldState& w, Cluster& c, uint64_t t, uint32_t age);

}  // namespace arc
