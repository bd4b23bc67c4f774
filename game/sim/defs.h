// game/sim/defs.h — ship classes and levels as plain definitions loaded from JSON.
//
// Loaders only fill defs and validate every value through core/json.h, so a wrong file fails
// with `path:line:col: what is wrong and what is allowed` before anything is simulated.
// ShipClassDef comes from assets/ships/*.json, LevelDef from levels/*.json, the AI pilots'
// difficulties from assets/settings/ai.json (see levels/README.md for every key). Paths inside
// files are relative to GameOptions::root_dir. One loader file per format: ship_class_defs.cpp,
// level_defs.cpp, mission_defs.cpp (a level's "mission" block), wave_defs.cpp (its "waves"),
// ai_defs.cpp.
//
// Example, compiled as GameExamples.LoadALevel in tests/unit/game/test_game_examples.cpp:
//   LevelDef level = load_level_def("levels/duel.json", ".");   // also loads the ship classes
#pragma once
#include <array>
#include <optional>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>
#include <glm/vec3.hpp>

#include "game/sim/event_defs.h"
#include "game/sim/input.h"

namespace arc {

struct BeamDef {
  std::vector<glm::dvec3> mounts;   // ship-local, forward is −Z
  double range = 600.0;             // metres
  double damage_per_second = 40.0;  // split over the mounts
  double energy_per_second = 25.0;
};

struct ProjectileWeaponDef {
  bool present = false;
  std::vector<glm::dvec3> hardpoints;
  double speed = 300.0;         // m/s relative to the ship
  double damage = 30.0;
  double energy = 10.0;         // per shot
  double cooldown = 1.0;        // seconds between shots
  double lifetime = 6.0;        // seconds
  double turn_rate = 90.0;      // degrees per second (missiles home, plasma does not)
  double hit_radius = 1.0;
  // Missiles only: a missile leaves only once its target was held within lock_cone of the nose
  // and within lock_range for lock_time, and homes on it. In flight its
  // seeker keeps the target only within seeker_cone of its heading (a target that turns out of
  // it is lost), and flares inside that cone can pull it away.
  double lock_time = 1.75;      // seconds
  double lock_cone = 13.0;      // degrees off the nose
  double lock_range = 1200.0;   // metres
  double seeker_cone = 50.0;    // degrees off the missile's heading
};

// Flares: dropped on the countermeasure command, `count` per sortie, one per `cooldown`; each
// lives `lifetime` and pulls every missile homing on its ship that has it in its seeker cone
// with probability `decoy_chance` (drawn once per missile and flare from the keyed RNG).
struct CountermeasureDef {
  int count = 0;
  double cooldown = 1.0;      // seconds between flares
  double lifetime = 3.0;      // seconds
  double decoy_chance = 0.7;  // 0..1
};

// Capital ships (game/sim/capital.h). A turret is a mount on the hull that aims and fires on its
// own at hostiles inside its arc: a beam turret strikes along a straight bolt, a flak turret
// bursts a shell near its target and hurts every hostile inside the burst. Each turret is also a
// subsystem with hull of its own; destroyed, it stops firing.
enum class TurretKind : uint8_t { Beam = 0, Flak = 1 };
struct TurretDef {
  std::string name;
  TurretKind kind = TurretKind::Beam;
  glm::dvec3 position{0.0};      // ship-local
  glm::dvec3 facing{0, 1, 0};    // ship-local unit vector: the middle of its arc
  double arc = 90.0;             // degrees off `facing` it can aim
  double range = 800.0;          // metres
  double damage = 20.0;          // per bolt or per shell burst
  double cooldown = 1.5;         // seconds between shots
  double spread = 0.02;          // radians of aim scatter
  double burst_radius = 25.0;    // flak: metres around the burst point
  double hull = 150.0;
  double radius = 8.0;           // its hit sphere
};
// Engines, shield generators and other parts a pilot can target: each a hit sphere with hull.
// Every engine destroyed stops the ship; every shield generator destroyed drops its shield.
enum class SubsystemKind : uint8_t { Engine = 0, ShieldGenerator = 1, Other = 2 };
struct SubsystemDef {
  std::string name;
  SubsystemKind kind = SubsystemKind::Other;
  glm::dvec3 position{0.0};
  double radius = 10.0;
  double hull = 300.0;
};
// How a capital ship dies: `stages` blasts at points along its hull over `seconds`, its wreck
// drifting and turning, then the final one `final_scale` times a fighter's explosion.
struct BreakupDef {
  int stages = 0;           // 0: one explosion, as fighters
  double seconds = 4.0;
  double final_scale = 8.0;
  double spin = 6.0;        // degrees per second the wreck turns
};
// A loadout: the weapon behind each trigger. Weapons: beam, plasma, missile, torpedo.
enum class WeaponKind : uint8_t { Beam = 0, Plasma = 1, Missile = 2, Torpedo = 3 };
constexpr WeaponKind last_enumerator(WeaponKind) { return WeaponKind::Torpedo; }
const char* weapon_name(WeaponKind k);
struct Loadout {
  WeaponKind primary = WeaponKind::Beam;
  WeaponKind secondary = WeaponKind::Missile;
  bool operator==(const Loadout&) const = default;
};

struct ShipClassDef {
  std::string name;      // file stem: "viper"
  std::string path;      // the file it came from
  std::string model;     // e.g. "assets/models/viper.glb"
  double mass = 10000.0;       // kg
  double thrust = 600000.0;    // N, main engine
  double strafe_thrust = 300000.0;
  double turn_rate[3] = {90.0, 90.0, 120.0};  // pitch, yaw, roll, degrees per second
  double turn_response = 6.0;  // 1/s: how fast angular rates follow the stick
  double max_speed = 150.0;    // m/s with flight assist
  double reverse_fraction = 0.3;
  double afterburner_speed = 1.6;   // speed and thrust factor
  double afterburner_energy = 20.0; // per second
  double hull = 100.0;
  double shield = 100.0;
  double shield_regen = 10.0;       // per second
  double shield_regen_delay = 3.0;  // seconds after the last hit
  double energy = 100.0;
  double energy_regen = 15.0;       // per second
  double collision_radius = 8.0;
  double shield_radius = 11.0;
  BeamDef beam;
  ProjectileWeaponDef missile;
  ProjectileWeaponDef plasma;
  // Torpedo: a slow homing warhead that harms only capital ships (and their subsystems).
  ProjectileWeaponDef torpedo;
  CountermeasureDef countermeasures;
  std::vector<glm::dvec3> exhausts;  // engine exhaust points, ship-local
  std::vector<TurretDef> turrets;        // capital ships only
  std::vector<SubsystemDef> subsystems;  // capital ships only
  BreakupDef breakup;
  // Set by a loadout (apply_loadout): the primary trigger fires plasma instead of the beam.
  bool primary_plasma = false;
  bool capital() const { return !turrets.empty() || !subsystems.empty(); }
  // Parts a pilot can target: the turrets, then the subsystems.
  size_t part_count() const { return turrets.size() + subsystems.size(); }
  bool has(WeaponKind k) const;
};

// Gunner: holds still and fires every weapon straight ahead in bursts (the effect gallery).
// Drone: a training target that flies slow circles and fires only when a training step tells it.
// Capital: cruises ahead at a steady throttle; its turrets fight on their own.
enum class AiKind : uint8_t { None = 0, Fighter = 1, Gunner = 2, Drone = 3, Capital = 4 };
constexpr AiKind last_enumerator(AiKind) { return AiKind::Capital; }

struct ShipSpawnDef {
  std::string name;
  std::string label;       // drawn below it with a fixed camera (the gallery); "" for none
  bool has_label = false;  // false: the name is drawn
  std::string ship_class;  // key into LevelDef::classes
  std::string team;
  bool player = false;
  bool wing = false;       // one of the player's wingmen: takes the wing orders
  AiKind ai = AiKind::Fighter;
  glm::dvec3 position{0.0};
  glm::dvec3 orientation_deg{0.0};  // yaw, pitch, roll
  glm::dvec3 velocity{0.0};
  // Absent until a training step or an event's spawn brings it ("inactive": true).
  bool inactive = false;
  std::string group;  // "group": events name the ships that share it together
};

// A pilot's place in a network match ("slots"): one ship of "ships"; unpiloted slots fly by AI.
struct SlotDef {
  std::string ship;
  std::string team;  // the ship's
};
inline constexpr size_t kMaxLevelSlots = 8;

// A reinforcement wave ("waves"): its ships enter the fight at once when the trigger holds,
// after `after_seconds`, or when `team` has fewer than `below` ships alive. (wave_defs.cpp)
struct WaveDef {
  double after_seconds = -1;  // < 0: triggered by a team's losses
  std::string team;           // with `below`: the team counted
  int below = 0;
  TriggerDef when;            // the same trigger as a time or team_below event's
  std::vector<ShipSpawnDef> ships;
};

struct PropDef {
  std::string model;
  std::string label;
  glm::dvec3 position{0.0};
  glm::dvec3 orientation_deg{0.0};
  double scale = 1.0;
  double radius = 0.0;  // collision sphere; 0 = no collision
};

struct EffectSpawnDef {
  std::string effect;
  std::string label;
  glm::dvec3 position{0.0};
  glm::dvec3 orientation_deg{0.0};
  double scale = 1.0;
  int repeat_ticks = 0;  // 0 = once at the start
  // "to": a lightning effect's channel is aimed from `position` at this point and cut there.
  bool has_target = false;
  glm::dvec3 target{0.0};
  // m/s: each spawn moves from `position` at this velocity until the next (needs repeat_ticks).
  glm::dvec3 velocity{0.0};
  // Where the label's top centre is drawn; by default 12 m × scale above `position`.
  bool has_label_at = false;
  glm::dvec3 label_at{0.0};
};

// Objectives: won when every primary objective is done, lost when one fails ("objectives").
enum class WinKind : uint8_t { DestroyAllHostiles = 0, SurviveTicks = 1, LastTeamStanding = 2, TrainingComplete = 3, Objectives = 4 };
enum class LoseKind : uint8_t { PlayerDestroyed = 0, Protect = 1, None = 2 };

struct CameraHintDef {
  std::string mode = "chase";  // chase, cockpit, fixed
  glm::dvec3 position{0.0, 30.0, 120.0};
  glm::dvec3 look_at{0.0};
  double fov_deg = 60.0;
};

// How AI fighters fly at one difficulty (assets/settings/ai.json; game/sim/ai_defs.cpp loads it).
struct AiDifficultyDef {
  double aim_error = 0;     // radians: largest scatter of the aim point, drawn at each decision
  double reaction_s = 0;    // seconds between decisions (target, evade, break off, aim scatter)
  double aggression = 0;    // 0..1: fire cone, missile use, how late it evades and breaks off
  double stick_limit = 1;   // 0..1: the furthest it pushes the stick (of the ship's turn rates)
  double jink = 0;          // 0..1: strafe thrust while under a hostile's guns
  double tail_limit_s = 0;  // seconds on a player's tail before it breaks off; 0 = never
  double tail_break_s = 0;  // how long that break-off lasts
};
// Easy, normal and hard fly the player's enemies; the optional "allies" row flies the player's
// own side at every difficulty (without it, allies fly the difficulty's row too).
struct AiDifficultyTable {
  std::array<AiDifficultyDef, 3> rows;
  std::optional<AiDifficultyDef> allies;
  AiDifficultyDef& operator[](size_t i) { return rows[i]; }
  const AiDifficultyDef& operator[](size_t i) const { return rows[i]; }
};

// The optional "mission" block: how the menu lists a level and the briefing before it starts.
// Menu data only: not simulated, not hashed.
enum class MissionCategory : uint8_t { Mission = 0, Effects = 1, Demo = 2 };
struct MissionDef {
  bool present = false;
  std::string title;      // the menu's name for the level
  std::string briefing;   // one paragraph shown before launch
  std::string objective;  // what to do, in a sentence, under the briefing
  int order = 0;          // position in the mission list (1 = first); unique within its category
  std::string order_where;  // "path:line:col" of `order`, for the catalog's duplicate-order error
  MissionCategory category = MissionCategory::Mission;
};

// A level's optional "loadout" block (game/sim/loadout.cpp): what the briefing offers the player,
// the ship classes and weapons allowed, and the choice it suggests. Menu data: not simulated.
struct LoadoutChoiceDef {
  bool present = false;
  std::vector<std::string> ships;   // class names (assets/ships/NAME.json)
  std::vector<WeaponKind> weapons;  // every weapon allowed in either bank
  std::string suggested_ship;
  Loadout suggested;
};

// The optional "training" block (game/sim/training_defs.cpp): steps that each wait for the player
// to do one thing. The prompt's {action} placeholders name remappable key actions; the HUD
// fills them from the live bindings.
enum class TrainingCondition : uint8_t {
  TurnedDegrees,       // the nose has turned `value` degrees in all since the step began
  SpeedAbove,          // the player's speed exceeds `value` m/s
  AfterburnerSeconds,  // the afterburner has burned `value` seconds since the step began
  TargetSelected,      // the player targets `ship` (any ship when empty)
  ShipDestroyed,       // `ship` has been destroyed
  MissileHit,          // one of the player's missiles (or plasma bolts) struck a hostile
  CommandIssued,       // the player issued one of `commands`
  WaitSeconds,         // `value` seconds have passed since the step began
};
struct TrainingStepDef {
  std::string prompt;
  TrainingCondition until = TrainingCondition::WaitSeconds;
  double value = 0;
  std::string ship;
  std::vector<Command> commands;
  std::vector<std::string> spawn;  // inactive ships that arrive when the step begins
  std::string fire_at_player;      // a drone that fires its missile at the player when the step begins
};
struct TrainingDef {
  std::vector<TrainingStepDef> steps;
};
struct LevelDef {
  std::string path;
  std::string name;
  uint64_t seed = 1;
  int tick_rate = 60;
  int difficulty = 1;  // Difficulty
  std::string objective;
  WinKind win = WinKind::DestroyAllHostiles;
  int64_t win_ticks = 0;
  LoseKind lose = LoseKind::PlayerDestroyed;
  std::string protect_ship;
  bool splash = false;
  double splash_radius = 60.0;
  double splash_damage = 40.0;
  std::vector<ShipSpawnDef> ships;
  std::vector<SlotDef> slots;  // empty: the player's ship is the only slot (slot_defs.cpp)
  std::vector<WaveDef> waves;  // their ships follow `ships` in World::ships, waiting until the wave
  std::vector<PropDef> props;
  std::vector<EffectSpawnDef> effects;
  CameraHintDef camera;
  // Every class the ships name, by name. Shared and immutable: a copied World's ships point at
  // the same definitions.
  std::map<std::string, std::shared_ptr<const ShipClassDef>> classes;
  // Team name → rgb of its hull stripes and engine glow ("team_colors"; blue and red have
  // defaults). A team without one keeps the models' own colours. Drawing only: not simulated.
  std::map<std::string, glm::dvec3> team_colors;
  AiDifficultyTable ai;  // the AI pilots at each difficulty
  MissionDef mission;    // "mission": present only in levels the menu lists
  LoadoutChoiceDef loadout;  // "loadout": the briefing's ship and weapon choice
  TrainingDef training;  // "training": steps for the player, empty in other levels
  EventsDef events;      // "objectives" and "events" (event_defs.cpp), empty in other levels
};

class EffectLibrary;

// "beam+torpedo": the primary trigger's weapon, then the secondary's. Returns false and says why
// (what is allowed) for anything else.
bool parse_loadout(const std::string& text, Loadout& out, std::string& why);
std::string loadout_text(const Loadout& l);
// Why `l` cannot be flown on class `c` ("" when it can): the primary is the beam or plasma, the
// secondary plasma, missile or torpedo, the two differ, and the class carries both.
std::string loadout_problem(const ShipClassDef& c, const Loadout& l);
// The class as the loadout arms it: the weapons it does not name removed.
ShipClassDef apply_loadout(const ShipClassDef& c, const Loadout& l);

// assets/settings/ai.json below `root_dir`: every difficulty and key is required.
AiDifficultyTable load_ai_difficulties(const std::string& root_dir);

// With `root_dir`, the class's model must resolve through its data layers to a file.
ShipClassDef load_ship_class(const std::string& path, const std::string& name, const std::string& root_dir = "");
// Parses ship class text as if it were the file `path` (fuzz targets, tests).
ShipClassDef parse_ship_class(const std::string& text, const std::string& path, const std::string& name);
// With `effects`, every effect a level names must be in it (checked at its position).
LevelDef load_level_def(const std::string& path, const std::string& root_dir, const EffectLibrary* effects = nullptr);
// Parses level text (tests write levels in memory); `path` names it in messages.
LevelDef parse_level_def(const std::string& text, const std::string& path, const std::string& root_dir,
                         const EffectLibrary* effects = nullptr);

}  // namespace arc
