// workbench/effect_timeline.h — one effect on the workbench stage, at any tick (no GL).
//
// Every particle is a closed-form function of its birth state and age, so the state at tick T
// can be reached two ways that must agree: playing (ParticleWorld::step every tick with the
// viewing camera, as the game does for clusters on screen) and scrubbing (every tick up to T
// stepped with a camera that sees nothing, so clusters only emit and die, then tick T with the
// viewing camera: the catch-up path the game uses for clusters that were culled). state_hash()
// covers the world's summary and every drawn particle, so tests compare the two paths.
//
// The effect is spawned at tick 0 at the origin, facing −Z, either standing still or attached to
// an owner flying a circle (trails and owner-space clusters need a moving owner to show).
//
// Example, compiled as WorkbenchExamples.ScrubAndStep in tests/unit/workbench/test_workbench_examples.cpp:
//   EffectTimeline t(doc->library(), doc->name(), {.motion = StageMotion::Still});
//   t.scrub_to(90, camera);         // tick 90 by the catch-up path
//   t.play_step(camera);            // tick 91 by normal stepping
//   world = &t.world();             // for collect(); counts in t.frame_stats()
//   // after an edit (doc->revision() changed): a timeline on the new library, at the same tick
//   t = EffectTimeline(doc->library(), doc->name(), stage);  t.scrub_to(tick, camera);
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "particles/effect_library.h"
#include "particles/particle_world.h"

namespace arc {

enum class StageMotion {
  Still,   // spawned free at the origin
  Circle,  // attached to an owner flying a horizontal circle around the origin
};

struct StageOptions {
  StageMotion motion = StageMotion::Still;
  double circle_radius = 20.0;   // m
  double circle_speed = 30.0;    // m/s along the circle
  uint64_t seed = 1;
  double tick_seconds = 1.0 / 60.0;
  uint32_t particle_budget = ParticleConfig{}.budget;        // particles.budget
  int lightning_interval = ParticleConfig{}.lightning_interval;  // particles.lightning_interval
};

struct EffectCounts {
  uint64_t tick = 0;
  uint32_t live_particles = 0;
  std::vector<uint32_t> cluster_particles;  // per cluster of the effect, in file order (0 once gone)
};

class EffectTimeline {
 public:
  EffectTimeline(std::shared_ptr<const EffectLibrary> library, const std::string& effect, const StageOptions& stage = {});

  // Back to tick 0: a fresh world with the effect just spawned.
  void restart();
  // One tick forwards by normal stepping.
  void play_step(const ParticleCamera& camera);
  // Exactly tick T, forwards or backwards, by the catch-up path (a fresh world when T < tick()).
  void scrub_to(uint64_t tick, const ParticleCamera& camera);
  uint64_t tick() const;

  const ParticleWorld& world() const { return *world_; }
  // Where the owner is at the current tick (the stage origin when Still); for a backdrop ship.
  OwnerTransform owner_transform() const;
  EffectCounts frame_stats() const;
  // Summary hash of the world and of every particle collect() gives for this camera.
  uint64_t state_hash(const ParticleCamera& camera) const;

  // Seconds until the effect is over when it ends by itself (bursts, cluster lifetimes,
  // emitter durations); a looping window (the longest particle lifetime, at least 1 s, twice)
  // for effects that emit until stopped. `ends` says which.
  static double life_seconds(const EffectDef& def, bool* ends = nullptr);
  double life_seconds() const;

 private:
  void set_owner(uint64_t tick);

  std::shared_ptr<const EffectLibrary> library_;
  std::string effect_;
  StageOptions stage_;
  std::unique_ptr<ParticleWorld> world_;
  EffectHandle handle_;
};

}  // namespace arc
