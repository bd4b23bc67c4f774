// game/render/sound_events.h — what the game sounds like this tick, read from the World.
//
// The simulation never calls audio, and sound adds nothing to its state or hash. Instead,
// SoundEventTracker compares each tick's World with what it remembered from the tick before
// (ships' shields, hulls, deaths, afterburners, beams; new and live projectiles and flares; the
// player's missile lock; the world's explosion list) and lists the sound events: one-shots (a launch, a hit, an explosion) and
// loops the app must keep asking for (beams, missile flight, engine hum). The app turns them
// into the audio engine's cues, the way a RenderView goes to the renderer. The list is a pure
// function of the World's sequence, so a replay gives the same events every run.
//
// Example, compiled as AppExamples.SoundsOfATick in tests/unit/app/test_app_examples.cpp:
//   SoundEventTracker sounds;
//   game.step(input);
//   for (const SoundEvent& e : sounds.collect(game.world())) audio.play(sound_cue(e));
#pragma once
#include <cstdint>
#include <vector>
#include <glm/vec3.hpp>

namespace arc {

class World;

enum class SoundKind : uint8_t {
  Beam,            // loop, per firing ship
  BeamHitShield,   // a shield took damage (beam, missile or plasma)
  BeamHitHull,     // a hull took damage
  ShieldRecharge,  // a shield starts regenerating
  MissileLaunch,
  MissileFlight,   // loop, per live missile
  PlasmaShot,
  Explosion,       // size: the blast radius
  Afterburner,     // lit
  EngineHum,       // loop, per live ship; intensity follows the throttle
  LockTick,        // the player's missile lock building: ticks that come faster as it fills
  LockTone,        // loop while the player's lock is complete
  Flare,           // a flare dropped
  PlayerHit,       // the player's ship took damage (heard at the listener, over the fight)
  MissileWarning,  // a missile homes on the player: at its launch, then every kWarningInterval
  Kill,            // the player destroyed a ship
};

// The name of the kind's sound in assets/sounds/sounds.json (and in replay messages).
const char* sound_kind_name(SoundKind kind);
bool is_loop(SoundKind kind);

struct SoundEvent {
  SoundKind kind = SoundKind::Explosion;
  glm::dvec3 position{0.0}, velocity{0.0};  // world frame
  double intensity = 1;  // 0..1: throttle, damage share
  double size = 0;       // explosions: blast radius in world units
  uint64_t owner = 0;    // ship index + 1, or a projectile's serial + 2^32: one loop per owner
};

class SoundEventTracker {
 public:
  // Events of the ticks since the last call (none while paused: loops then fade out). A world
  // whose tick went back or whose ships changed is a new game: the first call after it lists
  // only the loops, so a restart does not sound like a battle.
  std::vector<SoundEvent> collect(const World& w);

 private:
  struct ShipMemory {
    bool alive = false, afterburner = false, regenerating = false;
    double shield = 0, hull = 0;
    int64_t next_hit_sound = 0;  // hits sound at most every kHitInterval ticks per ship
  };
  void ship_events(const World& w, size_t index, std::vector<SoundEvent>& out);
  void projectile_events(const World& w, std::vector<SoundEvent>& out);
  glm::dvec3 hit_point(const World& w, size_t target) const;

  std::vector<ShipMemory> ships_;
  void lock_events(const World& w, std::vector<SoundEvent>& out);
  void flare_events(const World& w, std::vector<SoundEvent>& out);
  void player_events(const World& w, std::vector<SoundEvent>& out);

  std::vector<uint32_t> projectiles_;  // serials alive at the last call, sorted
  std::vector<uint32_t> flares_;       // flare serials alive at the last call, sorted
  int64_t next_warning_ = 0;           // no missile warning before this tick
  int player_kills_ = 0;
  int64_t next_lock_tick_ = 0;         // no lock tick before this tick
  int64_t tick_ = -1;
  bool primed_ = false;
};

}  // namespace arc
