// game/sim/serialize.cpp — World snapshots: the settings header, then every saved field in the
// order of the field visitors (game/sim/world.h), then the particle world's own snapshot.
#include "game/sim/serialize.h"

#include <string>

#include "game/sim/mission_events.h"
#include "game/sim/world.h"
#include "core/snapshot_io.h"
#include "core/state_fields.h"

namespace arc {

// ---------------------------------------------------------------- leaf encodings

// Found by fields::write_value (argument-dependent lookup, hence namespace arc rather than an
// unnamed namespace); read back by WorldReading below.
static_assert(sizeof(InputFrame) == 8, "a field added to InputFrame needs its hash, snapshot and dump encodings");

static void write_leaf(snapshot::Writer& out, const InputFrame& f) {
  for (int8_t a : {f.pitch, f.yaw, f.roll, f.throttle, f.strafe_x, f.strafe_y}) out.u8(uint8_t(a));
  out.u16(f.buttons);
}
static void write_leaf(snapshot::Writer& out, ClusterHandle h) {
  out.u32(h.index);
  out.u32(h.generation);
}
static void write_leaf(snapshot::Writer& out, const EffectHandle& e) { fields::write_value(out, e.clusters); }
static void write_leaf(snapshot::Writer& out, const ShipClassDef* c) { out.str(c->name); }
static void write_leaf(snapshot::Writer& out, const std::optional<ParticleWorld>& p) { out.bytes(p->save()); }
// Written only in training levels (the reader knows from the level), so other snapshots keep their bytes.
static void write_leaf(snapshot::Writer& out, const std::optional<TrainingProgress>& t) {
  if (t) fields::write_value(out, *t);
}

// Written only in levels with events or objectives, likewise.
static void write_leaf(snapshot::Writer& out, const std::optional<MissionProgress>& m) {
  if (m) fields::write_value(out, *m);
}

namespace {

constexpr uint64_t kMagic = snapshot::magic("ARCSNAP1");
// 3: typed ids (ships, teams, model slots, particle owners) as their u32 values; 4: ship combat stats;
// 5: the wing, the waves and the messages; 6: missile locks, flares and decoyed missiles
constexpr uint32_t kVersion = 6;

using snapshot::Reader;
using snapshot::Writer;

// ---------------------------------------------------------------- settings header

// What restore must load the level with before the rest can be read: its name and tick rate,
// the seed, the difficulty and the simulation settings.
struct SnapshotSettings {
  std::string level;
  int32_t tick_rate = 0;
  uint64_t seed = 0;
  Difficulty difficulty = Difficulty::Normal;
  uint32_t particle_budget = 0;
  int32_t lightning_interval = 0;
  int32_t substeps = 0;
  bool operator==(const SnapshotSettings&) const = default;
};

template <fields::MaybeConst<SnapshotSettings> S, class V>
void visit_fields(S& s, V&& v) {
  v("level", s.level, fields::saved, fields::unhashed);
  v("tick_rate", s.tick_rate, fields::saved, fields::unhashed);
  v("seed", s.seed, fields::saved, fields::unhashed);
  v("difficulty", s.difficulty, fields::saved, fields::unhashed);
  v("particle_budget", s.particle_budget, fields::saved, fields::unhashed);
  v("lightning_interval", s.lightning_interval, fields::saved, fields::unhashed);
  v("substeps", s.substeps, fields::saved, fields::unhashed);
}

// The World's fields tagged level_settings (world.h), as the header holds them.
SnapshotSettings settings_of(const World& w) {
  return {w.level.name, w.level.tick_rate, w.seed, static_cast<Difficulty>(w.difficulty), w.options.particle_budget,
          w.options.lightning_interval, w.options.substeps};
}

// Reads the header; hooks of fields::FieldReader check the values the engine relies on.
struct SettingsReading {
  void after_read(Reader& in, const SnapshotSettings& s) {
    if (s.particle_budget == 0 || s.particle_budget > kMaxParticleBudget)
      in.fail("particle budget " + std::to_string(s.particle_budget) + " is outside 1.." + std::to_string(kMaxParticleBudget));
    if (s.lightning_interval < 0 || s.lightning_interval > 1000)
      in.fail("lightning interval " + std::to_string(s.lightning_interval) + " is out of range 0..1000");
    if (s.substeps < 1 || s.substeps > 64) in.fail("sub-steps " + std::to_string(s.substeps) + " is out of range 1..64");
  }
};

SnapshotSettings read_settings(Reader& in) {
  SnapshotSettings s;
  SettingsReading hooks;
  fields::FieldReader<SettingsReading>(in, hooks).read("settings", s);
  return s;
}

// ---------------------------------------------------------------- world

// fields::FieldReader's context for a World: leaf types, references and checks across fields.
struct WorldReading {
  World& w;

  void read_leaf(Reader& in, const char*, InputFrame& f) {
    for (int8_t* a : {&f.pitch, &f.yaw, &f.roll, &f.throttle, &f.strafe_x, &f.strafe_y}) *a = int8_t(in.u8());
    f.buttons = in.u16();
  }
  void read_leaf(Reader& in, const char*, ClusterHandle& h) {
    h.index = in.u32();
    h.generation = in.u32();
  }
  void read_leaf(Reader& in, const char* name, EffectHandle& e) { fields::FieldReader(in, *this).read(name, e.clusters); }
  void read_leaf(Reader& in, const char*, std::optional<ParticleWorld>& p) { p->load(in.bytes()); }
  void read_leaf(Reader& in, const char* name, std::optional<TrainingProgress>& t) {
    t.reset();
    const size_t steps = w.level.training.steps.size();
    if (steps == 0) return;
    t.emplace();
    fields::FieldReader(in, *this).read(name, *t);
    if (t->step < 0 || size_t(t->step) > steps)
      in.fail(std::string(name) + " step " + std::to_string(t->step) + " is outside 0.." + std::to_string(steps));
  }

  void read_leaf(Reader& in, const char* name, std::optional<MissionProgress>& m) {
    m.reset();
    if (w.level.events.empty()) return;
    m.emplace(new_mission_progress(w));
    fields::FieldReader(in, *this).read(name, *m);
  }

  // A typed id: its u32 value (validate checks what it refers to).
  template <class Tag>
  void read_leaf(Reader& in, const char*, Id<Tag>& id) {
    id = Id<Tag>{in.u32()};
  }

  // An id into a table of `count` entries, or null: whatever holds one indexes that table with it.
  static void check_ref(Reader& in, const char* name, uint32_t v, size_t count, const char* table) {
    if (v > count)
      in.fail(std::string(name) + " " + std::to_string(v) + " is not one of the " + std::to_string(count) + " " + table +
              " (0 for none, else 1.." + std::to_string(count) + ")");
  }
  void validate(Reader& in, const char* name, ShipId v, ShipRef) { check_ref(in, name, v.value, w.ships.size(), "ships"); }
  void validate(Reader& in, const char* name, ModelSlot v, ModelRef) {
    check_ref(in, name, v.value, w.model_paths.size(), "level's models");
  }
  void validate(Reader& in, const char* name, TeamId v, TeamRef) { check_ref(in, name, v.value, w.team_names.size(), "teams"); }
  // A particle owner the world has handed out (allocate_owner); next_particle_owner is read first.
  void validate(Reader& in, const char* name, OwnerId v, OwnerRef) {
    if (v.value == 0 || v.value >= w.next_particle_owner)
      in.fail(std::string(name) + " particle owner " + std::to_string(v.value) + " was never allocated (1.." +
              std::to_string(w.next_particle_owner - 1) + ")");
  }
  // Every ship is on a team; the beam code indexes mounts and hit distances by channel.
  void after_read(Reader& in, const Ship& s) {
    if (!s.team) in.fail("ship " + std::to_string(s.id.value) + " (" + s.name + "): has no team");
    if (s.beam_channels.size() > s.cls->beam.mounts.size() || s.beam_hit_distance.size() != s.beam_channels.size())
      in.fail("ship " + std::to_string(s.id.value) + " (" + s.name + "): " + std::to_string(s.beam_channels.size()) +
              " beam channels and " + std::to_string(s.beam_hit_distance.size()) + " hit distances for " +
              std::to_string(s.cls->beam.mounts.size()) + " mounts");
  }
  void after_read(Reader& in, const World& world) {
    if (world.next_particle_owner == 0) in.fail("next particle owner is 0 (owners start at 1)");
  }
  void after_read(Reader& in, const Projectile& p) {
    if (!p.owner) in.fail("projectile " + std::to_string(p.serial) + " has no owner");
  }
  void after_read(Reader& in, const Flare& f) {
    if (!f.owner) in.fail("flare " + std::to_string(f.serial) + " has no owner");
  }
};

Reader open(const std::vector<uint8_t>& bytes) {
  return Reader::unframe(bytes.data(), bytes.size(), kMagic, kVersion, "game");
}

}  // namespace

std::vector<uint8_t> save_world(const World& w) {
  Writer out;
  fields::write_value(out, settings_of(w));
  fields::write_value(out, w);
  return out.framed(kMagic, kVersion);
}

GameOptions snapshot_options(const std::vector<uint8_t>& bytes, const GameOptions& base) {
  Reader in = open(bytes);
  const SnapshotSettings s = read_settings(in);
  GameOptions o = base;
  o.seed_override = true;
  o.seed = s.seed;
  o.difficulty_override = true;
  o.difficulty = s.difficulty;
  o.particle_budget = s.particle_budget;
  o.lightning_interval = s.lightning_interval;
  o.substeps = s.substeps;
  return o;
}

void load_world(World& w, const std::vector<uint8_t>& bytes) {
  Reader in = open(bytes);
  const SnapshotSettings saved = read_settings(in);
  const SnapshotSettings here = settings_of(w);
  if (saved.level != here.level || saved.tick_rate != here.tick_rate)
    in.fail("saved in level '" + saved.level + "' at " + std::to_string(saved.tick_rate) + " ticks per second, restored into '" +
            here.level + "' at " + std::to_string(here.tick_rate));
  if (saved != here) in.fail("the world was not initialised with the snapshot's seed, difficulty and simulation settings");
  WorldReading hooks{w};
  fields::FieldReader<WorldReading>(in, hooks).read("world", w);
  in.expect_end();
  // Both clocks advance together (step_world steps the particles to w.tick); a particle world
  // behind the game would be caught up tick by tick at the next step.
  if (w.tick < 0) in.fail("tick " + std::to_string(w.tick) + " is negative");
  if (w.particles->tick() != uint64_t(w.tick))
    throw InputError("snapshot: game: the particle world is at tick " + std::to_string(w.particles->tick()) + ", the game at tick " +
                     std::to_string(w.tick));
}

}  // namespace arc
