// The workbench's scene: one effect, a backdrop, and an exact timeline (see the header).
#include "game/workbench/workbench_stage.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/hash.h"
#include "particles/world_state.h"

namespace arc {
namespace {

constexpr double kCircleRadius = 60.0;   // m: the circling ship's path
constexpr double kCircleSpeed = 40.0;    // m/s along it
constexpr OwnerId kStageOwner{1u};

// Cluster ages are counted from the tick after the spawn (ParticleWorld: spawn_tick = tick + 1),
// so stage tick T is world tick T + 1: tick 0 shows the burst.
uint64_t world_tick(uint64_t stage_tick) { return stage_tick + 1; }

}  // namespace

WorkbenchStage::WorkbenchStage(uint32_t particle_budget, double tick_seconds)
    : budget_(particle_budget), h_(tick_seconds) {}

WorkbenchStage::~WorkbenchStage() = default;

void WorkbenchStage::set_models(std::vector<StageModel> ships, StageModel wall) {
  ships_ = std::move(ships);
  wall_ = std::move(wall);
}

void WorkbenchStage::set_effect(const std::string& text, const std::string& path) {
  auto library = std::make_unique<EffectLibrary>();
  library->load_text(text, path);  // InputError: nothing changes
  const std::vector<std::string> names = library->names();
  world_.reset();  // its clusters point into the old library
  library_ = std::move(library);
  effect_name_ = names.front();
  scrub(tick_);
}

const EffectDef* WorkbenchStage::effect() const { return library_ ? &library_->get(effect_name_) : nullptr; }

void WorkbenchStage::set_backdrop(Backdrop b) {
  backdrop_ = b;
  if (backdrop_.model >= ships_.size()) backdrop_.model = 0;
  scrub(tick_);  // attached or not changes the spawn
}

void WorkbenchStage::set_attach_point(AttachPoint p) {
  attach_ = p;
  scrub(tick_);
}

void WorkbenchStage::set_speed(double s) { speed_ = std::clamp(s, 0.1, 4.0); }

void WorkbenchStage::set_loop_seconds(double s) {
  loop_seconds_ = std::clamp(s, 0.1, 60.0);
  if (tick_ > loop_ticks()) scrub(0);
}

uint64_t WorkbenchStage::loop_ticks() const { return uint64_t(std::max(1.0, std::round(loop_seconds_ / h_))); }

double WorkbenchStage::effect_seconds() const {
  const EffectDef* def = effect();
  if (!def) return 0.0;
  double longest = 0.0;
  for (const ClusterDef& c : def->clusters) {
    double life = c.lifetime;
    if (c.animation == AnimationType::Lightning && backdrop_.kind != BackdropKind::Circling)
      life = life > 0.0 ? std::min(life, c.lightning.free_lifetime) : c.lightning.free_lifetime;
    if (life <= 0.0 && c.emitter.duration > 0.0) life = c.emitter.duration + c.particles.lifetime.max;
    if (life <= 0.0 && c.emitter.rate <= 0.0 && c.emitter.spacing <= 0.0 && c.particles.lifetime.max > 0.0)
      life = c.particles.lifetime.max;  // a burst: over when its particles are
    if (life <= 0.0) return 0.0;
    longest = std::max(longest, life);
  }
  return longest;
}

glm::dvec3 WorkbenchStage::attach_offset() const {
  if (ships_.empty() || attach_ == AttachPoint::Centre) return glm::dvec3(0.0);
  const StageModel& m = ships_[backdrop_.model];
  return attach_ == AttachPoint::Stern ? glm::dvec3(0, 0, m.bounds_max.z) : glm::dvec3(0, 0, m.bounds_min.z);
}

// Counter-clockwise seen from above, nose (−Z) along the motion, banked into the turn.
OwnerTransform WorkbenchStage::circle_pose(uint64_t stage_tick) const {
  const double w = kCircleSpeed / kCircleRadius;
  const double a = w * double(stage_tick) * h_;
  OwnerTransform t;
  t.position = {kCircleRadius * std::cos(a), 0.0, -kCircleRadius * std::sin(a)};
  t.velocity = {-kCircleSpeed * std::sin(a), 0.0, -kCircleSpeed * std::cos(a)};
  const glm::dquat heading = glm::angleAxis(a, glm::dvec3(0, 1, 0));
  t.orientation = heading * glm::angleAxis(0.35, glm::dvec3(0, 0, 1));
  return t;
}

// A fresh world with the effect spawned at stage tick 0.
void WorkbenchStage::restart() {
  ParticleConfig config;
  config.budget = budget_;
  config.tick_seconds = h_;
  world_ = std::make_unique<ParticleWorld>(config, library_.get());
  if (!library_) return;
  SpawnParams p;
  if (backdrop_.kind == BackdropKind::Circling && !ships_.empty()) {
    p.owner = kStageOwner;
    p.position = attach_offset();
    world_->set_owner_transform(kStageOwner, circle_pose(0));
  }
  world_->spawn(library_->id(effect_name_), p);
  world_->step(world_tick(0), camera_);
}

void WorkbenchStage::scrub(uint64_t tick) {
  tick_ = std::min(tick, loop_ticks());
  accumulator_ = 0.0;
  restart();
  if (backdrop_.kind != BackdropKind::Circling) {
    world_->step(world_tick(tick_), camera_);  // the catch-up path, in one call
    return;
  }
  for (uint64_t t = 1; t <= tick_; ++t) {  // the owner moves every tick
    world_->set_owner_transform(kStageOwner, circle_pose(t));
    world_->step(world_tick(t), camera_);
  }
}

void WorkbenchStage::step_one() {
  if (tick_ + 1 > loop_ticks()) {
    scrub(0);
    return;
  }
  ++tick_;
  if (backdrop_.kind == BackdropKind::Circling) world_->set_owner_transform(kStageOwner, circle_pose(tick_));
  world_->step(world_tick(tick_), camera_);
}

void WorkbenchStage::step_by(int ticks) {
  playing_ = false;
  const int64_t n = int64_t(loop_ticks()) + 1;
  const int64_t target = ((int64_t(tick_) + ticks) % n + n) % n;
  if (target == int64_t(tick_) + 1) step_one();
  else scrub(uint64_t(target));
}

void WorkbenchStage::advance(double frame_seconds) {
  if (!playing_ || !world_) return;
  accumulator_ += std::min(frame_seconds, 0.25) * speed_;
  while (accumulator_ >= h_) {
    accumulator_ -= h_;
    step_one();
  }
}

void WorkbenchStage::build_view(const CameraView& camera, int width, int height, RenderView& out) const {
  out.camera = camera;
  out.time_seconds = double(tick_) * h_;
  out.meshes.clear();
  out.particles.clear();
  out.hud = {};
  std::vector<DrawnOwner> drawn;
  if (backdrop_.kind == BackdropKind::Wall) {
    MeshInstance m;
    m.model = wall_.id;
    // Its face a little behind the origin, so the effect's particles cut it.
    m.position = {0.0, 0.0, -double(wall_.bounds_max.z) - 2.0};
    out.meshes.push_back(m);
  } else if (!ships_.empty() && backdrop_.kind != BackdropKind::Space) {
    const StageModel& ship = ships_[backdrop_.model];
    MeshInstance m;
    m.model = ship.id;
    if (backdrop_.kind == BackdropKind::Model) {
      m.position = {0.0, 0.0, -ship.radius * 1.3};  // behind the stage, seen past the effect
    } else {
      const OwnerTransform t = circle_pose(tick_);
      m.position = t.position;
      m.orientation = t.orientation;
      drawn.push_back({kStageOwner, t.position, t.orientation});
    }
    out.meshes.push_back(m);
  }
  if (!world_) return;
  ParticleCamera pc;
  pc.position = camera.position;
  pc.orientation = camera.orientation;
  pc.fov_y_radians = camera.fov_y_radians;
  pc.aspect = height > 0 ? double(width) / double(height) : 1.0;
  pc.near_plane = camera.near_plane;
  world_->collect(pc, out.particles, drawn);
}

std::vector<uint32_t> WorkbenchStage::live_per_cluster() const {
  std::vector<uint32_t> counts(effect() ? effect()->clusters.size() : 0, 0);
  if (!world_) return counts;
  for (const Cluster& c : ParticleWorldAccess::state(*world_).slots)
    if (c.alive && c.def_index < counts.size()) counts[c.def_index] += uint32_t(c.pool.count());
  return counts;
}

uint32_t WorkbenchStage::live_particles() const { return world_ ? world_->stats().live_particles : 0; }

uint64_t WorkbenchStage::state_hash() const {
  StateHasher h;
  if (world_) world_->hash(h);
  return h.value();
}

void WorkbenchStage::bounds(glm::dvec3& centre, double& radius) const {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  bool any = false;
  if (world_) {
    ParticleCamera everywhere;
    everywhere.fov_y_radians = 3.1;  // nothing culled by direction
    std::vector<ParticleInstance> all;
    world_->collect(everywhere, all);
    for (const ParticleInstance& p : all) {
      const glm::dvec3 q(p.pos[0], p.pos[1], p.pos[2]);
      lo = glm::min(lo, q - double(p.size));
      hi = glm::max(hi, q + double(p.size));
      any = true;
    }
  }
  if (!any) {
    const double r = backdrop_.kind == BackdropKind::Space || ships_.empty() ? 5.0 : ships_[backdrop_.model].radius;
    centre = backdrop_.kind == BackdropKind::Circling ? circle_pose(tick_).position : glm::dvec3(0.0);
    radius = r;
    return;
  }
  centre = (lo + hi) * 0.5;
  radius = std::max(0.5, glm::length(hi - lo) * 0.5);
}

}  // namespace arc
