// game/sim/world.h — the simulated state: ships, projectiles, the particle world, level state.
//
// World is plain data plus the particle world; Game (game/sim/game.h) steps it. Ships are kept
// in a vector in id order (ShipId::from_index), dead ships stay with alive = false so ids never
// move. Each ship keeps its previous tick's transform beside the current one, so the renderer
// can interpolate by alpha without the simulation knowing about frames. Particle owners are
// allocated by allocate_owner(): each ship gets one at level start, each projectile when fired.
#pragma once
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "game/sim/defs.h"
#include "game/sim/effects.h"
#include "game/sim/game.h"
#include "game/sim/ids.h"
#include "game/sim/input.h"
#include "particles/particle_world.h"

namespace arc {

class EffectLibrary;

// The nose direction of an orientation: ship-local −Z.
inline glm::dvec3 forward_of(const glm::dquat& q) { return q * glm::dvec3(0, 0, -1); }

enum class SecondaryWeapon : uint8_t { Missile = 0, Plasma = 1 };
enum class AiMode : uint8_t { Attack = 0, Evade = 1, BreakOff = 2 };
enum class CameraMode : uint8_t { Chase = 0, Cockpit = 1, Fixed = 2 };

struct AiState {
  AiMode mode = AiMode::Attack;
  ShipId target;
  int64_t mode_until = 0;      // tick at which the current evade / break-off ends
  int64_t next_think = 0;      // reaction time: decisions are refreshed at this tick
  glm::dvec3 aim_error{0.0};   // unit-sphere offset, scaled by distance and difficulty
  glm::dvec3 evade_dir{0.0};   // world direction while evading or breaking off
};

struct Ship {
  // Definition
  ShipId id;
  std::string name;
  TeamId team;
  OwnerId particle_owner;  // its shield, exhausts and beams are attached to this owner
  const ShipClassDef* cls = nullptr;
  int class_index = 0;  // index in World::class_names
  ModelSlot model;
  bool player = false;
  AiKind ai = AiKind::Fighter;
  // Motion (world frame; angular velocity in the ship frame, rad/s)
  glm::dvec3 position{0.0}, velocity{0.0}, angular_velocity{0.0};
  glm::dquat orientation{1, 0, 0, 0};
  glm::dvec3 prev_position{0.0};
  glm::dquat prev_orientation{1, 0, 0, 0};
  // Condition
  bool alive = true;
  double hull = 0, shield = 0, energy = 0;
  int64_t last_hit_tick = -1000000;   // shield regeneration waits after this
  int64_t shield_flash_tick = -1000000;
  int64_t death_tick = -1;
  ShipId last_attacker;
  int kills = 0;
  ShipId target;  // the ship's current target (player: HUD target)
  // Controls of this tick (from the InputFrame or the AI)
  InputFrame controls;
  bool afterburner_on = false;
  SecondaryWeapon secondary = SecondaryWeapon::Missile;
  double secondary_cooldown = 0;  // seconds until the next shot
  uint32_t hardpoint_cycle = 0;
  // Beam
  bool beam_firing = false;
  std::vector<ClusterHandle> beam_channels;  // one per mount while firing
  std::vector<double> beam_hit_distance;     // per channel; < 0 = no hit this tick
  ShipId beam_target;
  // Attached effects
  EffectHandle shield_fx;
  std::vector<EffectHandle> exhaust_fx;
  double shown_shield_intensity = -1;
  int shield_density = 4;          // quarters of full strength the shield cluster was spawned with
  int64_t shield_spawn_tick = 0;   // its burst is emitted at the next particle step
  double shown_exhaust_intensity = -1;
  AiState ai_state;
};

struct Projectile {
  uint32_t serial = 0;
  SecondaryWeapon kind = SecondaryWeapon::Missile;
  ShipId owner;             // the ship that fired it
  ShipId target;
  OwnerId particle_owner;   // its trail is attached to this owner
  glm::dvec3 position{0.0}, velocity{0.0}, prev_position{0.0};
  double damage = 0, turn_rate = 0, hit_radius = 0;
  int64_t expire_tick = 0;
  EffectHandle trail;
};

struct ExplosionEvent {
  glm::dvec3 position{0.0};
  int64_t tick = 0;
  double radius = 0;
};

struct Prop {
  ModelSlot model;
  std::string label;
  glm::dvec3 position{0.0};
  glm::dquat orientation{1, 0, 0, 0};
  double scale = 1, radius = 0;
};

struct CameraRig {
  glm::dvec3 position{0.0};
  glm::dquat orientation{1, 0, 0, 0};
};

enum class Outcome : uint8_t { Undecided = 0, Victory = 1, Defeat = 2, TeamWon = 3 };

class World {
 public:
  LevelDef level;
  std::vector<std::string> class_names;  // sorted, for class_index
  std::vector<std::string> team_names;   // in order of first appearance in the level, for TeamId
  std::vector<std::string> model_paths;  // every model the level needs (load only these), for ModelSlot
  std::vector<Ship> ships;
  std::vector<Projectile> projectiles;
  std::vector<Prop> props;
  std::vector<ExplosionEvent> explosions;  // recent ones, for hull flashes
  std::shared_ptr<const EffectLibrary> effects;
  GameEffects fx;  // the effects the game spawns, resolved in `effects` at load
  std::unique_ptr<ParticleWorld> particles;
  uint64_t seed = 1;
  int difficulty = 1;
  int64_t tick = 0;
  double dt = 1.0 / 60.0;
  uint32_t next_projectile_serial = 1;
  uint32_t next_particle_owner = 1;  // allocate_owner()
  bool paused = false;
  ShipId player;  // null in attract levels
  Outcome outcome = Outcome::Undecided;
  TeamId winner;  // winning team when decided (null: none)
  int64_t outcome_tick = -1;
  CameraMode camera_mode = CameraMode::Chase;
  CameraRig camera, prev_camera;
  GameOptions options;
  uint64_t steps = 0;  // step() calls, paused ones included

  World() = default;
  World(const World& o) { *this = o; }
  World& operator=(const World& o);

  Ship& ship(ShipId id) { return ships[id.index()]; }
  const Ship& ship(ShipId id) const { return ships[id.index()]; }
  // The ship the camera and HUD follow: the player, else the first live ship (null if none).
  ShipId focus_ship() const;
  bool hostile(const Ship& a, const Ship& b) const { return a.team != b.team; }
  // A team's name as the level spells it; "none" for the null team.
  const std::string& team_name(TeamId team) const;
};

// A particle owner no ship or projectile of this World has had before.
inline OwnerId allocate_owner(World& w) { return OwnerId{w.next_particle_owner++}; }

inline int64_t seconds_to_ticks(const World& w, double s) { return static_cast<int64_t>(std::llround(s / w.dt)); }

}  // namespace arc
