// game/sim/world.h — the simulated state: ships, projectiles, the particle world, level state.
//
// World is plain data plus the particle world; Game (game/sim/game.h) steps it. Ships are kept
// in a vector in id order (ShipId::from_index), dead ships stay with alive = false so ids never move.
// Each ship keeps its previous tick's transform beside the current one, so the renderer can
// interpolate by alpha without the simulation knowing about frames. Particle owners are
// allocated by allocate_owner(): each ship gets one at level start, each projectile when fired.
// A World copies deeply (its particle world too); copies share the immutable level definitions.
//
// Every struct here is followed by its field visitor (core/state_fields.h), the one list
// of its fields that Game::hash, the snapshot (serialize.cpp) and Game::state_dump follow. The
// per-tick hash takes every struct's state_hash words, then (a second pass over the world)
// its presentation_hash words; word numbers are frozen, since replays store these hashes. A
// field added to a struct and not to its visitor fails tests/unit/game/test_state_fields.cpp.
#pragma once
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
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
#include "core/state_fields.h"

namespace arc {

class EffectLibrary;

// The nose direction of an orientation: ship-local −Z.
inline glm::dvec3 forward_of(const glm::dquat& q) { return q * glm::dvec3(0, 0, -1); }

enum class SecondaryWeapon : uint8_t { Missile = 0, Plasma = 1, Torpedo = 2 };
enum class AiMode : uint8_t { Attack = 0, Evade = 1, BreakOff = 2 };
// Padlock: the chase camera turned to keep the player's target in view (camera_rig.h).
enum class CameraMode : uint8_t { Chase = 0, Cockpit = 1, Fixed = 2, Padlock = 3 };
enum class Outcome : uint8_t { Undecided = 0, Victory = 1, Defeat = 2, TeamWon = 3 };
// The player's standing order to the wing (game/sim/wing.h).
enum class WingOrder : uint8_t { EngageAtWill = 0, Attack = 1, Cover = 2, FormUp = 3 };
// Who a message on the HUD speaks for: a wingman, reinforcements of the player's side or hostile ones.
// Radio: a line an event gives a named speaker ("Speaker: text").
enum class MessageKind : uint8_t { Wing = 0, Friendly = 1, Hostile = 2, Radio = 3 };
// The last value of each enum: a snapshot's byte beyond it is an error.
constexpr SecondaryWeapon last_enumerator(SecondaryWeapon) { return SecondaryWeapon::Torpedo; }
constexpr AiMode last_enumerator(AiMode) { return AiMode::BreakOff; }
constexpr CameraMode last_enumerator(CameraMode) { return CameraMode::Padlock; }
constexpr Outcome last_enumerator(Outcome) { return Outcome::TeamWon; }
constexpr WingOrder last_enumerator(WingOrder) { return WingOrder::FormUp; }
constexpr MessageKind last_enumerator(MessageKind) { return MessageKind::Radio; }

// Where the per-tick hash takes a field: word W of the state pass or of the presentation pass.
inline constexpr int kStateHashPass = 0;
inline constexpr int kPresentationHashPass = 1;
template <int W, fields::HashAs As = fields::HashAs::value>
inline constexpr fields::HashAt<kStateHashPass, W, As> state_hash;
template <int W, fields::HashAs As = fields::HashAs::value>
inline constexpr fields::HashAt<kPresentationHashPass, W, As> presentation_hash;

// Saved fields the snapshot reader validates: an id into World::ships, World::model_paths or
// World::team_names (0 for none, else index + 1 within the table), or a particle owner the world
// has handed out (allocate_owner: 1..next_particle_owner - 1).
struct ShipRef : fields::Saved {};
struct ModelRef : fields::Saved {};
struct TeamRef : fields::Saved {};
struct OwnerRef : fields::Saved {};
inline constexpr ShipRef ship_ref;
inline constexpr ModelRef model_ref;
inline constexpr TeamRef team_ref;
inline constexpr OwnerRef owner_ref;
// The settings a world is made with: the snapshot's header (serialize.cpp) holds them, restore
// loads the level with them.
struct LevelSettings {};
inline constexpr LevelSettings level_settings;

struct AiState {
  AiMode mode = AiMode::Attack;
  ShipId target;
  int64_t mode_until = 0;      // tick at which the current evade / break-off ends
  int64_t next_think = 0;      // reaction time: decisions are refreshed at this tick
  int64_t tail_since = -1;     // tick it got on a player's tail (−1: not on one)
  glm::dvec3 aim_error{0.0};   // unit-sphere offset, scaled by distance and difficulty
  glm::dvec3 evade_dir{0.0};   // world direction while evading or breaking off
};

template <fields::MaybeConst<AiState> A, class V>
void visit_fields(A& a, V&& v) {
  v("mode", a.mode, fields::saved, state_hash<0>);
  v("target", a.target, ship_ref, state_hash<1>);
  v("mode_until", a.mode_until, fields::saved, state_hash<2>);
  v("next_think", a.next_think, fields::saved, state_hash<3>);
  v("tail_since", a.tail_since, fields::saved, state_hash<6>);
  v("aim_error", a.aim_error, fields::saved, state_hash<4>);
  v("evade_dir", a.evade_dir, fields::saved, state_hash<5>);
}

// What a ship has done in this game, for the results screen, the summary and replay `expect`
// lines. Beam accuracy counts ticks: a tick the beam fires is a shot, one where any of its
// channels stays on a hostile is a hit. Missile shots are every secondary projectile (missiles
// and plasma bolts); a hit is one that strikes a hostile ship. Damage counts what shields and
// hulls took, never more than was left of them; the plasma's share of the secondary shots and
// the damage dealt by each secondary weapon are kept apart too (the beam's is the rest).
struct CombatStats {
  double damage_dealt = 0, damage_taken = 0;
  int64_t beam_ticks = 0, beam_hit_ticks = 0;
  int64_t missiles_fired = 0, missiles_hit = 0;
  int64_t plasma_fired = 0, plasma_hit = 0;
  double missile_damage = 0, plasma_damage = 0;
};

template <fields::MaybeConst<CombatStats> C, class V>
void visit_fields(C& c, V&& v) {
  v("damage_dealt", c.damage_dealt, fields::saved, state_hash<0>);
  v("damage_taken", c.damage_taken, fields::saved, state_hash<1>);
  v("beam_ticks", c.beam_ticks, fields::saved, state_hash<2>);
  v("beam_hit_ticks", c.beam_hit_ticks, fields::saved, state_hash<3>);
  v("missiles_fired", c.missiles_fired, fields::saved, state_hash<4>);
  v("missiles_hit", c.missiles_hit, fields::saved, state_hash<5>);
  v("plasma_fired", c.plasma_fired, fields::saved, state_hash<6>);
  v("plasma_hit", c.plasma_hit, fields::saved, state_hash<7>);
  v("missile_damage", c.missile_damage, fields::saved, state_hash<8>);
  v("plasma_damage", c.plasma_damage, fields::saved, state_hash<9>);
}

// A ship's missile lock and flares (game/sim/seekers.h). The lock builds while the ship's
// target stays within its missile's lock cone and range; lock_ticks counts those ticks.
struct SeekerState {
  ShipId lock_target;               // the ship the lock is building on (null: none)
  int64_t lock_ticks = 0;           // ticks it has been held
  int flares = 0;                   // flares left
  int64_t flare_ready_tick = 0;     // no flare before this tick (the cooldown)
};

template <fields::MaybeConst<SeekerState> S, class V>
void visit_fields(S& s, V&& v) {
  v("lock_target", s.lock_target, ship_ref, state_hash<0>);
  v("lock_ticks", s.lock_ticks, fields::saved, state_hash<1>);
  v("flares", s.flares, fields::saved, state_hash<2>);
  v("flare_ready_tick", s.flare_ready_tick, fields::saved, state_hash<3>);
}

// A capital ship's turret or subsystem (ShipClassDef::turrets, then ::subsystems): its hull, and
// for a turret the tick it may fire next, the ship it aims at, the tick it last fired and the
// bolt of a beam turret while it shows.
struct PartState {
  double hull = 0;
  int64_t ready_tick = 0;
  ShipId aim;
  int64_t fired_tick = -1;
  EffectHandle bolt;
};

template <fields::MaybeConst<PartState> P, class V>
void visit_fields(P& p, V&& v) {
  v("hull", p.hull, fields::saved, state_hash<0>);
  v("ready_tick", p.ready_tick, fields::saved, state_hash<1>);
  v("aim", p.aim, ship_ref, state_hash<2>);
  v("fired_tick", p.fired_tick, fields::saved, state_hash<3>);
  v("bolt", p.bolt, fields::saved, presentation_hash<0>);
}

// Shots that hit as a share of shots fired; 0 before the first shot.
inline double accuracy(int64_t hits, int64_t shots) { return shots > 0 ? double(hits) / double(shots) : 0.0; }

struct Ship {
  // Definition
  ShipId id;
  std::string name;
  TeamId team;
  OwnerId particle_owner;             // its shield, exhausts and beams are attached to this owner
  const ShipClassDef* cls = nullptr;  // one of World::level.classes
  ModelSlot model;                    // position in World::model_paths
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
  CombatStats stats;
  SeekerState seeker;
  // Capital ships: one entry per turret and subsystem (empty for fighters, so their hashes stay).
  std::vector<PartState> parts;
  // The part of `target` this ship aims at: none or one entry (an index into its parts).
  std::vector<int32_t> target_part;
  // Primary trigger firing plasma (a loadout): its cooldown, in one entry; empty otherwise.
  std::vector<double> primary_cooldown;
};

// A wave's ship before its wave arrives: not alive, never killed (game/sim/waves.h).
inline bool waiting(const Ship& s) { return !s.alive && s.death_tick < 0; }
// Alive, or still to arrive with its wave: the outcome counts it.
inline bool in_fight(const Ship& s) { return s.alive || waiting(s); }

// Name, class, team, player, AI kind and model come from the level and never change: unhashed.
template <fields::MaybeConst<Ship> S, class V>
void visit_fields(S& s, V&& v) {
  v("id", s.id, fields::checked, state_hash<0>);
  v("name", s.name, fields::checked, fields::unhashed);
  v("class", s.cls, fields::checked, fields::unhashed);  // saved as the class name
  v("team", s.team, team_ref, fields::unhashed);
  v("particle_owner", s.particle_owner, owner_ref, state_hash<22>);
  v("player", s.player, fields::saved, fields::unhashed);
  v("ai", s.ai, fields::saved, fields::unhashed);
  v("position", s.position, fields::saved, state_hash<2>);
  v("velocity", s.velocity, fields::saved, state_hash<3>);
  v("angular_velocity", s.angular_velocity, fields::saved, state_hash<4>);
  v("orientation", s.orientation, fields::saved, state_hash<5>);
  v("prev_position", s.prev_position, fields::saved, presentation_hash<0>);
  v("prev_orientation", s.prev_orientation, fields::saved, presentation_hash<1>);
  v("alive", s.alive, fields::saved, state_hash<1>);
  v("hull", s.hull, fields::saved, state_hash<6>);
  v("shield", s.shield, fields::saved, state_hash<7>);
  v("energy", s.energy, fields::saved, state_hash<8>);
  v("last_hit_tick", s.last_hit_tick, fields::saved, state_hash<9>);
  v("shield_flash_tick", s.shield_flash_tick, fields::saved, presentation_hash<2>);
  v("death_tick", s.death_tick, fields::saved, presentation_hash<3>);
  v("last_attacker", s.last_attacker, ship_ref, state_hash<10>);
  v("kills", s.kills, fields::saved, state_hash<11>);
  v("target", s.target, ship_ref, state_hash<12>);
  v("controls", s.controls, fields::saved, state_hash<13>);
  v("afterburner_on", s.afterburner_on, fields::saved, state_hash<14>);
  v("secondary", s.secondary, fields::saved, state_hash<15>);
  v("secondary_cooldown", s.secondary_cooldown, fields::saved, state_hash<16>);
  v("hardpoint_cycle", s.hardpoint_cycle, fields::saved, state_hash<17>);
  v("beam_firing", s.beam_firing, fields::saved, state_hash<18>);
  v("beam_channels", s.beam_channels, fields::saved, presentation_hash<10>);
  v("beam_hit_distance", s.beam_hit_distance, fields::saved, state_hash<20>);
  v("beam_target", s.beam_target, ship_ref, state_hash<19>);
  v("shield_fx", s.shield_fx, fields::saved, presentation_hash<8>);
  v("exhaust_fx", s.exhaust_fx, fields::saved, presentation_hash<9>);
  v("shown_shield_intensity", s.shown_shield_intensity, fields::saved, presentation_hash<4>);
  v("shield_density", s.shield_density, fields::saved, presentation_hash<6>);
  v("shield_spawn_tick", s.shield_spawn_tick, fields::saved, presentation_hash<7>);
  v("shown_exhaust_intensity", s.shown_exhaust_intensity, fields::saved, presentation_hash<5>);
  v("ai_state", s.ai_state, fields::saved, state_hash<21>);
  v("stats", s.stats, fields::saved, state_hash<23>);
  v("seeker", s.seeker, fields::saved, state_hash<24>);
  v("parts", s.parts, fields::saved, state_hash<25>);
  v("target_part", s.target_part, fields::saved, state_hash<26>);
  v("primary_cooldown", s.primary_cooldown, fields::saved, state_hash<27>);
  v("model", s.model, fields::not_saved, fields::unhashed);  // the class's model
}

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
  uint32_t decoy = 0;       // serial of the flare it chases instead of its target (0: none)
  std::vector<int32_t> part;  // torpedoes: the target's part it homes on (none or one entry)
};

// Damage, turn rate and hit radius come from the weapon's definition at the shot: unhashed.
template <fields::MaybeConst<Projectile> P, class V>
void visit_fields(P& p, V&& v) {
  v("serial", p.serial, fields::saved, state_hash<0>);
  v("kind", p.kind, fields::saved, state_hash<1>);
  v("owner", p.owner, ship_ref, state_hash<2>);
  v("target", p.target, ship_ref, state_hash<3>);
  v("particle_owner", p.particle_owner, owner_ref, state_hash<7>);
  v("position", p.position, fields::saved, state_hash<4>);
  v("velocity", p.velocity, fields::saved, state_hash<5>);
  v("prev_position", p.prev_position, fields::saved, presentation_hash<0>);
  v("damage", p.damage, fields::saved, fields::unhashed);
  v("turn_rate", p.turn_rate, fields::saved, fields::unhashed);
  v("hit_radius", p.hit_radius, fields::saved, fields::unhashed);
  v("expire_tick", p.expire_tick, fields::saved, state_hash<6>);
  v("trail", p.trail, fields::saved, presentation_hash<1>);
  v("decoy", p.decoy, fields::saved, state_hash<8>);
  v("part", p.part, fields::saved, state_hash<9>);
}

// A flare dropped against missiles: it drifts behind its ship, burns for its lifetime and
// draws missiles that took it for their target (Projectile::decoy).
struct Flare {
  uint32_t serial = 0;      // from World::next_projectile_serial
  ShipId owner;             // the ship that dropped it
  OwnerId particle_owner;   // its glow is attached to this owner
  glm::dvec3 position{0.0}, velocity{0.0}, prev_position{0.0};
  int64_t expire_tick = 0;
  EffectHandle fx;
};

template <fields::MaybeConst<Flare> F, class V>
void visit_fields(F& f, V&& v) {
  v("serial", f.serial, fields::saved, state_hash<0>);
  v("owner", f.owner, ship_ref, state_hash<1>);
  v("particle_owner", f.particle_owner, owner_ref, state_hash<2>);
  v("position", f.position, fields::saved, state_hash<3>);
  v("velocity", f.velocity, fields::saved, state_hash<4>);
  v("prev_position", f.prev_position, fields::saved, presentation_hash<0>);
  v("expire_tick", f.expire_tick, fields::saved, state_hash<5>);
  v("fx", f.fx, fields::saved, presentation_hash<1>);
}

struct ExplosionEvent {
  glm::dvec3 position{0.0};
  int64_t tick = 0;
  double radius = 0;
};

template <fields::MaybeConst<ExplosionEvent> E, class V>
void visit_fields(E& e, V&& v) {
  v("position", e.position, fields::saved, presentation_hash<0>);
  v("tick", e.tick, fields::saved, presentation_hash<1>);
  v("radius", e.radius, fields::saved, presentation_hash<2>);
}

struct Prop {
  ModelSlot model;
  std::string label;
  glm::dvec3 position{0.0};
  glm::dquat orientation{1, 0, 0, 0};
  double scale = 1, radius = 0;
};

// Props are placed by the level and never move: saved, unhashed.
template <fields::MaybeConst<Prop> P, class V>
void visit_fields(P& p, V&& v) {
  v("model", p.model, model_ref, fields::unhashed);
  v("label", p.label, fields::saved, fields::unhashed);
  v("position", p.position, fields::saved, fields::unhashed);
  v("orientation", p.orientation, fields::saved, fields::unhashed);
  v("scale", p.scale, fields::saved, fields::unhashed);
  v("radius", p.radius, fields::saved, fields::unhashed);
}

// Where a training level's player stands (game/sim/training.h): the step under way (the steps'
// count once all are done), the tick it began, what its condition has gathered so far (degrees
// turned, seconds of afterburner) and the player's missile hits when it began.
struct TrainingProgress {
  int32_t step = 0;
  int64_t step_tick = 0;
  double progress = 0;
  int64_t missile_hits_before = 0;
};

template <fields::MaybeConst<TrainingProgress> T, class V>
void visit_fields(T& t, V&& v) {
  v("step", t.step, fields::saved, state_hash<0>);
  v("step_tick", t.step_tick, fields::saved, state_hash<1>);
  v("progress", t.progress, fields::saved, state_hash<2>);
  v("missile_hits_before", t.missile_hits_before, fields::saved, state_hash<3>);
}

// A ship that has not arrived yet: not alive and never destroyed (a training step spawns it).
inline bool dormant(const Ship& s) { return !s.alive && s.death_tick < 0; }

struct CameraRig {
  glm::dvec3 position{0.0};
  glm::dquat orientation{1, 0, 0, 0};
};

template <fields::MaybeConst<CameraRig> C, class V>
void visit_fields(C& c, V&& v) {
  v("position", c.position, fields::saved, presentation_hash<0>);
  v("orientation", c.orientation, fields::saved, presentation_hash<1>);
}

// A ship the level flags "wing": it takes the player's orders. `target` is the ship an attack
// order named; `slot` its place in the formation (1 = first off the player's wing).
struct Wingman {
  ShipId ship;
  WingOrder order = WingOrder::EngageAtWill;
  ShipId target;
  int32_t slot = 1;
};

template <fields::MaybeConst<Wingman> M, class V>
void visit_fields(M& m, V&& v) {
  v("ship", m.ship, ship_ref, state_hash<0>);
  v("order", m.order, fields::saved, state_hash<1>);
  v("target", m.target, ship_ref, state_hash<2>);
  v("slot", m.slot, fields::saved, state_hash<3>);
}

// A reinforcement wave of the level (LevelDef::waves): the tick it arrived, −1 while it waits.
struct WaveState {
  int64_t arrived_tick = -1;
};

template <fields::MaybeConst<WaveState> S, class V>
void visit_fields(S& s, V&& v) {
  v("arrived_tick", s.arrived_tick, fields::saved, state_hash<0>);
}

// A line the HUD shows for a while (wing replies, reinforcements), with the tick it was posted.
struct SimMessage {
  int64_t tick = 0;
  MessageKind kind = MessageKind::Wing;
  std::string text;
};

template <fields::MaybeConst<SimMessage> M, class V>
void visit_fields(M& m, V&& v) {
  v("tick", m.tick, fields::saved, presentation_hash<0>);
  v("kind", m.kind, fields::saved, presentation_hash<1>);
  v("text", m.text, fields::saved, presentation_hash<2>);
}

// A capital ship breaking up (game/sim/capital.h): its wreck drifts and turns from the tick it
// died; `stage` blasts have gone off, the final one ends it.
struct BreakUp {
  ShipId ship;
  int64_t start_tick = 0;
  int32_t stage = 0;
  glm::dvec3 position{0.0}, velocity{0.0};
  glm::dquat orientation{1, 0, 0, 0};
  glm::dvec3 prev_position{0.0};
  glm::dquat prev_orientation{1, 0, 0, 0};
};

template <fields::MaybeConst<BreakUp> B, class V>
void visit_fields(B& b, V&& v) {
  v("ship", b.ship, ship_ref, state_hash<0>);
  v("start_tick", b.start_tick, fields::saved, state_hash<1>);
  v("stage", b.stage, fields::saved, state_hash<2>);
  v("position", b.position, fields::saved, state_hash<3>);
  v("velocity", b.velocity, fields::saved, state_hash<4>);
  v("orientation", b.orientation, fields::saved, state_hash<5>);
  v("prev_position", b.prev_position, fields::saved, presentation_hash<0>);
  v("prev_orientation", b.prev_orientation, fields::saved, presentation_hash<1>);
}

// A network match's slot (LevelDef::slots): its ship, and whether a pilot flies it (else the
// AI does). Set by Game::set_pilots; not in snapshots (the match sets it again after a restore).
struct PilotSlot {
  ShipId ship;
  bool piloted = false;
};

template <fields::MaybeConst<PilotSlot> P, class V>
void visit_fields(P& p, V&& v) {
  v("ship", p.ship, fields::not_saved, state_hash<0>);
  v("piloted", p.piloted, fields::not_saved, state_hash<1>);
}

}  // namespace arc

#include "game/sim/mission_state.h"  // NOLINT: needs the hash words and reference tags above

namespace arc {

class World {
 public:
  LevelDef level;
  std::vector<std::string> team_names;   // in order of first appearance in the level, for TeamId
  std::vector<std::string> model_paths;  // every model the level needs (load only these), for ModelSlot
  std::vector<Ship> ships;
  std::vector<Projectile> projectiles;
  std::vector<Flare> flares;
  std::vector<Prop> props;
  std::vector<ExplosionEvent> explosions;  // recent ones, for hull flashes
  std::shared_ptr<const EffectLibrary> effects;
  GameEffects fx;                          // the effects the game spawns, resolved in `effects` at load
  std::optional<ParticleWorld> particles;  // made by init_world
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
  // Present only in levels with a "training" block: in other levels the hash and the snapshot
  // take nothing from it.
  std::optional<TrainingProgress> training;
  GameOptions options;
  uint64_t steps = 0;  // step() calls, paused ones included
  std::vector<Wingman> wing;            // the player's wingmen, in level order (empty: no wing)
  std::vector<WaveState> waves;         // one per LevelDef::waves entry; their ships wait, not alive
  std::vector<SimMessage> messages;     // newest last, at most kMaxMessages
  // Present only in levels with "objectives" or "events" (game/sim/mission_events.h).
  std::optional<MissionProgress> mission;
  std::vector<BreakUp> breakups;        // capital ships breaking up (empty: none)
  std::vector<PilotSlot> pilots;        // network matches only (empty: the one player's input)

  Ship& ship(ShipId id) { return ships[id.index()]; }
  const Ship& ship(ShipId id) const { return ships[id.index()]; }
  // The ship the camera and HUD follow: the player, else the first live ship (null if none).
  ShipId focus_ship() const;
  bool hostile(const Ship& a, const Ship& b) const { return a.team != b.team; }
  // A team's name as the level spells it; "none" for the null team.
  const std::string& team_name(TeamId team) const;
};

// The hash's state pass: the counters and outcome, then every ship's and every projectile's
// state; its presentation pass: every ship's and projectile's presentation, the explosions, the
// camera rig (it decides particle culling) and the particle world's per-cluster summary.
template <fields::MaybeConst<World> W, class V>
void visit_fields(W& w, V&& v) {
  v("level", w.level, level_settings, fields::unhashed);  // static definitions; its name and tick rate
  v("seed", w.seed, level_settings, state_hash<1>);
  v("difficulty", w.difficulty, level_settings, state_hash<2>);
  v("options", w.options, level_settings, fields::unhashed);
  v("tick", w.tick, fields::saved, state_hash<0>);
  v("steps", w.steps, fields::saved, fields::unhashed);  // in full_hash(): a paused step changes nothing else
  v("next_projectile_serial", w.next_projectile_serial, fields::saved, state_hash<7>);
  v("next_particle_owner", w.next_particle_owner, fields::saved, state_hash<10>);
  v("paused", w.paused, fields::saved, state_hash<3>);
  v("player", w.player, ship_ref, fields::unhashed);  // set by the level
  v("outcome", w.outcome, fields::saved, state_hash<4>);
  v("winner", w.winner, team_ref, state_hash<5>);
  v("outcome_tick", w.outcome_tick, fields::saved, state_hash<6>);
  v("camera_mode", w.camera_mode, fields::saved, presentation_hash<3>);
  v("camera", w.camera, fields::saved, presentation_hash<4>);
  v("prev_camera", w.prev_camera, fields::saved, presentation_hash<5>);
  v("training", w.training, fields::saved, state_hash<14>);  // only in training levels
  v("ships", w.ships, fields::checked, state_hash<8>, presentation_hash<0>);
  v("projectiles", w.projectiles, fields::saved, state_hash<9>, presentation_hash<1>);
  v("flares", w.flares, fields::saved, state_hash<11>, presentation_hash<7>);
  v("props", w.props, fields::checked, fields::unhashed);
  v("explosions", w.explosions, fields::saved, presentation_hash<2>);
  v("particles", w.particles, fields::saved, presentation_hash<6>);  // its own snapshot; hash_summary
  // Empty lists hash to nothing, so levels without a wing or waves keep their hashes.
  v("wing", w.wing, fields::saved, state_hash<12>);
  v("waves", w.waves, fields::checked, state_hash<13>);
  v("messages", w.messages, fields::saved, presentation_hash<8>);
  v("mission", w.mission, fields::saved, state_hash<15>);  // only in levels with events or objectives
  v("breakups", w.breakups, fields::saved, state_hash<16>, presentation_hash<9>);
  v("pilots", w.pilots, fields::not_saved, state_hash<17>);  // empty outside network matches
  v("team_names", w.team_names, fields::not_saved, fields::unhashed);    // from the level
  v("model_paths", w.model_paths, fields::not_saved, fields::unhashed);  // from the level
  v("effects", w.effects, fields::not_saved, fields::unhashed);          // the shared library
  v("fx", w.fx, fields::not_saved, fields::unhashed);                    // resolved in `effects` at load
  v("dt", w.dt, fields::not_saved, fields::unhashed);                    // from the level's tick rate
}

// A particle owner no ship or projectile of this World has had before. (Moving level effects
// use owners of their own from 2^31 up, level_effect_owner in game/sim/effects.h.)
inline OwnerId allocate_owner(World& w) { return OwnerId{w.next_particle_owner++}; }

// How many messages World::messages keeps.
inline constexpr size_t kMaxMessages = 8;

inline int64_t seconds_to_ticks(const World& w, double s) { return static_cast<int64_t>(std::llround(s / w.dt)); }

}  // namespace arc
