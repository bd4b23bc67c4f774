// game/sim/game.cpp — Game: level loading, stepping, the per-tick hash, the state dump and the
// summary; snapshots are in serialize.cpp, the rules of a tick in simulation.cpp.
#include "game/sim/game.h"

#include <array>
#include <bit>
#include <cstdio>
#include <optional>
#include <ostream>
#include <sstream>
#include <nlohmann/json.hpp>

#include "core/hash.h"
#include "game/sim/effects.h"
#include "game/sim/level_start.h"
#include "game/sim/loadout.h"
#include "game/sim/serialize.h"
#include "game/sim/simulation.h"
#include "game/sim/world.h"
#include "core/fast_hash.h"
#include "core/state_fields.h"

namespace arc {

// ---------------------------------------------------------------- World

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
void Game::copy_state_from(const Game& o) {
  if (this != &o) *world_ = *o.world_;
}
Game::Game(Game&&) noexcept = default;
Game& Game::operator=(Game&&) noexcept = default;
Game::~Game() = default;

Game Game::load_level(const std::string& level_path, const GameOptions& options) {
  return load_level(level_path, options, nullptr);
}

Game Game::load_level(const std::string& level_path, const GameOptions& options, std::shared_ptr<ParticleStore> store) {
  Game g;
  std::shared_ptr<const EffectLibrary> fx = load_effect_library(options.root_dir);
  LevelDef level = load_level_def(level_path, options.root_dir, fx.get());
  apply_player_choice(level, options.ship, options.loadout, options.root_dir);
  init_world(*g.world_, std::move(level), fx, options, std::move(store));
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

static ShipId ship_named(const World& w, const std::string& name) {
  for (const Ship& s : w.ships)
    if (s.name == name) return s.id;
  return {};
}

size_t Game::slot_count() const {
  const World& w = *world_;
  return !w.level.slots.empty() ? w.level.slots.size() : w.player ? 1 : 0;
}

void Game::set_pilots(const std::vector<bool>& piloted) {
  World& w = *world_;
  w.pilots.clear();
  for (size_t i = 0; i < slot_count(); ++i) {
    PilotSlot p;
    p.ship = w.level.slots.empty() ? w.player : ship_named(w, w.level.slots[i].ship);
    p.piloted = i < piloted.size() && piloted[i];
    w.pilots.push_back(p);
  }
}

void Game::step_slots(const std::vector<SlotInput>& slots) {
  World& w = *world_;
  ++w.steps;
  step_world(w, InputFrame{}, {}, &slots);
}

uint64_t Game::tick() const { return static_cast<uint64_t>(world_->tick); }
double Game::tick_seconds() const { return world_->dt; }
bool Game::paused() const { return world_->paused; }
const World& Game::world() const { return *world_; }
World& Game::world_mut() { return *world_; }

// ---------------------------------------------------------------- hash and dump leaves

// Leaf types' hash words and dump text, found by fields::hash_value and fields::dump_value
// (argument-dependent lookup, hence namespace arc rather than an unnamed namespace).
static_assert(sizeof(InputFrame) == 8, "a field added to InputFrame needs its hash, snapshot and dump encodings");

// The six axes in one word, then the buttons.
static void hash_leaf(FastHasher& h, const InputFrame& f) {
  h.add_u64(std::bit_cast<uint64_t>(std::array<int8_t, 8>{f.pitch, f.yaw, f.roll, f.throttle, f.strafe_x, f.strafe_y, 0, 0}));
  h.add_u64(f.buttons);
}
static void hash_leaf(FastHasher& h, ClusterHandle c) { h.add_u64((uint64_t(c.index) << 32) | c.generation); }
static void hash_leaf(FastHasher& h, const EffectHandle& e) {
  h.add_u64(e.clusters.size());
  for (ClusterHandle c : e.clusters) hash_leaf(h, c);
}
// Per-cluster summaries: particle state is a closed-form function of them (full_hash() hashes
// every particle as well).
static void hash_leaf(FastHasher& h, const std::optional<ParticleWorld>& p) { p->hash_summary(h); }
// Nothing at all outside training levels, so their hashes are those of a world without it.
static void hash_leaf(FastHasher& h, const std::optional<TrainingProgress>& t) {
  if (t) fields::hash_pass<kStateHashPass>(h, *t);
}

// Nothing at all outside levels with events or objectives, likewise.
static void hash_leaf(FastHasher& h, const std::optional<MissionProgress>& m) {
  if (m) fields::hash_pass<kStateHashPass>(h, *m);
}

static void dump_leaf(std::ostream& o, const std::optional<MissionProgress>& m) {
  if (!m) o << "(none)";
  else fields::dump_fields(o, *m);
}
static void dump_leaf(std::ostream& o, const InputFrame& f) {
  o << "(p" << int(f.pitch) << " y" << int(f.yaw) << " r" << int(f.roll) << " t" << int(f.throttle) << " x"
    << int(f.strafe_x) << " z" << int(f.strafe_y) << " b" << f.buttons << ')';
}
static void dump_leaf(std::ostream& o, ClusterHandle c) { o << c.index << ':' << c.generation; }
static void dump_leaf(std::ostream& o, const EffectHandle& e) {
  o << '[';
  for (ClusterHandle c : e.clusters) o << ' ' << c.index << ':' << c.generation;
  o << " ]";
}
static void dump_leaf(std::ostream& o, const ShipClassDef* c) { o << c->name; }
static void dump_leaf(std::ostream& o, const std::optional<TrainingProgress>& t) {
  if (!t) o << "(none)";
  else o << "(step " << t->step << " since " << t->step_tick << " progress " << t->progress << " hits " << t->missile_hits_before << ')';
}
static void dump_leaf(std::ostream& o, const std::optional<ParticleWorld>& p) {
  const ParticleStats st = p->stats();
  o << "(live " << st.live_particles << " clusters " << st.live_clusters << " refused " << st.refused_particles << ')';
}

namespace {

const char* outcome_name(Outcome o) {
  switch (o) {
    case Outcome::Victory: return "victory";
    case Outcome::Defeat: return "defeat";
    case Outcome::TeamWon: return "team_won";
    default: return "undecided";
  }
}

}  // namespace

// The cheap per-tick hash: FastHasher, so it costs a small part of a step. The order of its
// words is the visitors' (game/sim/world.h), frozen by the hashes replays store. Flattened, so
// the hasher stays in registers through every ship's words.
[[gnu::flatten]] uint64_t Game::hash() const {
  FastHasher h;  // local: kept in registers (core/fast_hash.h)
  fields::hash_pass<kStateHashPass>(h, *world_);
  fields::hash_pass<kPresentationHashPass>(h, *world_);
  return h.value();
}

uint64_t Game::full_hash() const {
  StateHasher h;
  h.add_u64(hash());
  h.add_u64(world_->steps);  // not in hash(): a paused step changes nothing else
  world_->particles->hash(h);
  return h.value();
}

std::string Game::state_dump() const {
  std::ostringstream o;
  o.precision(17);
  fields::dump_fields(o, *world_);
  o << "\n";
  return o.str();
}

std::string Game::summary_json() const {
  const World& w = *world_;
  nlohmann::ordered_json j;
  j["level"] = w.level.name;
  j["tick"] = w.tick;
  j["seconds"] = double(w.tick) * w.dt;
  if (w.outcome != Outcome::Undecided) j["decided_seconds"] = double(w.outcome_tick) * w.dt;
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
    const CombatStats& st = s.stats;
    e["damage_dealt"] = st.damage_dealt;
    e["damage_taken"] = st.damage_taken;
    e["beam"] = {{"shots", st.beam_ticks}, {"hits", st.beam_hit_ticks},
                 {"accuracy", accuracy(st.beam_hit_ticks, st.beam_ticks)}};
    e["missile"] = {{"shots", st.missiles_fired}, {"hits", st.missiles_hit},
                    {"accuracy", accuracy(st.missiles_hit, st.missiles_fired)}};
    ships.push_back(std::move(e));
  }
  j["ships"] = std::move(ships);
  if (w.training) j["training"] = {{"step", w.training->step}, {"steps", w.level.training.steps.size()}};
  if (w.mission) {
    static const char* const kStates[] = {"pending", "done", "failed"};
    nlohmann::ordered_json objectives = nlohmann::ordered_json::object(), events = nlohmann::ordered_json::object();
    for (size_t i = 0; i < w.mission->objectives.size(); ++i)
      objectives[w.level.events.objectives[i].id] = kStates[size_t(w.mission->objectives[i].status)];
    for (size_t i = 0; i < w.mission->events.size(); ++i)
      events[w.level.events.events[i].id] = w.mission->events[i].fired_tick;
    j["objectives"] = std::move(objectives);
    j["events_fired"] = std::move(events);  // the tick each ran its actions, −1 for not yet
  }
  ParticleStats st = w.particles->stats();
  j["particles"] = st.live_particles;
  j["clusters"] = st.live_clusters;
  j["refused_particles"] = st.refused_particles;
  // 16 hex digits, as the replay prints hashes: a JSON number above 2^53 is rounded by most readers.
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash()));
  j["hash"] = hex;
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
