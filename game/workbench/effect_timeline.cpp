#include "game/workbench/effect_timeline.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/fast_hash.h"

namespace arc {
namespace {

constexpr OwnerId kStageOwner{1u};

// A camera so far away that every cluster is culled: stepping with it only emits and retires
// particles, which is what the game does for clusters off screen.
ParticleCamera blind_camera() {
  ParticleCamera c;
  c.position = glm::dvec3(0.0, 1e12, 0.0);
  return c;
}

// When one cluster is over by itself, in seconds; a negative value: it runs until stopped.
double cluster_end(const ClusterDef& c) {
  if (c.animation == AnimationType::Lightning)
    return c.lifetime > 0.0 ? std::min(c.lifetime, c.lightning.free_lifetime) : c.lightning.free_lifetime;
  if (c.lifetime > 0.0) return c.lifetime;
  const EmitterDef& e = c.emitter;
  const bool burst_only = e.rate == 0.0 && e.spacing == 0.0;
  if ((!burst_only && e.duration <= 0.0) || c.particles.lifetime.max <= 0.0) return -1.0;
  return (burst_only ? 0.0 : e.duration) + c.particles.lifetime.max;
}

// The stage owner's pose at a tick: the origin, or on its circle with −Z (the emitter's forward)
// along the direction of flight.
OwnerTransform owner_at(const StageOptions& stage, uint64_t tick) {
  if (stage.motion == StageMotion::Still) return {};
  const double r = std::max(stage.circle_radius, 1e-3);
  const double angle = stage.circle_speed / r * double(tick) * stage.tick_seconds;
  const glm::dvec3 tangent(-std::sin(angle), 0.0, std::cos(angle));
  OwnerTransform t;
  t.position = glm::dvec3(r * std::cos(angle), 0.0, r * std::sin(angle));
  t.velocity = tangent * stage.circle_speed;
  t.orientation = glm::angleAxis(std::atan2(-tangent.x, -tangent.z), glm::dvec3(0, 1, 0));
  return t;
}

}  // namespace

EffectTimeline::EffectTimeline(std::shared_ptr<const EffectLibrary> library, const std::string& effect,
                               const StageOptions& stage)
    : library_(std::move(library)), effect_(effect), stage_(stage) {
  restart();
}

void EffectTimeline::restart() {
  ParticleConfig config;
  config.seed = stage_.seed;
  config.tick_seconds = stage_.tick_seconds;
  config.budget = stage_.particle_budget;
  config.lightning_interval = stage_.lightning_interval;
  // The new world takes the old one's store; the old world goes first, so its blocks are back.
  std::shared_ptr<ParticleStore> store = world_ ? world_->store() : nullptr;
  world_.reset();
  world_ = std::make_unique<ParticleWorld>(config, library_.get(), std::move(store));
  SpawnParams params;
  if (stage_.motion == StageMotion::Circle) {
    params.owner = kStageOwner;
    set_owner(0);
  }
  handle_ = world_->spawn(effect_, params);
}

OwnerTransform EffectTimeline::owner_transform() const { return owner_at(stage_, world_->tick()); }

void EffectTimeline::set_owner(uint64_t tick) {
  if (stage_.motion == StageMotion::Circle) world_->set_owner_transform(kStageOwner, owner_at(stage_, tick));
}

uint64_t EffectTimeline::tick() const { return world_->tick(); }

void EffectTimeline::play_step(const ParticleCamera& camera) {
  const uint64_t t = world_->tick() + 1;
  set_owner(t);
  world_->step(t, camera);
}

void EffectTimeline::scrub_to(uint64_t tick, const ParticleCamera& camera) {
  if (tick < world_->tick()) restart();
  const ParticleCamera blind = blind_camera();
  for (uint64_t t = world_->tick() + 1; t < tick; ++t) {
    set_owner(t);
    world_->step(t, blind);
  }
  set_owner(tick);
  world_->step(tick, camera);
}

EffectCounts EffectTimeline::frame_stats() const {
  EffectCounts s;
  s.tick = world_->tick();
  s.live_particles = world_->stats().live_particles;
  for (ClusterHandle c : handle_.clusters) s.cluster_particles.push_back(world_->particle_count(c));
  return s;
}

uint64_t EffectTimeline::state_hash(const ParticleCamera& camera) const {
  FastHasher h;
  world_->hash_summary(h);
  std::vector<ParticleInstance> drawn;
  world_->collect(camera, drawn);
  h.add_u64(drawn.size());
  for (const ParticleInstance& p : drawn) {
    uint64_t words[sizeof(ParticleInstance) / 8];
    std::memcpy(words, &p, sizeof p);
    for (uint64_t w : words) h.add_u64(w);
  }
  return h.value();
}

double EffectTimeline::life_seconds(const EffectDef& def, bool* ends) {
  double end = 0.0, longest_particle = 0.0;
  bool all_end = true;
  for (const ClusterDef& c : def.clusters) {
    const double e = cluster_end(c);
    if (e < 0.0) all_end = false;
    end = std::max(end, e);
    longest_particle = std::max(longest_particle, c.particles.lifetime.max);
  }
  if (ends) *ends = all_end;
  return all_end ? std::max(end, 1.0 / 60.0) : 2.0 * std::max(1.0, longest_particle);
}

double EffectTimeline::life_seconds() const { return life_seconds(library_->get(effect_)); }

}  // namespace arc
