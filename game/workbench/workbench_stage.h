// game/workbench/workbench_stage.h — the effect workbench's scene and clock (no GL).
//
// One effect spawned at the origin of an empty stage, over a backdrop (empty space, a ship
// model behind it, the wall it can cut, or a ship flying a circle the effect is attached to),
// and the timeline a tweaker drives: play, pause, speed, one tick forwards or back, a loop
// period, and a scrub to any tick. The effect restarts at tick 0 every loop period.
//
// Going back or jumping is exact: a fresh world spawns the effect at tick 0 and steps to the
// target in one call, which is the particle world's skip/catch-up path (emission and deaths
// tick by tick, the closed-form animation once at the end), so the state at tick T is the same
// whether it was played to or scrubbed to. On the circling backdrop the owner's pose is set
// for every tick on both paths, as the game does.
//
//   WorkbenchStage stage(root, 200000);
//   stage.set_effect(text, "assets/effects/hull_sparks.json");   // InputError: the loader's line
//   stage.advance(frame_seconds);           // plays at the chosen speed
//   stage.scrub(90);                         // tick 90 (1.5 s), exactly
//   stage.build_view(camera, width, height, view);   // meshes and particles for the renderer
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "gfx/render_view.h"
#include "particles/effect_library.h"
#include "particles/particle_world.h"

namespace arc {

enum class BackdropKind { Space, Model, Wall, Circling };

struct Backdrop {
  BackdropKind kind = BackdropKind::Space;
  size_t model = 0;  // Model and Circling: which of the stage's ship models
};

// Where an attached effect sits on the circling ship.
enum class AttachPoint { Centre, Stern, Nose };

struct StageModel {
  std::string name;  // file stem: "viper"
  ModelId id{};      // the renderer's
  glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};
  double radius = 1.0;
};

class WorkbenchStage {
 public:
  WorkbenchStage(uint32_t particle_budget, double tick_seconds = 1.0 / 60.0);
  ~WorkbenchStage();

  // The models the backdrops use: ships first, the wall separately (ids from the renderer).
  void set_models(std::vector<StageModel> ships, StageModel wall);
  const std::vector<StageModel>& ship_models() const { return ships_; }

  // Parses and validates effect text as the file `path` (InputError: the loader's one line; the
  // stage keeps the effect it had) and restarts it at the tick it was showing.
  void set_effect(const std::string& text, const std::string& path);
  const EffectDef* effect() const;

  void set_backdrop(Backdrop b);
  Backdrop backdrop() const { return backdrop_; }
  void set_attach_point(AttachPoint p);
  AttachPoint attach_point() const { return attach_; }
  // The view the particle world culls by while stepping (culling never changes a particle,
  // but the world records it, so play and scrub step with the same camera).
  void set_camera(const ParticleCamera& c) { camera_ = c; }

  // ---- time ---------------------------------------------------------------------------------
  void advance(double frame_seconds);  // plays `speed` × frame_seconds when playing
  void set_playing(bool on) { playing_ = on; }
  bool playing() const { return playing_; }
  void set_speed(double s);            // clamped to [0.1, 4]
  double speed() const { return speed_; }
  void set_loop_seconds(double s);     // clamped to [0.1, 60]
  double loop_seconds() const { return loop_seconds_; }
  uint64_t loop_ticks() const;
  void scrub(uint64_t tick);           // exact state at `tick` (clamped to the loop)
  void step_by(int ticks);             // pauses, then moves by `ticks` within the loop
  uint64_t tick() const { return tick_; }
  double tick_seconds() const { return h_; }
  // The effect's own length in seconds: its longest cluster (lifetime, or emission plus the
  // longest particle life); 0 when some cluster runs until stopped.
  double effect_seconds() const;

  // ---- drawing and figures ------------------------------------------------------------------
  void build_view(const CameraView& camera, int width, int height, RenderView& out) const;
  // Live particles per cluster of the effect (by index in its definition), this tick.
  std::vector<uint32_t> live_per_cluster() const;
  uint32_t live_particles() const;
  uint32_t particle_budget() const { return budget_; }
  uint64_t state_hash() const;  // ParticleWorld::hash of the current state
  // A sphere around what is on stage: the particles (world positions) or, with none, the backdrop.
  void bounds(glm::dvec3& centre, double& radius) const;

 private:
  void restart();
  void step_one();
  OwnerTransform circle_pose(uint64_t tick) const;
  glm::dvec3 attach_offset() const;

  uint32_t budget_;
  double h_;
  std::unique_ptr<EffectLibrary> library_;
  std::unique_ptr<ParticleWorld> world_;
  std::string effect_name_;
  std::vector<StageModel> ships_;
  StageModel wall_;
  Backdrop backdrop_;
  ParticleCamera camera_;
  AttachPoint attach_ = AttachPoint::Centre;
  bool playing_ = true;
  double speed_ = 1.0;
  double loop_seconds_ = 3.0;
  double accumulator_ = 0.0;
  uint64_t tick_ = 0;
};

}  // namespace arc
