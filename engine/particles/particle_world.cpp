// particles/particle_world.cpp — clusters: spawn, attach, step (emission in emission.cpp, animate, cull),
// collect, hash.
#include "particles/particle_world.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <glm/mat3x3.hpp>
#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "core/error.h"
#include "core/rng.h"
#include "particles/cluster.h"
#include "particles/effect_library.h"
#include "particles/emission.h"
#include "particles/instance_output.h"
#include "particles/world_state.h"

namespace arc {
namespace {

constexpr double kFlashGain = 3.0;  // a flashed particle's alpha at the impact point, × the normal
constexpr double kFlashCos = 0.6;   // particles within acos(0.6) ≈ 53° of the impact direction flash

double length(const glm::dvec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

// A cluster's life in seconds, 0 = unlimited. A lightning channel spawned without an owner (a
// level effect) has nobody to end it, so it lives its definition's free_lifetime at most.
double cluster_lifetime(const Cluster& c) {
  const ClusterDef& d = *c.def;
  if (d.animation != AnimationType::Lightning || c.owner != 0) return d.lifetime;
  return d.lifetime > 0.0 ? std::min(d.lifetime, d.lightning.free_lifetime) : d.lightning.free_lifetime;
}

float curve_max(const Curve& c) {
  float m = 0.0f;
  for (const CurveKey& k : c.keys) m = std::max(m, k.value);
  return m;
}

}  // namespace

struct ParticleWorld::Impl : ParticleWorldState {
  // A culled cluster drawn anyway is evaluated here, not in place. Its storage comes from the
  // store (copy assignment keeps the source), so it does not follow the largest such cluster
  // in the heap.
  mutable ParticlePool scratch;
  // With config.threads != 1, made on the first step; a copy of the world makes its own.
  struct Arena {
    std::unique_ptr<tbb::task_arena> p;
    Arena() = default;
    Arena(const Arena&) {}
    Arena& operator=(const Arena&) { return *this; }
  } arena;
  std::vector<uint32_t> todo;              // the slots step() animates
  std::vector<uint8_t> was_culled;         // of each of them, before this step
  uint32_t skipped_particles = 0, animated_particles = 0, caught_up = 0;  // the last step's, for stats()

  Cluster* find(ClusterHandle hnd) {
    if (!hnd || hnd.index > slots.size()) return nullptr;
    Cluster& c = slots[hnd.index - 1];
    return c.alive && c.generation == hnd.generation ? &c : nullptr;
  }
  const Cluster* find(ClusterHandle hnd) const { return const_cast<Impl*>(this)->find(hnd); }

  Pose frame(const Cluster& c) const {
    if (moves_with_frame(c)) return emitter_pose(c);
    return {c.world_origin, glm::dquat(1, 0, 0, 0)};
  }
  // frame() with the owner where the renderer draws it, when `drawn` lists it.
  Pose drawn_frame(const Cluster& c, std::span<const DrawnOwner> drawn) const {
    if (c.owner == 0 || !moves_with_frame(c)) return frame(c);
    auto it = std::lower_bound(drawn.begin(), drawn.end(), c.owner,
                               [](const DrawnOwner& d, uint32_t owner) { return d.owner.value < owner; });
    if (it == drawn.end() || it->owner.value != c.owner) return frame(c);
    return {it->position + it->orientation * c.local_position, it->orientation * c.local_orientation};
  }

  int lightning_interval(const Cluster& c) const {
    return config.lightning_interval > 0 ? config.lightning_interval : c.def->lightning.sizzle_ticks;
  }

  Cluster& allocate(uint32_t& slot) {
    if (!free_slots.empty()) {
      slot = free_slots.back();
      free_slots.pop_back();
    } else {
      slot = uint32_t(slots.size());
      slots.emplace_back();
    }
    Cluster& c = slots[slot];
    const uint32_t generation = c.generation + 1;
    c = Cluster{};
    c.generation = generation;
    c.alive = true;
    return c;
  }

  ClusterHandle create(const EffectDef& effect, uint32_t index, const SpawnParams& p) {
    const ClusterDef& d = effect.clusters[index];
    uint32_t slot = 0;
    Cluster& c = allocate(slot);
    c.serial = next_serial++;
    c.effect = &effect;
    c.def_index = index;
    c.def = &d;
    c.spawn_tick = tick + 1;
    c.owner = p.owner.value;
    c.local_position = p.position;
    c.local_orientation = p.orientation;
    c.spawn_velocity = p.velocity;
    c.scale = p.scale;
    c.intensity = p.intensity;
    c.priority = d.priority >= 0 ? d.priority : p.priority;
    if (d.animation == AnimationType::Linear) c.motion = motion_table(d);
    const Pose e = emitter_pose(c);
    c.world_origin = e.position;
    c.last_emit_position = e.position;
    const double expected = d.emitter.burst * p.intensity + d.emitter.rate * p.intensity * d.particles.lifetime.max + 16.0;
    c.pool = ParticlePool(store.get());
    c.pool.reserve_in_store(size_t(std::min(expected, double(config.budget))));
    return {slot + 1, c.generation};
  }

  void release(Cluster& c) {
    live_particles -= uint32_t(c.pool.count());
    // The storage goes back to the heap. Kept for the slot's next cluster, it crept up: a slot
    // is reused by any effect, so every slot came to hold the largest effect's capacity (three
    // times the live particles by the end of an arena battle, and more with every battle).
    c.pool = ParticlePool{};
    c.lightning.points = {};
    c.alive = false;
    ++c.generation;
    free_slots.push_back(uint32_t(&c - slots.data()));
  }

  // ---- lightning --------------------------------------------------------------------------

  void rebuild_lightning(Cluster& c, uint64_t t) {
    const uint64_t epoch = lightning_epoch(t, c.spawn_tick, lightning_interval(c));
    if (epoch == c.lightning.epoch) return;
    c.lightning.epoch = epoch;
    build_lightning(c.def->lightning, c.scale, Rng{config.seed, c.serial, epoch}, c.lightning);
    const size_t segments = c.lightning.points.size() - 1;
    const size_t have = c.pool.count();
    size_t want = segments;
    if (segments > have) {
      const uint32_t limit = budget_limit(c.priority);
      const size_t room = live_particles >= limit ? 0 : limit - live_particles;
      want = std::min(segments, have + room);
      refused += segments - want;
    }
    live_particles = uint32_t(live_particles - have + want);
    c.pool.resize(want);
    const uint32_t age = uint32_t(epoch - c.spawn_tick);
    for (size_t i = 0; i < want; ++i) {
      c.pool.birth[i] = age;
      c.pool.death[i] = kNeverDies;
      c.pool.uid[i] = uint32_t(i);
      c.pool.size0[i] = float(c.def->lightning.width * c.scale);
      c.pool.rot0[i] = c.pool.spin[i] = c.pool.reach[i] = 0.0f;
      c.pool.sprite[i] = c.def->sprite;
    }
    apply_cut(c);
  }

  // Segment particles: start, visible segment vector (shortened at the cut), centre, hidden flag.
  static void apply_cut(Cluster& c) {
    const auto& pts = c.lightning.points;
    double along = 0.0;
    ParticlePool& pl = c.pool;
    for (size_t i = 0; i < pl.count(); ++i) {
      const glm::dvec3 seg = pts[i + 1] - pts[i];
      const double len = length(seg);
      const double visible = std::clamp(c.lightning.cut - along, 0.0, len);
      const glm::dvec3 v = len > 0.0 ? seg * (visible / len) : glm::dvec3(0.0);
      const glm::dvec3 mid = pts[i] + v * 0.5;
      pl.p0x[i] = float(pts[i].x), pl.p0y[i] = float(pts[i].y), pl.p0z[i] = float(pts[i].z);
      pl.vx[i] = float(v.x), pl.vy[i] = float(v.y), pl.vz[i] = float(v.z);
      pl.px[i] = float(mid.x), pl.py[i] = float(mid.y), pl.pz[i] = float(mid.z);
      pl.flags[i] = visible > 0.0 ? uint8_t(0) : uint8_t(kParticleHidden);
      along += len;
    }
  }

  // ---- per tick ---------------------------------------------------------------------------

  // Emission, deaths and lightning re-evaluation: done every tick for every cluster (culled or
  // not), because they decide what exists and what the budget admits.
  void advance(Cluster& c, uint64_t t) {
    if (t < c.spawn_tick) return;
    const uint32_t age = uint32_t(t - c.spawn_tick);
    const ClusterDef& d = *c.def;
    const double lifetime = cluster_lifetime(c);
    if (lifetime > 0.0 && age >= life_ticks(lifetime, h())) {
      release(c);
      return;
    }
    live_particles -= uint32_t(c.pool.retire(age));
    if (d.animation == AnimationType::Lightning) {
      rebuild_lightning(c, t);
      return;
    }
    emit_particles(*this, c, t, age);
    const EmitterDef& ed = d.emitter;
    const bool rate_done = !c.emitting || (ed.rate <= 0.0 && ed.spacing <= 0.0) ||
                           (ed.duration > 0.0 && double(age + 1) * h() >= ed.duration);
    if (rate_done && c.pool.count() == 0) release(c);
  }

  float max_particle_size(const Cluster& c) const {
    const ClusterDef& d = *c.def;
    if (d.animation == AnimationType::Lightning) return float(d.lightning.width * c.scale);
    return float(d.particles.size.max * c.scale) * std::max(curve_max(d.size), 1.0f);
  }

  void update_bound(Cluster& c, uint64_t t) {
    const ClusterDef& d = *c.def;
    const double margin = max_particle_size(c);
    if (d.animation == AnimationType::Sphere) {
      c.bound_center = glm::dvec3(0.0);
      c.bound_radius = sphere_radius(d.sphere, c.scale, double(t - c.spawn_tick) * h(), d.lifetime) *
                           (1.0 + d.sphere.amplitude) + margin;
      return;
    }
    if (d.animation == AnimationType::Lightning) {
      glm::dvec3 lo = c.lightning.points.front(), hi = lo;
      for (const glm::dvec3& q : c.lightning.points) lo = glm::min(lo, q), hi = glm::max(hi, q);
      c.bound_center = (lo + hi) * 0.5;
      c.bound_radius = length(hi - lo) * 0.5 + margin;
      return;
    }
    const ParticlePool& p = c.pool;
    if (p.count() == 0) {
      c.bound_center = glm::dvec3(0.0), c.bound_radius = 0.0;
      return;
    }
    // Birth positions and reaches only change with the set of particles: no pass over a
    // cluster's particles on a tick that neither bore nor retired one.
    if (p.changes() == c.bound_changes && margin == c.bound_margin) return;
    float lo[3] = {p.p0x[0], p.p0y[0], p.p0z[0]}, hi[3] = {lo[0], lo[1], lo[2]};
    for (size_t i = 0; i < p.count(); ++i) {
      const float r = p.reach[i];
      lo[0] = std::min(lo[0], p.p0x[i] - r), hi[0] = std::max(hi[0], p.p0x[i] + r);
      lo[1] = std::min(lo[1], p.p0y[i] - r), hi[1] = std::max(hi[1], p.p0y[i] + r);
      lo[2] = std::min(lo[2], p.p0z[i] - r), hi[2] = std::max(hi[2], p.p0z[i] + r);
    }
    const glm::dvec3 a(lo[0], lo[1], lo[2]), b(hi[0], hi[1], hi[2]);
    c.bound_center = (a + b) * 0.5;
    c.bound_radius = length(b - a) * 0.5 + margin;
    c.bound_changes = p.changes();
    c.bound_margin = margin;
  }

  bool visible(const Cluster& c, const ParticleCamera& cam) const {
    const Pose f = frame(c);
    const glm::dvec3 d = f.position + f.orientation * c.bound_center - cam.position;
    const double dist = length(d);
    const double r = c.bound_radius;
    if (dist - r > config.cull_distance) return false;
    if (dist <= r) return true;
    const glm::dvec3 fwd = cam.orientation * glm::dvec3(0, 0, -1);
    const double depth = glm::dot(d, fwd);
    const double half_diag = std::atan(std::tan(cam.fov_y_radians * 0.5) * std::sqrt(1.0 + cam.aspect * cam.aspect));
    const double angle = std::acos(std::clamp(depth / dist, -1.0, 1.0));
    // 10% wider than the view, so interpolated frame cameras rarely meet a stale cluster.
    return angle - std::asin(std::min(1.0, r / dist)) <= std::min(3.14159265358979, half_diag * 1.1);
  }

  // Brings a pool to tick t from its birth state (the same arithmetic for skipped and animated clusters).
  void animate(const Cluster& c, uint64_t t, ParticlePool& pool) const {
    const ClusterDef& d = *c.def;
    const uint32_t age = uint32_t(t - c.spawn_tick);
    const double age_s = double(age) * h();
    switch (d.animation) {
      case AnimationType::Linear:
        animate_linear(pool, age, *c.motion, glm::vec3(d.linear.acceleration * c.scale));
        break;
      case AnimationType::Sphere: {
        const float radius = float(sphere_radius(d.sphere, c.scale, age_s, d.lifetime));
        if (d.sphere.motion == SphereMotion::Stochastic) {
          animate_sphere_stochastic(pool, radius, config.seed, c.serial, t);
        } else {
          const glm::dquat q = d.sphere.motion == SphereMotion::Rotational ? sphere_rotation(d.sphere.rotation_rate, h(), age)
                                                                            : glm::dquat(1, 0, 0, 0);
          animate_sphere(pool, radius, glm::mat3(glm::mat3_cast(q)));
        }
        break;
      }
      case AnimationType::Lightning:
        break;
    }
    const float life_t = d.lifetime > 0.0 ? float(std::min(1.0, age_s / d.lifetime)) : 0.0f;
    animate_attributes(pool, age, h(), CurveSet{&d.size, &d.red, &d.green, &d.blue, &d.alpha, &d.burn},
                       float(c.intensity), life_t);
    if (d.animation == AnimationType::Sphere) apply_flash(c, t, pool);
  }

  void apply_flash(const Cluster& c, uint64_t t, ParticlePool& pool) const {
    if (c.flash_ticks == 0 || t < c.flash_tick || t - c.flash_tick >= c.flash_ticks) return;
    const float fade = 1.0f - float(t - c.flash_tick) / float(c.flash_ticks);
    const glm::vec3 dir(c.flash_direction);
    for (size_t i = 0; i < pool.count(); ++i) {
      const glm::vec3 p(pool.px[i], pool.py[i], pool.pz[i]);
      const float l = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
      if (l <= 0.0f) continue;
      const float cosang = (p.x * dir.x + p.y * dir.y + p.z * dir.z) / l;
      const float w = std::max(0.0f, (cosang - float(kFlashCos)) / (1.0f - float(kFlashCos)));
      const float gain = 1.0f + float(kFlashGain) * fade * w * w;
      pool.a[i] = std::min(1.0f, pool.a[i] * gain);
      pool.size[i] *= 1.0f + 0.5f * fade * w;
    }
  }
};

// ---- public API -------------------------------------------------------------------------------

ParticleWorld::ParticleWorld(const ParticleConfig& config, const EffectLibrary* effects, std::shared_ptr<ParticleStore> store)
    : impl_(std::make_unique<Impl>()) {
  impl_->config = config;
  impl_->effects = effects;
  impl_->store = store && store->capacity() >= config.budget ? std::move(store) : std::make_shared<ParticleStore>(config.budget);
  impl_->scratch = ParticlePool(impl_->store.get());
  impl_->reserve_slots();
}
ParticleWorld::~ParticleWorld() = default;
std::shared_ptr<ParticleStore> ParticleWorld::store() const { return impl_->store; }
ParticleWorldState& ParticleWorldAccess::state(ParticleWorld& w) { return *w.impl_; }
const ParticleWorldState& ParticleWorldAccess::state(const ParticleWorld& w) { return *w.impl_; }
ParticleWorld::ParticleWorld(const ParticleWorld& o) : impl_(std::make_unique<Impl>(*o.impl_)) {}
// Into the pools, slots and maps this world has: a rollback's per-tick save and restore copy
// a battle's particles without taking or faulting in fresh memory.
ParticleWorld& ParticleWorld::operator=(const ParticleWorld& o) {
  if (this != &o) *impl_ = *o.impl_;
  return *this;
}

EffectHandle ParticleWorld::spawn(const std::string& effect, const SpawnParams& params) {
  if (!impl_->effects) throw InputError("unknown effect '" + effect + "': no effect library");
  return spawn(impl_->effects->id(effect), params);
}

EffectHandle ParticleWorld::spawn(EffectId effect, const SpawnParams& params) {
  if (!impl_->effects) throw InputError("effect id " + std::to_string(effect.value) + ": no effect library");
  const EffectDef& def = impl_->effects->get(effect);
  EffectHandle out;
  for (uint32_t i = 0; i < def.clusters.size(); ++i) {
    if (def.clusters[i].animation == AnimationType::Lightning) {
      out.clusters.push_back(spawn_lightning(effect, params.owner, params.position, params.orientation * glm::dvec3(0, 0, -1)));
      continue;
    }
    out.clusters.push_back(impl_->create(def, i, params));
  }
  return out;
}

ClusterHandle ParticleWorld::spawn_lightning(const std::string& effect, OwnerId owner, const glm::dvec3& local_origin,
                                             const glm::dvec3& local_direction) {
  if (!impl_->effects) throw InputError("unknown effect '" + effect + "': no effect library");
  return spawn_lightning(impl_->effects->id(effect), owner, local_origin, local_direction);
}

ClusterHandle ParticleWorld::spawn_lightning(EffectId effect, OwnerId owner, const glm::dvec3& local_origin,
                                             const glm::dvec3& local_direction) {
  if (!impl_->effects) throw InputError("effect id " + std::to_string(effect.value) + ": no effect library");
  const EffectDef& def = impl_->effects->get(effect);
  for (uint32_t i = 0; i < def.clusters.size(); ++i) {
    if (def.clusters[i].animation != AnimationType::Lightning) continue;
    SpawnParams p;
    p.owner = owner;
    // The origin goes into the cluster's frame (double); the channel itself is built around
    // zero, so its float particle positions stay precise however far from the world origin.
    p.position = local_origin;
    ClusterHandle hnd = impl_->create(def, i, p);
    Cluster& c = *impl_->find(hnd);
    const double l = length(local_direction);
    c.lightning.origin = glm::dvec3(0.0);
    c.lightning.direction = l > 1e-12 ? local_direction / l : glm::dvec3(0, 0, -1);
    impl_->rebuild_lightning(c, c.spawn_tick);
    return hnd;
  }
  throw InputError(def.path + ": effect '" + def.name + "' has no lightning cluster (animation type \"lightning\")");
}

void ParticleWorld::destroy(ClusterHandle cluster) {
  if (Cluster* c = impl_->find(cluster)) impl_->release(*c);
}

void ParticleWorld::destroy(const EffectHandle& effect) {
  for (ClusterHandle c : effect.clusters) destroy(c);
}

void ParticleWorld::destroy_owner(OwnerId owner) {
  if (!owner) return;
  for (Cluster& c : impl_->slots)
    if (c.alive && c.owner == owner.value) impl_->release(c);
  impl_->owners.erase(owner.value);
}

void ParticleWorld::release_owner(OwnerId owner) {
  if (!owner) return;
  for (Cluster& c : impl_->slots) {
    if (!c.alive || c.owner != owner.value) continue;
    if (moves_with_frame(c)) {
      impl_->release(c);  // it would have nothing left to move with
      continue;
    }
    // World-space particles stay where they were emitted: stop emitting and let them fade.
    c.emitting = false;
    c.owner = 0;
  }
  impl_->owners.erase(owner.value);
}

bool ParticleWorld::alive(ClusterHandle cluster) const { return impl_->find(cluster) != nullptr; }

uint32_t ParticleWorld::particle_count(ClusterHandle cluster) const {
  const Cluster* c = impl_->find(cluster);
  return c ? uint32_t(c->pool.count()) : 0u;
}

void ParticleWorld::set_owner_transform(OwnerId owner, const OwnerTransform& t) {
  if (owner) impl_->owners[owner.value] = t;
}

void ParticleWorld::stop_emitting(ClusterHandle cluster) {
  if (Cluster* c = impl_->find(cluster)) c->emitting = false;
}

void ParticleWorld::set_intensity(ClusterHandle cluster, double intensity) {
  if (Cluster* c = impl_->find(cluster)) c->intensity = std::isfinite(intensity) ? std::max(0.0, intensity) : 0.0;
}

void ParticleWorld::flash(ClusterHandle cluster, const glm::dvec3& world_point, double seconds) {
  Cluster* c = impl_->find(cluster);
  if (!c || !(seconds > 0.0)) return;
  const Pose f = impl_->frame(*c);
  const glm::dvec3 local = glm::inverse(f.orientation) * (world_point - f.position);
  const double l = length(local);
  c->flash_direction = l > 1e-12 ? local / l : glm::dvec3(0, 0, -1);
  c->flash_tick = impl_->tick;
  c->flash_ticks = life_ticks(seconds, impl_->h());
  if (c->animated_tick == impl_->tick && impl_->tick >= c->spawn_tick) impl_->animate(*c, impl_->tick, c->pool);
}

std::vector<glm::dvec3> ParticleWorld::lightning_points(ClusterHandle channel) const {
  std::vector<glm::dvec3> out;
  const Cluster* c = impl_->find(channel);
  if (!c || c->def->animation != AnimationType::Lightning) return out;
  const Pose f = impl_->frame(*c);
  for (const glm::dvec3& p : c->lightning.points) out.push_back(f.position + f.orientation * p);
  return out;
}

double ParticleWorld::lightning_length(ClusterHandle channel) const {
  const Cluster* c = impl_->find(channel);
  return c && c->def->animation == AnimationType::Lightning ? c->lightning.length() : 0.0;
}

void ParticleWorld::cut_lightning(ClusterHandle channel, double distance) {
  Cluster* c = impl_->find(channel);
  if (!c || c->def->animation != AnimationType::Lightning) return;
  c->lightning.cut = std::isnan(distance) ? 0.0 : std::max(0.0, distance);
  Impl::apply_cut(*c);
}

glm::dvec3 ParticleWorld::lightning_point_at(ClusterHandle channel, double distance) const {
  const Cluster* c = impl_->find(channel);
  if (!c || c->def->animation != AnimationType::Lightning) return glm::dvec3(0.0);
  const Pose f = impl_->frame(*c);
  return f.position + f.orientation * c->lightning.point_at(distance);
}

void ParticleWorld::step(uint64_t tick, const ParticleCamera& camera) {
  Impl& w = *impl_;
  for (uint64_t t = w.tick + 1; t <= tick; ++t)
    for (Cluster& c : w.slots)
      if (c.alive) w.advance(c, t);
  w.tick = std::max(w.tick, tick);
  w.skipped = w.skipped_particles = w.animated_particles = w.caught_up = 0;
  w.todo.clear();
  for (size_t slot = 0; slot < w.slots.size(); ++slot)
    if (w.slots[slot].alive && w.tick >= w.slots[slot].spawn_tick) w.todo.push_back(uint32_t(slot));
  w.was_culled.resize(w.todo.size());
  // Each cluster touches only its own state: any split over threads gives the same result.
  auto animate_one = [&](size_t k) {
    Cluster& c = w.slots[w.todo[k]];
    w.update_bound(c, w.tick);
    w.was_culled[k] = c.culled;
    c.culled = c.intensity <= 0.0 || !w.visible(c, camera);
    if (c.culled) return;
    w.animate(c, w.tick, c.pool);
    c.animated_tick = w.tick;
  };
  if (w.config.threads == 1 || w.todo.size() < 2) {
    for (size_t k = 0; k < w.todo.size(); ++k) animate_one(k);
  } else {
    if (!w.arena.p)
      w.arena.p = std::make_unique<tbb::task_arena>(w.config.threads > 0 ? w.config.threads : static_cast<int>(tbb::task_arena::automatic));
    w.arena.p->execute([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, w.todo.size()), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k != r.end(); ++k) animate_one(k);
      });
    });
  }
  for (size_t k = 0; k < w.todo.size(); ++k) {  // the counts, in slot order
    const Cluster& c = w.slots[w.todo[k]];
    if (c.culled) {
      ++w.skipped;
      w.skipped_particles += uint32_t(c.pool.count());
      continue;
    }
    w.caught_up += w.was_culled[k] ? 1u : 0u;
    w.animated_particles += uint32_t(c.pool.count());
  }
}

void ParticleWorld::collect(const ParticleCamera& camera, std::vector<ParticleInstance>& out,
                            std::span<const DrawnOwner> drawn) const {
  const Impl& w = *impl_;
  // Room for the whole budget, taken once and written once: grown by doubling, the output would
  // go through ever larger blocks as battles grow, each one copied and left behind in the heap;
  // reserved but untouched, its resident pages would grow with the busiest moment seen so far.
  // Written through at once, it costs what the budget promises from the first frame and never
  // grows.
  if (out.capacity() < out.size() + w.config.budget) {
    const size_t used = out.size();
    out.resize(used + w.config.budget);
    out.resize(used);
  }
  for (size_t slot = 0; slot < w.slots.size(); ++slot) {
    const Cluster& c = w.slots[slot];
    if (!c.alive || c.intensity <= 0.0 || w.tick < c.spawn_tick || c.pool.count() == 0) continue;
    if (!w.visible(c, camera)) continue;
    const ParticlePool* pool = &c.pool;
    if (c.animated_tick != w.tick) {
      w.scratch = c.pool;
      w.animate(c, w.tick, w.scratch);
      pool = &w.scratch;
    }
    append_instances(c, *pool, w.drawn_frame(c, drawn), camera, uint32_t(w.tick - c.spawn_tick), uint32_t(slot + 1), out);
  }
}

ParticleStats ParticleWorld::stats() const {
  ParticleStats s;
  s.live_particles = impl_->live_particles;
  for (const Cluster& c : impl_->slots) {
    s.live_clusters += c.alive ? 1u : 0u;
    s.pools_on_heap += c.alive && c.pool.capacity() && !c.pool.in_store() ? 1u : 0u;
  }
  s.store_in_use = impl_->store->in_use();
  s.store_capacity = impl_->store->capacity();
  s.refused_particles = impl_->refused;
  s.skipped_clusters = impl_->skipped;
  s.skipped_particles = impl_->skipped_particles;
  s.animated_particles = impl_->animated_particles;
  s.caught_up_clusters = impl_->caught_up;
  return s;
}

uint64_t ParticleWorld::tick() const { return impl_->tick; }

}  // namespace arc
