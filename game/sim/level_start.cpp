// game/sim/level_start.cpp — the World at tick 0: settings, the particle world, the game's
// effects resolved to ids, teams, ships and props from the level, the camera rig, and each
// ship's particle owner, shield sphere and engine exhausts.
#include "game/sim/level_start.h"

#include <string>

#include "core/error.h"
#include "game/sim/camera_rig.h"
#include "game/sim/capital.h"
#include "game/sim/commands.h"
#include "game/sim/effects.h"
#include "game/sim/geometry.h"
#include "game/sim/mission_events.h"
#include "game/sim/shields.h"
#include "game/sim/training.h"
#include "game/sim/world.h"
#include "particles/particle_store.h"

namespace arc {
namespace {

// A model's slot in World::model_paths, added on first use (the renderer loads only these).
ModelSlot add_model(World& w, const std::string& path) {
  for (size_t i = 0; i < w.model_paths.size(); ++i)
    if (w.model_paths[i] == path) return ModelSlot::from_index(i);
  w.model_paths.push_back(path);
  return ModelSlot::from_index(w.model_paths.size() - 1);
}

// A team's id in World::team_names, added on first use.
TeamId add_team(World& w, const std::string& name) {
  for (size_t i = 0; i < w.team_names.size(); ++i)
    if (w.team_names[i] == name) return TeamId::from_index(i);
  w.team_names.push_back(name);
  return TeamId::from_index(w.team_names.size() - 1);
}

void add_ship(World& w, const ShipSpawnDef& d, bool waiting) {
  Ship s;
  s.id = ShipId::from_index(w.ships.size());
  s.name = d.name;
  s.team = add_team(w, d.team);
  s.particle_owner = allocate_owner(w);
  s.cls = w.level.classes.at(d.ship_class).get();
  s.model = add_model(w, s.cls->model);
  s.player = d.player;
  s.ai = d.ai;
  s.position = s.prev_position = d.position;
  s.orientation = s.prev_orientation = orientation_from_degrees(d.orientation_deg);
  s.velocity = d.velocity;
  s.hull = s.cls->hull;
  s.shield = s.cls->shield;
  s.energy = s.cls->energy;
  s.seeker.flares = s.cls->countermeasures.count;
  // A wave's ships wait out of play until it arrives (waves.cpp); an "inactive" ship until a
  // training step calls it (training.cpp).
  s.alive = !waiting && !d.inactive;
  if (!s.cls->missile.present && s.cls->plasma.present) s.secondary = SecondaryWeapon::Plasma;
  if (!s.cls->missile.present && !(s.cls->plasma.present && !s.cls->primary_plasma) && s.cls->torpedo.present)
    s.secondary = SecondaryWeapon::Torpedo;
  init_parts(s);
  if (d.player) w.player = s.id;
  // The autopilot setting hands the player's ship to the fighter AI (replays of whole missions).
  if (d.player && w.options.autopilot && s.ai == AiKind::None) s.ai = AiKind::Fighter;
  if (d.wing) w.wing.push_back({s.id, WingOrder::EngageAtWill, ShipId{}, int32_t(w.wing.size() + 1)});
  w.ships.push_back(std::move(s));
}

void add_ships(World& w) {
  for (const ShipSpawnDef& d : w.level.ships) add_ship(w, d, false);
  for (const WaveDef& wave : w.level.waves) {
    for (const ShipSpawnDef& d : wave.ships) add_ship(w, d, true);
    w.waves.push_back({});
  }
}

void add_props(World& w) {
  for (const PropDef& d : w.level.props) {
    Prop p;
    p.model = add_model(w, d.model);
    p.label = d.label;
    p.position = d.position;
    p.orientation = orientation_from_degrees(d.orientation_deg);
    p.scale = d.scale;
    p.radius = d.radius;
    w.props.push_back(std::move(p));
  }
}

}  // namespace

void attach_ship_effects(World& w, Ship& s) {
  // Spawned at full intensity: the burst's particle count is scaled by the intensity of the
  // first particle step, after which update_shields_and_energy() dims it to what it shows.
  if (s.cls->shield > 0) spawn_shield(w, s, 4);
  for (const glm::dvec3& e : exhaust_plume_points(s.cls->exhausts)) {
    SpawnParams ep;
    ep.owner = s.particle_owner;
    ep.position = e;
    ep.orientation = glm::angleAxis(kPi, glm::dvec3(0, 1, 0));  // exhaust cone points backwards (+Z)
    ep.scale = s.cls->collision_radius / 8.0;
    ep.priority = 0;
    s.exhaust_fx.push_back(spawn_fx(w, w.fx.engine_exhaust, ep));
  }
}

std::vector<glm::dvec3> exhaust_plume_points(const std::vector<glm::dvec3>& exhausts) {
  const size_t n = exhausts.size();
  if (n <= kMaxExhaustPlumes) return exhausts;
  std::vector<glm::dvec3> out;
  out.reserve(kMaxExhaustPlumes);
  for (size_t k = 0; k < kMaxExhaustPlumes; ++k) out.push_back(exhausts[(2 * k + 1) * n / (2 * kMaxExhaustPlumes)]);
  return out;
}

void arrive_ship(World& w, Ship& s) {
  if (!dormant(s)) return;
  s.alive = true;
  s.prev_position = s.position;
  s.prev_orientation = s.orientation;
  set_owner(w, s.particle_owner, s.position, s.orientation, s.velocity);
  attach_ship_effects(w, s);
}

void init_world(World& w, LevelDef level, std::shared_ptr<const EffectLibrary> effects, const GameOptions& o,
                std::shared_ptr<ParticleStore> store) {
  w.options = o;
  w.level = std::move(level);
  w.seed = o.seed_override ? o.seed : w.level.seed;
  w.difficulty = o.difficulty_override ? static_cast<int>(o.difficulty) : w.level.difficulty;
  w.dt = 1.0 / w.level.tick_rate;
  w.effects = std::move(effects);
  ParticleConfig pc;
  pc.seed = w.seed;
  pc.budget = o.particle_budget;
  pc.lightning_interval = o.lightning_interval;
  pc.cull_distance = o.cull_distance;
  pc.tick_seconds = w.dt;
  pc.threads = o.sim_threads;
  if (store && store->in_use() > 0) store = nullptr;  // another world's particles are in it
  w.particles.emplace(pc, w.effects.get(), std::move(store));
  add_ships(w);
  // The player starts with the nearest hostile targeted, so the HUD shows it from the first frame.
  if (w.player) w.ship(w.player).target = nearest_hostile(w, w.player);
  add_props(w);
  w.camera_mode = w.level.camera.mode == "cockpit" ? CameraMode::Cockpit
                  : w.level.camera.mode == "fixed" ? CameraMode::Fixed
                                                   : CameraMode::Chase;
  if (const ShipId f = w.focus_ship()) w.camera.orientation = w.ship(f).orientation;
  update_camera(w);
  w.prev_camera = w.camera;
  publish_owner_transforms(w);
  try {
    w.fx = resolve_game_effects(*w.effects, w.level);
    for (Ship& s : w.ships)
      if (s.alive) attach_ship_effects(w, s);
    start_training(w);
    start_mission(w);
  } catch (const InputError& e) {
    throw InputError(w.level.path + ": " + e.what());
  }
}

}  // namespace arc
