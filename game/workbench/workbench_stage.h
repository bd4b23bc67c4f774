// game/workbench/workbench_stage.h — the effect workbench's scene and clock (no GL).
//
// One effect on a stage at the origin, over a backdrop (empty space, a ship model behind it,
// the wall it can cut, or a ship flying a circle the effect is attached to), and the timeline a
// tweaker drives: play, pause, speed, one tick forwards or back, a loop period, and a scrub to
// any tick. The effect restarts at tick 0 every loop period.
//
// The particles come from an EffectTimeline (effect_timeline.h): playing steps it tick by tick,
// going back or jumping scrubs it by the catch-up path, and the two give the same state at a
// tick (tests/unit/workbench compares their hashes). Every step uses the camera last given,
// so a scrub and a play to the same tick agree for the view on screen too.
//
// Example, compiled as AppExamples.WorkbenchStage in tests/unit/app/test_app_examples.cpp:
//   WorkbenchStage stage;
//   stage.set_effect(doc->library(), doc->name());
//   stage.advance(frame_seconds);           // plays at the chosen speed
//   stage.scrub(90);                         // tick 90 (1.5 s), exactly
//   stage.build_view(camera, width, height, view);   // meshes and particles for the renderer
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include <glm/vec3.hpp>

#include "game/workbench/effect_timeline.h"
#include "gfx/render_view.h"

namespace arc {

enum class BackdropKind { Space, Model, Wall, Circling };

struct Backdrop {
  BackdropKind kind = BackdropKind::Space;
  size_t model = 0;  // Model and Circling: which of the stage's ship models
  // Circling: the effect sits at the ship's stern (engine exhausts) rather than its centre; the
  // ship is drawn shifted forwards so its stern is on the effect's owner.
  bool at_stern = false;
};

struct StageModel {
  std::string name;  // file stem: "viper"
  ModelId id{};      // the renderer's
  glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};
  double radius = 1.0;
};

class WorkbenchStage {
 public:
  WorkbenchStage();
  // The user's particles.budget and particles.lightning_interval, as the game would use them.
  void set_particle_limits(uint32_t budget, int lightning_interval);
  ~WorkbenchStage();

  // The models the backdrops use: the ships, and the wall (ids from the renderer).
  void set_models(std::vector<StageModel> ships, StageModel wall);
  const std::vector<StageModel>& ship_models() const { return ships_; }

  // A new or edited effect (a library holding it, as EffectDocument::library() gives), shown
  // at the tick the stage was at.
  void set_effect(std::shared_ptr<const EffectLibrary> library, const std::string& name);
  const EffectDef* effect() const;

  void set_backdrop(Backdrop b);
  Backdrop backdrop() const { return backdrop_; }
  void set_camera(const ParticleCamera& c) { camera_ = c; }  // the view the world steps with

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
  void step_by(int ticks);             // pauses, then moves by `ticks`, wrapping within the loop
  uint64_t tick() const { return tick_; }
  double tick_seconds() const { return options_.tick_seconds; }
  // The effect's length (EffectTimeline::life_seconds); `ends` false: it runs until stopped.
  double effect_seconds(bool* ends) const;

  // ---- drawing and figures ------------------------------------------------------------------
  void build_view(const CameraView& camera, int width, int height, RenderView& out) const;
  EffectCounts counts() const;
  uint64_t state_hash() const;  // EffectTimeline::state_hash for the stepping camera
  uint32_t particle_budget() const;
  // Where the orbit camera centres: the circling ship, else the stage's origin.
  glm::dvec3 focus() const;
  // A sphere around what is on stage: the particles or, with none, the backdrop.
  void bounds(glm::dvec3& centre, double& radius) const;

 private:
  void rebuild();

  StageOptions options_;
  std::shared_ptr<const EffectLibrary> library_;
  std::string effect_name_;
  std::unique_ptr<EffectTimeline> timeline_;
  std::vector<StageModel> ships_;
  StageModel wall_;
  Backdrop backdrop_;
  ParticleCamera camera_;
  bool playing_ = true;
  double speed_ = 1.0;
  double loop_seconds_ = 3.0;
  double accumulator_ = 0.0;
  uint64_t tick_ = 0;
};

}  // namespace arc
