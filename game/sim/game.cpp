#include "game/sim/game.h"

#include <array>
#include <bit>
#include <cstring>
#include <sstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/hash.h"
#include "game/sim/effects.h"
#include "game/sim/simulation.h"
#include "game/sim/world.h"

namespace arc {

// ---------------------------------------------------------------- World

World& World::operator=(const World& o) {
  if (this == &o) return *this;
  level = o.level;
  class_names = o.class_names;
  model_paths = o.model_paths;
  ships = o.ships;
  projectiles = o.projectiles;
  props = o.props;
  explosions = o.explosions;
  effects = o.effects;
  particles = o.particles ? std::make_unique<ParticleWorld>(*o.particles) : nullptr;
  seed = o.seed;
  difficulty = o.difficulty;
  tick = o.tick;
  dt = o.dt;
  next_projectile_serial = o.next_projectile_serial;
  paused = o.paused;
  player = o.player;
  outcome = o.outcome;
  winner = o.winner;
  outcome_tick = o.outcome_tick;
  camera_mode = o.camera_mode;
  camera = o.camera;
  prev_camera = o.prev_camera;
  options = o.options;
  input_log = o.input_log;
  steps = o.steps;
  // Ship classes live in this World's own level copy.
  for (Ship& s : ships) s.cls = &level.classes.at(class_names[s.class_index]);
  return *this;
}

int World::focus_ship() const {
  if (player >= 0) return player;
  for (const Ship& s : ships)
    if (s.alive) return s.id;
  return -1;
}

int World::model_index(const std::string& path) const {
  for (size_t i = 0; i < model_paths.size(); ++i)
    if (model_paths[i] == path) return static_cast<int>(i);
  return -1;
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
  if (!w.input_log.empty() && cmds.empty() && w.input_log.back().commands.empty() &&
      w.input_log.back().input == input && w.input_log.back().count < UINT32_MAX)
    ++w.input_log.back().count;
  else
    w.input_log.push_back(InputRun{input, cmds, 1});
  ++w.steps;
  step_world(w, input, cmds);
}

uint64_t Game::tick() const { return static_cast<uint64_t>(world_->tick); }
double Game::tick_seconds() const { return world_->dt; }
bool Game::paused() const { return world_->paused; }
const World& Game::world() const { return *world_; }
World& Game::world_mut() { return *world_; }

namespace {

void hash_clusters(StateHasher& h, const EffectHandle& e) {
  h.add_u64(e.clusters.size());
  for (ClusterHandle c : e.clusters) h.add_u64((uint64_t(c.index) << 32) | c.generation);
}

void hash_core(const World& w, StateHasher& h) {
  h.add_i64(w.tick);
  h.add_u64(w.seed);
  h.add_i64(w.difficulty);
  h.add_bool(w.paused);
  h.add_u64(static_cast<uint64_t>(w.outcome));
  h.add_str(w.winner);
  h.add_i64(w.outcome_tick);
  h.add_u64(w.next_projectile_serial);
  for (const Ship& s : w.ships) {
    h.add_i64(s.id);
    h.add_bool(s.alive);
    h.add_vec(s.position);
    h.add_vec(s.velocity);
    h.add_vec(s.angular_velocity);
    h.add_quat(s.orientation);
    h.add_f64(s.hull);
    h.add_f64(s.shield);
    h.add_f64(s.energy);
    h.add_i64(s.last_hit_tick);
    h.add_i64(s.last_attacker);
    h.add_i64(s.kills);
    h.add_i64(s.target);
    h.add_u64(std::bit_cast<uint64_t>(std::array<int8_t, 8>{s.controls.pitch, s.controls.yaw, s.controls.roll,
                                                            s.controls.throttle, s.controls.strafe_x,
                                                            s.controls.strafe_y, 0, 0}));
    h.add_u64(s.controls.buttons);
    h.add_bool(s.afterburner_on);
    h.add_u64(static_cast<uint64_t>(s.secondary));
    h.add_f64(s.secondary_cooldown);
    h.add_u64(s.hardpoint_cycle);
    h.add_bool(s.beam_firing);
    h.add_i64(s.beam_target);
    for (double d : s.beam_hit_distance) h.add_f64(d);
    const AiState& ai = s.ai_state;
    h.add_u64(static_cast<uint64_t>(ai.mode));
    h.add_i64(ai.target);
    h.add_i64(ai.mode_until);
    h.add_i64(ai.next_think);
    h.add_vec(ai.aim_error);
    h.add_vec(ai.evade_dir);
  }
  for (const Projectile& p : w.projectiles) {
    h.add_u64(p.serial);
    h.add_u64(static_cast<uint64_t>(p.kind));
    h.add_i64(p.owner);
    h.add_i64(p.target);
    h.add_vec(p.position);
    h.add_vec(p.velocity);
    h.add_i64(p.expire_tick);
  }
  w.particles->hash(h);
}

const char* outcome_name(Outcome o) {
  switch (o) {
    case Outcome::Victory: return "victory";
    case Outcome::Defeat: return "defeat";
    case Outcome::TeamWon: return "team_won";
    default: return "undecided";
  }
}

// Little-endian byte writer/reader for save games.
struct Writer {
  std::vector<uint8_t> bytes;
  void u64(uint64_t v) {
    for (int i = 0; i < 8; ++i) bytes.push_back(uint8_t(v >> (8 * i)));
  }
  void raw(const void* p, size_t n) {
    const uint8_t* b = static_cast<const uint8_t*>(p);
    bytes.insert(bytes.end(), b, b + n);
  }
};

struct Reader {
  const std::vector<uint8_t>& bytes;
  size_t at = 0;
  std::string what;
  uint64_t u64() {
    if (at + 8 > bytes.size()) throw InputError(what + ": save data is truncated at byte " + std::to_string(at));
    uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= uint64_t(bytes[at + i]) << (8 * i);
    at += 8;
    return v;
  }
  void raw(void* p, size_t n) {
    if (at + n > bytes.size()) throw InputError(what + ": save data is truncated at byte " + std::to_string(at));
    std::memcpy(p, bytes.data() + at, n);
    at += n;
  }
};

constexpr uint64_t kSaveMagic = 0x3145564153524341ull;  // "ACRSAVE1"

}  // namespace

uint64_t Game::hash() const {
  StateHasher h;
  hash_core(*world_, h);
  return h.value();
}

uint64_t Game::full_hash() const {
  const World& w = *world_;
  StateHasher h;
  hash_core(w, h);
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
  h.add_u64(w.steps);
  return h.value();
}

std::string Game::state_dump() const {
  const World& w = *world_;
  std::ostringstream o;
  o.precision(17);
  o << "tick " << w.tick << " steps " << w.steps << " paused " << w.paused << " outcome " << outcome_name(w.outcome)
    << " winner " << (w.winner.empty() ? "-" : w.winner) << "\n";
  for (const Ship& s : w.ships) {
    o << "ship " << s.id << " " << s.name << " team " << s.team << " class " << s.cls->name << " alive " << s.alive
      << " hull " << s.hull << " shield " << s.shield << " energy " << s.energy << " kills " << s.kills << "\n"
      << "  pos " << s.position.x << " " << s.position.y << " " << s.position.z << " vel " << s.velocity.x << " "
      << s.velocity.y << " " << s.velocity.z << "\n"
      << "  rot " << s.orientation.w << " " << s.orientation.x << " " << s.orientation.y << " " << s.orientation.z
      << " angvel " << s.angular_velocity.x << " " << s.angular_velocity.y << " " << s.angular_velocity.z << "\n"
      << "  controls p" << int(s.controls.pitch) << " y" << int(s.controls.yaw) << " r" << int(s.controls.roll) << " t"
      << int(s.controls.throttle) << " b" << s.controls.buttons << " target " << s.target << " beam "
      << s.beam_firing << "->" << s.beam_target << " secondary " << int(s.secondary) << " cooldown "
      << s.secondary_cooldown << " ai mode " << int(s.ai_state.mode) << " target " << s.ai_state.target << "\n";
  }
  for (const Projectile& p : w.projectiles)
    o << "projectile " << p.serial << " kind " << int(p.kind) << " owner " << p.owner << " target " << p.target
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
    j["winner"] = w.winner;
    j["decided_tick"] = w.outcome_tick;
  } else {
    j["winner"] = nullptr;
  }
  nlohmann::ordered_json ships = nlohmann::ordered_json::array();
  for (const Ship& s : w.ships) {
    nlohmann::ordered_json e;
    e["name"] = s.name;
    e["team"] = s.team;
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

std::vector<uint8_t> Game::save() const {
  const World& w = *world_;
  Writer out;
  out.u64(kSaveMagic);
  out.u64(w.seed);
  out.u64(static_cast<uint64_t>(w.difficulty));
  out.u64(w.steps);
  out.u64(w.input_log.size());
  for (const InputRun& r : w.input_log) {
    out.raw(&r.input, sizeof r.input);
    out.u64(r.count);
    out.u64(r.commands.size());
    for (Command c : r.commands) out.u64(static_cast<uint64_t>(c));
  }
  out.u64(hash());
  out.u64(full_hash());
  return out.bytes;
}

Game Game::restore(const std::vector<uint8_t>& bytes, const std::string& level_path, const GameOptions& options) {
  Reader in{bytes, 0, level_path};
  if (in.u64() != kSaveMagic) throw InputError(level_path + ": not an Arcfire save (bad magic)");
  GameOptions o = options;
  o.seed_override = true;
  o.seed = in.u64();
  uint64_t diff = in.u64();
  if (diff > 2) throw InputError(level_path + ": save has difficulty " + std::to_string(diff) + ", allowed 0..2");
  o.difficulty_override = true;
  o.difficulty = static_cast<Difficulty>(diff);
  uint64_t steps = in.u64();
  uint64_t runs = in.u64();
  if (runs > bytes.size()) throw InputError(level_path + ": save data is corrupt (run count)");
  Game g = load_level(level_path, o);
  // The save is the complete input history: replaying it rebuilds every byte of state,
  // particles included, because the simulation is a pure function of its inputs.
  for (uint64_t i = 0; i < runs; ++i) {
    InputFrame f;
    in.raw(&f, sizeof f);
    uint64_t count = in.u64();
    uint64_t ncmd = in.u64();
    if (ncmd > 64 || count == 0 || count > steps) throw InputError(level_path + ": save data is corrupt (run " + std::to_string(i) + ")");
    std::vector<Command> cmds;
    for (uint64_t c = 0; c < ncmd; ++c) {
      uint64_t v = in.u64();
      if (v > static_cast<uint64_t>(Command::Resume)) throw InputError(level_path + ": save has an unknown command " + std::to_string(v));
      cmds.push_back(static_cast<Command>(v));
    }
    g.step(f, cmds);
    for (uint64_t k = 1; k < count; ++k) g.step(f);
  }
  uint64_t h = in.u64();
  uint64_t fh = in.u64();
  if (g.world_->steps != steps || g.hash() != h || g.full_hash() != fh)
    throw InputError(level_path + ": save does not match this level or build (state hash differs after replay)");
  return g;
}

}  // namespace arc
