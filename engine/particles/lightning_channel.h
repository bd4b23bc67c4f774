// particles/lightning_channel.h — the lightning-beam channel of Hadwiger 2000 §5.2.
//
// A seed segment from the origin along the direction fixes the channel's general direction and
// basic segment length. Every further segment deviates from the seed direction by a random
// angle up to max_angle (uniform over the spherical cap) and has a random length in
// seed_length·[1 − jitter, 1 + jitter]; segments are concatenated while the total stays within
// max_length. A guided channel (guide_distance > 0, a weapon that must hit what it is aimed at)
// measures each deviation from the direction toward the seed line's point guide_distance ahead
// of the segment's start instead, so it sizzles about the aim line without wandering off it.
// No branches. Every n ticks all segments but the seed are drawn again ("sizzle");
// the draw is keyed by (seed, stream, epoch tick), so a channel is a pure function of its epoch.
#pragma once
#include <cstdint>
#include <vector>
#include <glm/vec3.hpp>

#include "core/rng.h"
#include "particles/effect_def.h"

namespace arc {

struct LightningChannel {
  glm::dvec3 origin{0.0};               // owner-local
  glm::dvec3 direction{0.0, 0.0, -1.0};  // owner-local, unit
  std::vector<glm::dvec3> points;        // owner-local polyline, points[0] = origin
  uint64_t epoch = ~0ull;                // tick the current segments were drawn for
  double cut = 1e300;                    // particles beyond this distance are hidden

  double length() const;
  // Point at a distance along the polyline, clamped to its ends.
  glm::dvec3 point_at(double distance) const;
};

// The epoch (tick of the last re-evaluation) for a channel spawned at spawn_tick.
uint64_t lightning_epoch(uint64_t tick, uint64_t spawn_tick, int interval);

// Rebuilds the polyline for one epoch; reuses the points' capacity.
void build_lightning(const LightningDef& def, double scale, const Rng& rng, LightningChannel& ch);

}  // namespace arc
