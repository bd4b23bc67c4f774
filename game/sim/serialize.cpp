#include "game/sim/serialize.h"

#include <algorithm>
#include <string>

#include "game/sim/world.h"
#include "core/snapshot_io.h"

namespace arc {
namespace {

constexpr uint64_t kMagic = snapshot::magic("ARCSNAP1");
constexpr uint32_t kVersion = 2;  // 2: typed ids (ships, teams, model slots, particle owners) as their u32 values

using snapshot::Reader;
using snapshot::Writer;

// ---- writing ------------------------------------------------------------------------------

void write_handle(Writer& out, ClusterHandle h) {
  out.u32(h.index);
  out.u32(h.generation);
}

void write_effect(Writer& out, const EffectHandle& e) {
  out.u32(uint32_t(e.clusters.size()));
  for (ClusterHandle h : e.clusters) write_handle(out, h);
}

void write_input(Writer& out, const InputFrame& f) {
  for (int8_t a : {f.pitch, f.yaw, f.roll, f.throttle, f.strafe_x, f.strafe_y}) out.u8(uint8_t(a));
  out.u16(f.buttons);
}

void write_options(Writer& out, const World& w) {
  out.str(w.level.name);
  out.i32(w.level.tick_rate);
  out.u64(w.seed);
  out.u8(uint8_t(w.difficulty));
  out.u32(w.options.particle_budget);
  out.i32(w.options.lightning_interval);
  out.i32(w.options.substeps);
}

void write_ship(Writer& out, const Ship& s, const World& w) {
  out.u32(s.id.value);
  out.str(s.name);
  out.str(w.class_names.at(size_t(s.class_index)));
  out.u32(s.team.value);
  out.u32(s.particle_owner.value);
  out.boolean(s.player);
  out.u8(uint8_t(s.ai));
  out.vec3(s.position);
  out.vec3(s.velocity);
  out.vec3(s.angular_velocity);
  out.quat(s.orientation);
  out.vec3(s.prev_position);
  out.quat(s.prev_orientation);
  out.boolean(s.alive);
  out.f64(s.hull);
  out.f64(s.shield);
  out.f64(s.energy);
  out.i64(s.last_hit_tick);
  out.i64(s.shield_flash_tick);
  out.i64(s.death_tick);
  out.u32(s.last_attacker.value);
  out.i32(s.kills);
  out.u32(s.target.value);
  write_input(out, s.controls);
  out.boolean(s.afterburner_on);
  out.u8(uint8_t(s.secondary));
  out.f64(s.secondary_cooldown);
  out.u32(s.hardpoint_cycle);
  out.boolean(s.beam_firing);
  out.u32(uint32_t(s.beam_channels.size()));
  for (ClusterHandle h : s.beam_channels) write_handle(out, h);
  out.u32(uint32_t(s.beam_hit_distance.size()));
  for (double d : s.beam_hit_distance) out.f64(d);
  out.u32(s.beam_target.value);
  write_effect(out, s.shield_fx);
  out.u32(uint32_t(s.exhaust_fx.size()));
  for (const EffectHandle& e : s.exhaust_fx) write_effect(out, e);
  out.f64(s.shown_shield_intensity);
  out.i32(s.shield_density);
  out.i64(s.shield_spawn_tick);
  out.f64(s.shown_exhaust_intensity);
  const AiState& ai = s.ai_state;
  out.u8(uint8_t(ai.mode));
  out.u32(ai.target.value);
  out.i64(ai.mode_until);
  out.i64(ai.next_think);
  out.vec3(ai.aim_error);
  out.vec3(ai.evade_dir);
}

// ---- reading ------------------------------------------------------------------------------

ClusterHandle read_handle(Reader& in) {
  ClusterHandle h;
  h.index = in.u32();
  h.generation = in.u32();
  return h;
}

EffectHandle read_effect(Reader& in) {
  EffectHandle e;
  e.clusters.resize(in.count(8, "effect cluster count"));
  for (ClusterHandle& h : e.clusters) h = read_handle(in);
  return e;
}

InputFrame read_input(Reader& in) {
  InputFrame f;
  for (int8_t* a : {&f.pitch, &f.yaw, &f.roll, &f.throttle, &f.strafe_x, &f.strafe_y}) *a = int8_t(in.u8());
  f.buttons = in.u16();
  return f;
}

template <typename E>
E read_enum(Reader& in, E last, const char* what) {
  const uint8_t v = in.u8();
  if (v > uint8_t(last)) in.fail(std::string(what) + " " + std::to_string(v) + " is out of range 0.." + std::to_string(int(last)));
  return static_cast<E>(v);
}

// An id into a table of `count` entries, or null: whatever holds one indexes that table with it.
template <typename IdType>
IdType read_ref(Reader& in, size_t count, const char* what, const char* table) {
  const uint32_t v = in.u32();
  if (v > count)
    in.fail(std::string(what) + " " + std::to_string(v) + " is not one of the " + std::to_string(count) + " " + table + " (0 for none)");
  return IdType{v};
}

ShipId read_ship_ref(Reader& in, const World& w, const char* what) { return read_ref<ShipId>(in, w.ships.size(), what, "ships"); }
TeamId read_team_ref(Reader& in, const World& w, const char* what) { return read_ref<TeamId>(in, w.team_names.size(), what, "teams"); }

// A particle owner the world has handed out (allocate_owner).
OwnerId read_owner(Reader& in, const World& w, const std::string& what) {
  const uint32_t v = in.u32();
  if (v == 0 || v >= w.next_particle_owner)
    in.fail(what + " particle owner " + std::to_string(v) + " was never allocated (1.." + std::to_string(w.next_particle_owner - 1) + ")");
  return OwnerId{v};
}

GameOptions read_options(Reader& in, GameOptions o, std::string& level_name, int& tick_rate) {
  level_name = in.str();
  tick_rate = in.i32();
  o.seed_override = true;
  o.seed = in.u64();
  o.difficulty_override = true;
  o.difficulty = read_enum(in, Difficulty::Hard, "difficulty");
  o.particle_budget = in.u32();
  o.lightning_interval = in.i32();
  o.substeps = in.i32();
  if (o.particle_budget == 0 || o.particle_budget > 16'000'000)
    in.fail("particle budget " + std::to_string(o.particle_budget) + " is outside 1..16000000");
  if (o.lightning_interval < 0 || o.lightning_interval > 1000)
    in.fail("lightning interval " + std::to_string(o.lightning_interval) + " is out of range 0..1000");
  if (o.substeps < 1 || o.substeps > 64) in.fail("sub-steps " + std::to_string(o.substeps) + " is out of range 1..64");
  return o;
}

void read_ship(Reader& in, Ship& s, const World& w) {
  const std::string at = "ship " + std::to_string(s.id.value) + " (" + s.name + "): ";
  const uint32_t id = in.u32();
  const std::string name = in.str();
  const std::string cls = in.str();
  if (id != s.id.value || name != s.name || cls != s.cls->name)
    in.fail("ship " + std::to_string(id) + " is '" + name + "' of class " + cls + " in the snapshot, '" + s.name + "' of class " +
            s.cls->name + " in level " + w.level.name);
  s.team = read_team_ref(in, w, "team");
  if (!s.team) in.fail(at + "has no team");
  s.particle_owner = read_owner(in, w, at);
  s.player = in.boolean();
  s.ai = read_enum(in, AiKind::Gunner, "AI kind");
  s.position = in.vec3();
  s.velocity = in.vec3();
  s.angular_velocity = in.vec3();
  s.orientation = in.quat();
  s.prev_position = in.vec3();
  s.prev_orientation = in.quat();
  s.alive = in.boolean();
  s.hull = in.f64();
  s.shield = in.f64();
  s.energy = in.f64();
  s.last_hit_tick = in.i64();
  s.shield_flash_tick = in.i64();
  s.death_tick = in.i64();
  s.last_attacker = read_ship_ref(in, w, "last attacker");
  s.kills = in.i32();
  s.target = read_ship_ref(in, w, "target");
  s.controls = read_input(in);
  s.afterburner_on = in.boolean();
  s.secondary = read_enum(in, SecondaryWeapon::Plasma, "secondary weapon");
  s.secondary_cooldown = in.f64();
  s.hardpoint_cycle = in.u32();
  s.beam_firing = in.boolean();
  s.beam_channels.resize(in.count(8, "beam channel count"));
  for (ClusterHandle& h : s.beam_channels) h = read_handle(in);
  s.beam_hit_distance.resize(in.count(8, "beam hit count"));
  for (double& d : s.beam_hit_distance) d = in.f64();
  // The beam code indexes mounts and hit distances by channel.
  if (s.beam_channels.size() > s.cls->beam.mounts.size() || s.beam_hit_distance.size() != s.beam_channels.size())
    in.fail(at + std::to_string(s.beam_channels.size()) + " beam channels and " + std::to_string(s.beam_hit_distance.size()) +
            " hit distances for " + std::to_string(s.cls->beam.mounts.size()) + " mounts");
  s.beam_target = read_ship_ref(in, w, "beam target");
  s.shield_fx = read_effect(in);
  s.exhaust_fx.resize(in.count(4, "exhaust count"));
  for (EffectHandle& e : s.exhaust_fx) e = read_effect(in);
  s.shown_shield_intensity = in.f64();
  s.shield_density = in.i32();
  s.shield_spawn_tick = in.i64();
  s.shown_exhaust_intensity = in.f64();
  AiState& ai = s.ai_state;
  ai.mode = read_enum(in, AiMode::BreakOff, "AI mode");
  ai.target = read_ship_ref(in, w, "AI target");
  ai.mode_until = in.i64();
  ai.next_think = in.i64();
  ai.aim_error = in.vec3();
  ai.evade_dir = in.vec3();
}

Reader open(const std::vector<uint8_t>& bytes) {
  return Reader::unframe(bytes.data(), bytes.size(), kMagic, kVersion, "game");
}

}  // namespace

std::vector<uint8_t> save_world(const World& w) {
  Writer out;
  write_options(out, w);
  out.i64(w.tick);
  out.u64(w.steps);
  out.u32(w.next_projectile_serial);
  out.u32(w.next_particle_owner);
  out.boolean(w.paused);
  out.u32(w.player.value);
  out.u8(uint8_t(w.outcome));
  out.u32(w.winner.value);
  out.i64(w.outcome_tick);
  out.u8(uint8_t(w.camera_mode));
  out.vec3(w.camera.position);
  out.quat(w.camera.orientation);
  out.vec3(w.prev_camera.position);
  out.quat(w.prev_camera.orientation);
  out.u32(uint32_t(w.ships.size()));
  for (const Ship& s : w.ships) write_ship(out, s, w);
  out.u32(uint32_t(w.projectiles.size()));
  for (const Projectile& p : w.projectiles) {
    out.u32(p.serial);
    out.u8(uint8_t(p.kind));
    out.u32(p.owner.value);
    out.u32(p.target.value);
    out.u32(p.particle_owner.value);
    out.vec3(p.position);
    out.vec3(p.velocity);
    out.vec3(p.prev_position);
    out.f64(p.damage);
    out.f64(p.turn_rate);
    out.f64(p.hit_radius);
    out.i64(p.expire_tick);
    write_effect(out, p.trail);
  }
  out.u32(uint32_t(w.props.size()));
  for (const Prop& p : w.props) {
    out.u32(p.model.value);
    out.str(p.label);
    out.vec3(p.position);
    out.quat(p.orientation);
    out.f64(p.scale);
    out.f64(p.radius);
  }
  out.u32(uint32_t(w.explosions.size()));
  for (const ExplosionEvent& e : w.explosions) {
    out.vec3(e.position);
    out.i64(e.tick);
    out.f64(e.radius);
  }
  out.bytes(w.particles->save());
  return out.framed(kMagic, kVersion);
}

GameOptions snapshot_options(const std::vector<uint8_t>& bytes, const GameOptions& base) {
  Reader in = open(bytes);
  std::string level;
  int tick_rate = 0;
  return read_options(in, base, level, tick_rate);
}

void load_world(World& w, const std::vector<uint8_t>& bytes) {
  Reader in = open(bytes);
  std::string level;
  int tick_rate = 0;
  const GameOptions o = read_options(in, w.options, level, tick_rate);
  if (level != w.level.name || tick_rate != w.level.tick_rate)
    in.fail("saved in level '" + level + "' at " + std::to_string(tick_rate) + " ticks per second, restored into '" + w.level.name +
            "' at " + std::to_string(w.level.tick_rate));
  if (o.seed != w.seed || int(o.difficulty) != w.difficulty || o.particle_budget != w.options.particle_budget ||
      o.lightning_interval != w.options.lightning_interval || o.substeps != w.options.substeps)
    in.fail("the world was not initialised with the snapshot's seed, difficulty and simulation settings");
  w.tick = in.i64();
  w.steps = in.u64();
  w.next_projectile_serial = in.u32();
  w.next_particle_owner = in.u32();
  if (w.next_particle_owner == 0) in.fail("next particle owner is 0 (owners start at 1)");
  w.paused = in.boolean();
  w.player = read_ship_ref(in, w, "player");
  w.outcome = read_enum(in, Outcome::TeamWon, "outcome");
  w.winner = read_team_ref(in, w, "winner");
  w.outcome_tick = in.i64();
  w.camera_mode = read_enum(in, CameraMode::Fixed, "camera mode");
  w.camera.position = in.vec3();
  w.camera.orientation = in.quat();
  w.prev_camera.position = in.vec3();
  w.prev_camera.orientation = in.quat();
  const size_t ships = in.count(1, "ship count");
  if (ships != w.ships.size())
    in.fail(std::to_string(ships) + " ships, level '" + w.level.name + "' has " + std::to_string(w.ships.size()));
  for (Ship& s : w.ships) read_ship(in, s, w);
  w.projectiles.resize(in.count(1, "projectile count"));
  for (Projectile& p : w.projectiles) {
    p.serial = in.u32();
    p.kind = read_enum(in, SecondaryWeapon::Plasma, "projectile kind");
    p.owner = read_ship_ref(in, w, "projectile owner");
    if (!p.owner) in.fail("projectile " + std::to_string(p.serial) + " has no owner");
    p.target = read_ship_ref(in, w, "projectile target");
    p.particle_owner = read_owner(in, w, "projectile " + std::to_string(p.serial));
    p.position = in.vec3();
    p.velocity = in.vec3();
    p.prev_position = in.vec3();
    p.damage = in.f64();
    p.turn_rate = in.f64();
    p.hit_radius = in.f64();
    p.expire_tick = in.i64();
    p.trail = read_effect(in);
  }
  const size_t props = in.count(1, "prop count");
  if (props != w.props.size())
    in.fail(std::to_string(props) + " props, level '" + w.level.name + "' has " + std::to_string(w.props.size()));
  for (Prop& p : w.props) {
    p.model = read_ref<ModelSlot>(in, w.model_paths.size(), "prop model", "level's models");
    p.label = in.str();
    p.position = in.vec3();
    p.orientation = in.quat();
    p.scale = in.f64();
    p.radius = in.f64();
  }
  w.explosions.resize(in.count(1, "explosion count"));
  for (ExplosionEvent& e : w.explosions) {
    e.position = in.vec3();
    e.tick = in.i64();
    e.radius = in.f64();
  }
  const std::vector<uint8_t> particles = in.bytes();
  in.expect_end();
  // Both clocks advance together (step_world steps the particles to w.tick); a particle world
  // behind the game would be caught up tick by tick at the next step.
  if (w.tick < 0) in.fail("tick " + std::to_string(w.tick) + " is negative");
  w.particles->load(particles);
  if (w.particles->tick() != uint64_t(w.tick))
    throw InputError("snapshot: game: the particle world is at tick " + std::to_string(w.particles->tick()) + ", the game at tick " +
                     std::to_string(w.tick));
}

}  // namespace arc
