// The workbench's scene: one effect, a backdrop, and an exact timeline (see the header).
#include "game/workbench/workbench_stage.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace arc {

WorkbenchStage::WorkbenchStage() {
  options_.circle_radius = 60.0;  // m: wide enough for the largest ship to turn visibly
  options_.circle_speed = 40.0;
}

WorkbenchStage::~WorkbenchStage() = default;

void WorkbenchStage::set_models(std::vector<StageModel> ships, StageModel wall) {
  ships_ = std::move(ships);
  wall_ = std::move(wall);
}

void WorkbenchStage::set_effect(std::shared_ptr<const EffectLibrary> library, const std::string& name) {
  library_ = std::move(library);
  effect_name_ = name;
  rebuild();
}

const EffectDef* WorkbenchStage::effect() const { return library_ ? &library_->get(effect_name_) : nullptr; }

// A fresh timeline (new effect, or the owner's motion changed) at the tick the stage was at.
void WorkbenchStage::rebuild() {
  if (!library_) return;
  options_.motion = backdrop_.kind == BackdropKind::Circling ? StageMotion::Circle : StageMotion::Still;
  timeline_ = std::make_unique<EffectTimeline>(library_, effect_name_, options_);
  scrub(tick_);
}

void WorkbenchStage::set_backdrop(Backdrop b) {
  const bool was_circling = backdrop_.kind == BackdropKind::Circling;
  backdrop_ = b;
  if (backdrop_.model >= ships_.size()) backdrop_.model = 0;
  if (was_circling != (b.kind == BackdropKind::Circling)) rebuild();
}

void WorkbenchStage::set_speed(double s) { speed_ = std::clamp(s, 0.1, 4.0); }

void WorkbenchStage::set_loop_seconds(double s) {
  loop_seconds_ = std::clamp(s, 0.1, 60.0);
  if (tick_ > loop_ticks()) scrub(0);
}

uint64_t WorkbenchStage::loop_ticks() const {
  return uint64_t(std::max(1.0, std::round(loop_seconds_ / options_.tick_seconds)));
}

double WorkbenchStage::effect_seconds(bool* ends) const {
  const EffectDef* def = effect();
  return def ? EffectTimeline::life_seconds(*def, ends) : 0.0;
}

void WorkbenchStage::scrub(uint64_t tick) {
  tick_ = std::min(tick, loop_ticks());
  accumulator_ = 0.0;
  if (timeline_) timeline_->scrub_to(tick_, camera_);
}

void WorkbenchStage::step_by(int ticks) {
  playing_ = false;
  const int64_t n = int64_t(loop_ticks()) + 1;
  const int64_t target = ((int64_t(tick_) + ticks) % n + n) % n;
  if (timeline_ && target == int64_t(tick_) + 1) {
    timeline_->play_step(camera_);
    tick_ = uint64_t(target);
  } else {
    scrub(uint64_t(target));
  }
}

void WorkbenchStage::advance(double frame_seconds) {
  if (!playing_ || !timeline_) return;
  accumulator_ += std::min(frame_seconds, 0.25) * speed_;
  while (accumulator_ >= options_.tick_seconds) {
    accumulator_ -= options_.tick_seconds;
    if (tick_ + 1 > loop_ticks()) {
      const double keep = accumulator_;
      scrub(0);  // the loop starts again: a fresh spawn
      accumulator_ = keep;
      continue;
    }
    timeline_->play_step(camera_);
    ++tick_;
  }
}

void WorkbenchStage::build_view(const CameraView& camera, int width, int height, RenderView& out) const {
  out.camera = camera;
  out.time_seconds = double(tick_) * options_.tick_seconds;
  out.meshes.clear();
  out.particles.clear();
  out.hud = {};
  if (backdrop_.kind == BackdropKind::Wall) {
    MeshInstance m;
    m.model = wall_.id;
    m.position = {0.0, 0.0, -double(wall_.bounds_max.z) - 2.0};  // its face just behind the stage
    out.meshes.push_back(m);
  } else if (!ships_.empty() && backdrop_.kind != BackdropKind::Space) {
    const StageModel& ship = ships_[backdrop_.model];
    MeshInstance m;
    m.model = ship.id;
    if (backdrop_.kind == BackdropKind::Model) {
      m.position = {0.0, 0.0, -ship.radius * 1.3};  // behind the stage, seen past the effect
    } else if (timeline_) {
      const OwnerTransform t = timeline_->owner_transform();
      const double stern = backdrop_.at_stern ? double(ship.bounds_max.z) : 0.0;  // +Z is aft
      m.position = t.position - t.orientation * glm::dvec3(0.0, 0.0, stern);
      m.orientation = t.orientation;
    }
    out.meshes.push_back(m);
  }
  if (!timeline_) return;
  ParticleCamera pc;
  pc.position = camera.position;
  pc.orientation = camera.orientation;
  pc.fov_y_radians = camera.fov_y_radians;
  pc.aspect = height > 0 ? double(width) / double(height) : 1.0;
  pc.near_plane = camera.near_plane;
  timeline_->world().collect(pc, out.particles);
}

EffectCounts WorkbenchStage::counts() const { return timeline_ ? timeline_->frame_stats() : EffectCounts{}; }

uint64_t WorkbenchStage::state_hash() const { return timeline_ ? timeline_->state_hash(camera_) : 0; }

uint32_t WorkbenchStage::particle_budget() const { return options_.particle_budget; }

void WorkbenchStage::set_particle_limits(uint32_t budget, int lightning_interval) {
  options_.particle_budget = budget;
  options_.lightning_interval = lightning_interval;
  if (library_) rebuild();
}

glm::dvec3 WorkbenchStage::focus() const {
  if (backdrop_.kind != BackdropKind::Circling || !timeline_) return glm::dvec3(0.0);
  return timeline_->owner_transform().position;
}

void WorkbenchStage::bounds(glm::dvec3& centre, double& radius) const {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  bool any = false;
  if (timeline_) {
    ParticleCamera everywhere;
    everywhere.fov_y_radians = 3.1;  // nothing culled by direction
    std::vector<ParticleInstance> all;
    timeline_->world().collect(everywhere, all);
    for (const ParticleInstance& p : all) {
      const glm::dvec3 q(p.pos[0], p.pos[1], p.pos[2]);
      lo = glm::min(lo, q - double(p.size));
      hi = glm::max(hi, q + double(p.size));
      any = true;
    }
  }
  if (any) {
    centre = (lo + hi) * 0.5;
    radius = std::max(0.5, glm::length(hi - lo) * 0.5);
    return;
  }
  const bool ship = backdrop_.kind != BackdropKind::Space && backdrop_.kind != BackdropKind::Wall && !ships_.empty();
  radius = ship ? ships_[backdrop_.model].radius : 5.0;
  centre = timeline_ && backdrop_.kind == BackdropKind::Circling ? timeline_->owner_transform().position : glm::dvec3(0.0);
}

}  // namespace arc
