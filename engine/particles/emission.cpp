// particles/emission.cpp — a cluster's new particles for one tick (see emission.h).
#include "particles/emission.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"
#include "particles/emitter.h"

namespace arc {
namespace {

double length(const glm::dvec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

// This tick's particles: the burst, then those of the rate and the spacing. Rate-only emitters
// spread theirs evenly over the path since the last tick (i + 1) / count; a spacing emitter puts
// its j-th where the accumulated amount crosses j, at path fraction (j − carried) / gained, so
// consecutive particles lie `spacing` apart across tick boundaries too.
struct EmissionPlan {
  uint64_t burst = 0;
  uint64_t count = 0;    // burst included
  double carried = 0.0;  // accumulator before this tick (spacing emitters)
  double gained = 0.0;   // added to it this tick (spacing emitters; 0 = rate placement)

  double along(uint64_t i) const {
    if (gained <= 0.0) return double(i + 1) / double(count);
    if (i < burst) return 1.0;  // where the emitter is now
    return std::min(1.0, (double(i - burst + 1) - carried) / gained);
  }
};

EmissionPlan plan_emission(const ParticleWorldState& w, Cluster& c, uint32_t age, double path_length) {
  const EmitterDef& ed = c.def->emitter;
  EmissionPlan plan;
  if (age == 0 && ed.burst > 0) plan.burst = uint64_t(std::llround(ed.burst * c.intensity));
  plan.count = plan.burst;
  const bool in_duration = ed.duration <= 0.0 || double(age) * w.h() < ed.duration;
  if (!c.emitting || !in_duration) return plan;
  if (ed.spacing > 0.0) {
    plan.carried = c.emit_accumulator;
    plan.gained = ed.rate * w.h() * c.intensity + path_length / ed.spacing * c.intensity;
    c.emit_accumulator += plan.gained;
  } else if (ed.rate > 0.0) {
    c.emit_accumulator += ed.rate * w.h() * c.intensity;
  } else {
    return plan;
  }
  const double whole = std::floor(c.emit_accumulator);
  c.emit_accumulator -= whole;
  plan.count += uint64_t(whole);
  return plan;
}

}  // namespace

void emit_particles(ParticleWorldState& w, Cluster& c, uint64_t t, uint32_t age) {
  const ClusterDef& d = *c.def;
  const EmitterDef& ed = d.emitter;
  const Pose ep = w.emitter_pose(c);
  const glm::dvec3 from = c.last_emit_position;
  c.last_emit_position = ep.position;
  const EmissionPlan plan = plan_emission(w, c, age, length(ep.position - from));
  const uint64_t count = plan.count;
  if (count == 0) return;
  const Rng rng{w.config.seed, c.serial, t};
  const uint32_t limit = w.budget_limit(c.priority);
  const glm::dvec3 inherited = w.owner_velocity(c) * d.particles.inherit_velocity;
  const ParticleInitDef& pd = d.particles;
  for (uint64_t i = 0; i < count; ++i) {
    if (w.live_particles >= limit) {
      w.refused += count - i;
      return;
    }
    const uint64_t base = i * 16;
    const EmitSample s = sample_emitter(ed, rng, base);
    const double speed = rng.range(base + 8, pd.speed.min, pd.speed.max) * c.scale;
    const uint32_t life = life_ticks(rng.range(base + 9, pd.lifetime.min, pd.lifetime.max), w.h());
    const size_t k = c.pool.count();
    c.pool.resize(k + 1);
    glm::dvec3 p0, v0;
    if (d.animation == AnimationType::Sphere) {
      p0 = uniform_direction(rng.uniform(base + 13), rng.uniform(base + 14));
      v0 = glm::dvec3(0.0);
    } else if (moves_with_frame(c)) {
      p0 = s.position * c.scale;
      v0 = s.direction * speed;
    } else {
      // World space: laid along the emitter's path since last tick.
      const glm::dvec3 at = from + (ep.position - from) * plan.along(i);
      p0 = at - c.world_origin + ep.orientation * (s.position * c.scale);
      v0 = ep.orientation * (s.direction * speed) + inherited;
    }
    ParticlePool& pl = c.pool;
    pl.p0x[k] = pl.px[k] = float(p0.x);
    pl.p0y[k] = pl.py[k] = float(p0.y);
    pl.p0z[k] = pl.pz[k] = float(p0.z);
    pl.vx[k] = float(v0.x);
    pl.vy[k] = float(v0.y);
    pl.vz[k] = float(v0.z);
    if (c.motion) {
      const uint32_t n = std::min(life, c.motion->last());
      const double a = length(d.linear.acceleration) * c.scale;
      pl.reach[k] = float(length(v0) * c.motion->g[n] + a * c.motion->f[n]);
    }
    pl.size0[k] = float(rng.range(base + 10, pd.size.min, pd.size.max) * c.scale);
    pl.rot0[k] = float(rng.range(base + 11, pd.rotation.min, pd.rotation.max));
    pl.spin[k] = float(rng.range(base + 12, pd.spin.min, pd.spin.max));
    pl.birth[k] = age;
    pl.death[k] = life == kNeverDies ? kNeverDies : age + life;
    pl.uid[k] = c.next_uid++;
    pl.sprite[k] = d.sprite;
    ++w.live_particles;
  }
}

}  // namespace arc
