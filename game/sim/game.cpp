#include "game/sim/game.h"

#include <array>
#include <bit>
#include <cstring>
#include <sstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/hash.h"
#include "game/sim/effects.h"
#include "game/sim/serialize.h"
#include "game/sim/level_start.h"
#include "game/sim/simulation.h"
#include "game/sim/world.h"
#include "core/fast_hash.h"

namespace arc {

// ---------------------------------------------------------------- World

World& World::operator=(const World& o) {
  if (this == &o) return *this;
  level = o.level;
  class_names = o.class_names;
  team_names = o.team_names;
  model_paths = o.model_paths;
  ships = o.ships;
  projectiles = o.projectiles;
  props = o.props;
  explosions = o.explosions;
  effects = o.effects;
  fx = o.fx;
  particles = o.particles ? std::make_unique<ParticleWorld>(*o.particles) : nullptr;
  seed = o.seed;
  difficulty = o.difficulty;
  tick = o.tick;
  dt = o.dt;
  next_projectile_serial = o.next_projectile_serial;
  next_particle_owner = o.next_particle_owner;
  paused = o.paused;
  player = o.player;
  outcome = o.outcome;
  winner = o.winner;
  outcome_tick = o.outcome_tick;
  camera_mode = o.camera_mode;
  camera = o.camera;
  prev_camera = o.prev_camera;
  options = o.options;
  steps = o.steps;
  // Ship classes live in this World's own level copy.
  for (Ship& s : ships) s.cls = &level.classes.at(class_names[s.class_index]);
  return *this;
}

ShipId World::focus_ship() const {
  if (player) return player;
  for (const Ship& s : ships)
    if (s.alive) return s.id;
  return {};
}

const std::string& World::team_name(TeamId team) const {
  static const std::string none = "none";
  return team ? team_names.at(team.index()) : none;
}

// ---------------------------------------------------------------- Game

Game::Game() : world_(std::make_unique<World>()) {}
Game::Game(const Game& o) : world_(std::make_unique<World>(*o.world_)) {}
Game& Game::operator=(const Game& o) {
  if (this != &o) world_ = std::make_unique<World>(*o.world_);
  return *this;
}
Game::Game(Game&&) noexcept = default;
Game& Game::operator=(Game&&) noexcept = default;
Game::~Game() = default;

Game Game::load_level(const std::string& level_path, const GameOptions& options) {
  Game g;
  std::shared_ptr<const EffectLibrary> fx = load_effect_library(options.root_dir);
  init_world(*g.world_, load_level_def(level_path, options.root_dir, fx.get()), fx, options);
  return g;
}

void Game::step(const InputFrame& input, const std::vector<Command>& commands) {
  World& w = *world_;
  std::vector<Command> cmds;
  for (Command c : commands)
    if (c != Command::None) cmds.push_back(c);
  ++w.steps;
  step_world(w, input, cmds);
}

uint64_t Game::tick() const { return static_cast<uint64_t>(world_->tick); }
double Game::tick_seconds() const { return world_->dt; }
bool Game::paused() const { return world_->paused; }
const World& Game::world() const { return *world_; }
World& Game::world_mut() { return *world_; }

namespace {

void hash_clusters(FastHasher& h, const EffectHandle& e) {
  h.add_u64(e.clusters.size());
  for (ClusterHandle c : e.clusters) h.add_u64((uint64_t(c.index) << 32) | c.generation);
}

// The cheap per-tick hash (Game::hash()): FastHasher, so it costs a small part of a step.
uint64_t hash_core(const World& w) {
  FastHasher h;  // local: kept in registers (core/fast_hash.h)
  h.add_i64(w.tick);
  h.add_u64(w.seed);
  h.add_i64(w.difficulty);
  h.add_bool(w.paused);
  h.add_u64(static_cast<uint64_t>(w.outcome));
  h.add_u64(w.winner.value);
  h.add_i64(w.outcome_tick);
  h.add_u64(w.next_projectile_serial);
  h.add_u64(w.next_particle_owner);
  for (const Ship& s : w.ships) {
    h.add_u64(s.id.value);
    h.add_bool(s.alive);
    h.add_vec(s.position);
    h.add_vec(s.velocity);
    h.add_vec(s.angular_velocity);
    h.add_quat(s.orientation);
    h.add_f64(s.hull);
    h.add_f64(s.shield);
    h.add_f64(s.energy);
    h.add_i64(s.last_hit_tick);
    h.add_u64(s.last_attacker.value);
    h.add_i64(s.kills);
    h.add_u64(s.target.value);
    h.add_u64(std::bit_cast<uint64_t>(std::array<int8_t, 8>{s.controls.pitch, s.controls.yaw, s.controls.roll,
                                                            s.controls.throttle, s.controls.strafe_x,
                                                            s.controls.strafe_y, 0, 0}));
    h.add_u64(s.controls.buttons);
    h.add_bool(s.afterburner_on);
    h.add_u64(static_cast<uint64_t>(s.secondary));
    h.add_f64(s.secondary_cooldown);
    h.add_u64(s.hardpoint_cycle);
    h.add_bool(s.beam_firing);
    h.add_u64(s.beam_target.value);
    for (double d : s.beam_hit_distance) h.add_f64(d);
    const AiState& ai = s.ai_state;
    h.add_u64(static_cast<uint64_t>(ai.mode));
    h.add_u64(ai.target.value);
    h.add_i64(ai.mode_until);
    h.add_i64(ai.next_think);
    h.add_vec(ai.aim_error);
    h.add_vec(ai.evade_dir);
  }
  for (const Projectile& p : w.projectiles) {
    h.add_u64(p.serial);
    h.add_u64(static_cast<uint64_t>(p.kind));
    h.add_u64(p.owner.value);
    h.add_u64(p.target.value);
    h.add_u64(p.particle_owner.value);
    h.add_vec(p.position);
    h.add_vec(p.velocity);
    h.add_i64(p.expire_tick);
  }
  // Presentation state (previous transforms, flashes, attached effects' handles, explosions,
  // the camera rig, which decides particle culling).
  for (const Ship& s : w.ships) {
    h.add_vec(s.prev_position);
    h.add_quat(s.prev_orientation);
    h.add_i64(s.shield_flash_tick);
    h.add_i64(s.death_tick);
    h.add_f64(s.shown_shield_intensity);
    h.add_f64(s.shown_exhaust_intensity);
    h.add_i64(s.shield_density);
    h.add_i64(s.shield_spawn_tick);
    hash_clusters(h, s.shield_fx);
    for (const EffectHandle& e : s.exhaust_fx) hash_clusters(h, e);
    for (ClusterHandle c : s.beam_channels) h.add_u64((uint64_t(c.index) << 32) | c.generation);
  }
  for (const Projectile& p : w.projectiles) {
    h.add_vec(p.prev_position);
    hash_clusters(h, p.trail);
  }
  for (const ExplosionEvent& e : w.explosions) {
    h.add_vec(e.position);
    h.add_i64(e.tick);
    h.add_f64(e.radius);
  }
  h.add_u64(static_cast<uint64_t>(w.camera_mode));
  h.add_vec(w.camera.position);
  h.add_quat(w.camera.orientation);
  h.add_vec(w.prev_camera.position);
  h.add_quat(w.prev_camera.orientation);
  // Per-cluster summaries: particle state is a closed-form function of them (full_hash()
  // hashes every particle as well).
  w.particles->hash_summary(h);
  return h.value();
}

const char* outcome_name(Outcome o) {
  switch (o) {
    case Outcome::Victory: return "victory";
    case Outcome::Defeat: return "defeat";
    case Outcome::TeamWon: return "team_won";
    default: return "undecided";
  }
}

}  // namespace

uint64_t Game::hash() const { return hash_core(*world_); }

uint64_t Game::full_hash() const {
  StateHasher h;
  h.add_u64(hash());
  h.add_u64(world_->steps);  // not in hash(): a paused step changes nothing else
  world_->particles->hash(h);
  return h.value();
}

std::string Game::state_dump() const {
  const World& w = *world_;
  std::ostringstream o;
  o.precision(17);
  o << "tick " << w.tick << " steps " << w.steps << " paused " << w.paused << " outcome " << outcome_name(w.outcome)
    << " winner " << (w.outcome == Outcome::Undecided ? "-" : w.team_name(w.winner)) << "\n";
  for (const Ship& s : w.ships) {
    o << "ship " << s.id.value << " " << s.name << " team " << w.team_name(s.team) << " class " << s.cls->name << " alive " << s.alive
      << " hull " << s.hull << " shield " << s.shield << " energy " << s.energy << " kills " << s.kills << "\n"
      << "  pos " << s.position.x << " " << s.position.y << " " << s.position.z << " vel " << s.velocity.x << " "
      << s.velocity.y << " " << s.velocity.z << "\n"
      << "  rot " << s.orientation.w << " " << s.orientation.x << " " << s.orientation.y << " " << s.orientation.z
      << " angvel " << s.angular_velocity.x << " " << s.angular_velocity.y << " " << s.angular_velocity.z << "\n"
      << "  controls p" << int(s.controls.pitch) << " y" << int(s.controls.yaw) << " r" << int(s.controls.roll) << " t"
      << int(s.controls.throttle) << " b" << s.controls.buttons << " target " << s.target.value << " beam "
      << s.beam_firing << "->" << s.beam_target.value << " secondary " << int(s.secondary) << " cooldown "
      << s.secondary_cooldown << " ai mode " << int(s.ai_state.mode) << " target " << s.ai_state.target.value << "\n";
  }
  for (const Projectile& p : w.projectiles)
    o << "projectile " << p.serial << " kind " << int(p.kind) << " owner " << p.owner.value << " target " << p.target.value
      << " pos " << p.position.x << " " << p.position.y << " " << p.position.z << "\n";
  ParticleStats st = w.particles->stats();
  o << "particles " << st.live_particles << " clusters " << st.live_clusters << " refused " << st.refused_particles
    << "\n";
  return o.str();
}

std::string Game::summary_json() const {
  const World& w = *world_;
  nlohmann::ordered_json j;
  j["level"] = w.level.name;
  j["tick"] = w.tick;
  j["seconds"] = double(w.tick) * w.dt;
  j["outcome"] = outcome_name(w.outcome);
  if (w.outcome != Outcome::Undecided) {
    j["winner"] = w.team_name(w.winner);
    j["decided_tick"] = w.outcome_tick;
  } else {
    j["winner"] = nullptr;
  }
  nlohmann::ordered_json ships = nlohmann::ordered_json::array();
  for (const Ship& s : w.ships) {
    nlohmann::ordered_json e;
    e["name"] = s.name;
    e["team"] = w.team_name(s.team);
    e["class"] = s.cls->name;
    e["player"] = s.player;
    e["alive"] = s.alive;
    e["hull"] = s.hull;
    e["shield"] = s.shield;
    e["kills"] = s.kills;
    ships.push_back(std::move(e));
  }
  j["ships"] = std::move(ships);
  ParticleStats st = w.particles->stats();
  j["particles"] = st.live_particles;
  j["clusters"] = st.live_clusters;
  j["refused_particles"] = st.refused_particles;
  j["hash"] = hash();
  return j.dump(2) + "\n";
}

std::vector<uint8_t> Game::save() const { return save_world(*world_); }

Game Game::restore(const std::vector<uint8_t>& bytes, const std::string& level_path, const GameOptions& options) {
  // The level supplies the static definitions (classes, effects, props' models); the snapshot
  // then overwrites every piece of dynamic state. Nothing is re-simulated.
  Game g = load_level(level_path, snapshot_options(bytes, options));
  load_world(*g.world_, bytes);
  return g;
}

}  // namespace arc
