// ParticleWorld::save/load: a loaded world is the same world (every particle, every counter)
// and goes on identically; damaged bytes are InputErrors and leave the world as it was. A
// cluster's fields are all named by its field visitor (particles/world_state.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "core/error.h"
#include "core/hash.h"
#include "particles/effect_library.h"
#include "core/fast_hash.h"
#include "particles/particle_store.h"
#include "particles/particle_world.h"
#include "core/snapshot_io.h"
#include "particles/world_state.h"
#include "core/data_root.h"

namespace arc {
namespace {

// The game's own effects: every animation type, owners, lightning, flashes.
const EffectLibrary& effects() {
  static EffectLibrary lib = [] {
    EffectLibrary l;
    l.load_directory(arc::data_root() + "/assets/effects");
    return l;
  }();
  return lib;
}

uint64_t full(const ParticleWorld& w) {
  StateHasher h;
  w.hash(h);
  return h.value();
}

uint64_t summary(const ParticleWorld& w) {
  FastHasher h;
  w.hash_summary(h);
  return h.value();
}

OwnerTransform owner_at(uint64_t tick, int id) {
  OwnerTransform t;
  const double a = 0.02 * double(tick) + id;
  t.position = {40.0 * std::cos(a) + 10 * id, 5.0 * id, 40.0 * std::sin(a)};
  t.orientation = glm::angleAxis(a, glm::dvec3(0, 1, 0));
  t.velocity = {-0.8 * std::sin(a) * 60, 0, 0.8 * std::cos(a) * 60};
  return t;
}

ParticleCamera camera() {
  ParticleCamera c;
  c.position = {0, 30, 150};
  return c;
}

// A busy scene driven by the tick alone: ships with shields and exhausts, beams that start,
// stop and get cut, explosions, sparks, missile trails whose owners stop emitting.
struct Scene {
  ParticleWorld world{ParticleConfig{.seed = 77, .budget = 60000}, &effects()};
  std::vector<ClusterHandle> beams;
  std::vector<EffectHandle> trails;

  void spawn_ships() {
    for (uint32_t id = 1; id <= 3; ++id) {
      world.set_owner_transform(OwnerId{id}, owner_at(0, int(id)));
      world.spawn("shield_sphere", SpawnParams{.owner = OwnerId{id}, .scale = 1.1});
      world.spawn("engine_exhaust", SpawnParams{.position = {0, 0, 4}, .owner = OwnerId{id}, .priority = 0});
    }
  }

  void step(uint64_t t) {
    for (uint32_t id = 1; id <= 3; ++id) world.set_owner_transform(OwnerId{id}, owner_at(t, int(id)));
    if (t % 50 == 3) beams.push_back(world.spawn_lightning("lightning_beam", OwnerId{1 + uint32_t(t % 3)}, {0, 0, -5}, {0, 0, -1}));
    if (t % 50 == 40 && !beams.empty()) {
      world.destroy(beams.front());
      beams.erase(beams.begin());
    }
    for (ClusterHandle b : beams) world.cut_lightning(b, 30.0 + double(t % 70));
    if (t % 90 == 17) world.spawn("ship_explosion", SpawnParams{.position = {double(t % 40), 0, -20}, .priority = 2});
    if (t % 7 == 2) world.spawn("hull_sparks", SpawnParams{.position = {0, double(t % 11), 0}, .priority = 0});
    if (t % 13 == 5) world.spawn("shield_hit", SpawnParams{.position = {3, 1, double(t % 5)}, .priority = 0});
    if (t % 60 == 11) {
      const OwnerId owner{1000 + uint32_t(t)};
      world.set_owner_transform(owner, owner_at(t, 7));
      trails.push_back(world.spawn("missile_trail", SpawnParams{.owner = owner}));
    }
    if (t % 60 == 50 && !trails.empty()) {
      for (ClusterHandle c : trails.front().clusters) world.stop_emitting(c);
      trails.erase(trails.begin());
    }
    world.step(t, camera());
  }
};

TEST(ParticleSnapshot, RoundTripKeepsEveryParticleAndContinuesIdentically) {
  Scene a;
  a.spawn_ships();
  for (uint64_t t = 1; t <= 250; ++t) a.step(t);
  ASSERT_GT(a.world.stats().live_particles, 500u);
  const std::vector<uint8_t> bytes = a.world.save();

  Scene b;  // a fresh world (nothing spawned) takes the whole state from the bytes
  b.world.load(bytes);
  b.beams = a.beams;
  b.trails = a.trails;
  EXPECT_EQ(full(a.world), full(b.world));
  EXPECT_EQ(summary(a.world), summary(b.world));
  EXPECT_EQ(b.world.save(), bytes);
  EXPECT_EQ(b.world.tick(), a.world.tick());
  EXPECT_EQ(b.world.stats().live_particles, a.world.stats().live_particles);
  EXPECT_EQ(b.world.stats().refused_particles, a.world.stats().refused_particles);
  for (ClusterHandle h : a.beams) EXPECT_TRUE(b.world.alive(h));

  for (uint64_t t = 251; t <= 500; ++t) {
    a.step(t);
    b.step(t);
    ASSERT_EQ(summary(a.world), summary(b.world)) << "tick " << t;
    ASSERT_EQ(full(a.world), full(b.world)) << "tick " << t;
  }
  std::vector<ParticleInstance> pa, pb;
  a.world.collect(camera(), pa);
  b.world.collect(camera(), pb);
  ASSERT_EQ(pa.size(), pb.size());
  EXPECT_EQ(0, std::memcmp(pa.data(), pb.data(), pa.size() * sizeof(ParticleInstance)));
}

TEST(ParticleSnapshot, CheapSummaryFollowsTheFullHash) {
  // Two worlds that differ only in one cluster's emitter state differ in the summary too.
  Scene a, b;
  a.spawn_ships();
  b.spawn_ships();
  for (uint64_t t = 1; t <= 30; ++t) a.step(t), b.step(t);
  ASSERT_EQ(summary(a.world), summary(b.world));
  b.world.spawn("hull_sparks", SpawnParams{.position = {1, 2, 3}});
  EXPECT_NE(summary(a.world), summary(b.world));
}

TEST(ParticleSnapshot, DamagedBytesAreInputErrorsAndLeaveTheWorldAlone) {
  Scene a;
  a.spawn_ships();
  for (uint64_t t = 1; t <= 120; ++t) a.step(t);
  const std::vector<uint8_t> bytes = a.world.save();
  Scene b;
  b.spawn_ships();
  b.step(1);
  const uint64_t before = full(b.world);
  auto expect_error = [&](const std::vector<uint8_t>& bad, const std::string& why) {
    try {
      b.world.load(bad);
      ADD_FAILURE() << why << ": loaded without an error";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("snapshot: particle world: ", 0), 0u) << e.what();
    }
    EXPECT_EQ(full(b.world), before) << why;
  };
  for (size_t n = 0; n < bytes.size(); n += 1 + n / 3) expect_error({bytes.begin(), bytes.begin() + n}, "cut at " + std::to_string(n));
  for (size_t at = 0; at < bytes.size(); at += 1 + at / 5) {
    std::vector<uint8_t> bad = bytes;
    bad[at] ^= 0x01;
    expect_error(bad, "bit flipped at " + std::to_string(at));
  }
  // A snapshot naming an effect this library lacks.
  EffectLibrary other;
  other.load_text(R"({ "clusters": [ { "sprite": "glow", "animation": { "type": "linear" }, "emitter": { "burst": 5 } } ] })",
                 "lonely.json");
  ParticleWorld stranger(ParticleConfig{}, &other);
  EXPECT_THROW(stranger.load(bytes), InputError);
  EXPECT_EQ(stranger.stats().live_clusters, 0u);
}

TEST(ParticleSnapshot, FieldsBehindAValidChecksumAreCheckedOrHarmless) {
  Scene a;
  a.spawn_ships();
  for (uint64_t t = 1; t <= 60; ++t) a.step(t);
  const std::vector<uint8_t> bytes = a.world.save();
  const size_t end = bytes.size() - snapshot::kFrameTrailer;
  int errors = 0, loaded = 0;
  auto store = std::make_shared<ParticleStore>(60000);  // one for every world below, made one at a time
  for (size_t at = snapshot::kFrameHeader; at < end; at += (at < 3000 ? 1 : 61)) {
    std::vector<uint8_t> bad = bytes;
    bad[at] = uint8_t(~bad[at]);
    const uint64_t c = snapshot::checksum(bad.data() + snapshot::kFrameHeader, end - snapshot::kFrameHeader);
    for (int i = 0; i < 8; ++i) bad[end + size_t(i)] = uint8_t(c >> (8 * i));
    ParticleWorld w(ParticleConfig{.seed = 77, .budget = 60000}, &effects(), store);
    try {
      w.load(bad);
      for (uint64_t t = 61; t <= 63; ++t) w.step(t, camera());
      std::vector<ParticleInstance> out;
      w.collect(camera(), out);
      ++loaded;
    } catch (const InputError&) {
      ++errors;
    }
  }
  EXPECT_GT(errors, 50);
  EXPECT_GT(loaded, 50);
}

// The budget is the settings' range at most (1..4 000 000): a world's particle store is written
// through at its budget, so a snapshot asking for more is refused before any of it is made.
TEST(ParticleSnapshot, ABudgetAboveTheSettingsRangeIsRefused) {
  Scene a;
  const std::vector<uint8_t> bytes = a.world.save();
  const size_t end = bytes.size() - snapshot::kFrameTrailer;
  std::vector<uint8_t> bad = bytes;
  const size_t budget_at = snapshot::kFrameHeader + 8;  // after the seed
  const uint32_t too_many = 4'000'001;
  for (int i = 0; i < 4; ++i) bad[budget_at + size_t(i)] = uint8_t(too_many >> (8 * i));
  const uint64_t c = snapshot::checksum(bad.data() + snapshot::kFrameHeader, end - snapshot::kFrameHeader);
  for (int i = 0; i < 8; ++i) bad[end + size_t(i)] = uint8_t(c >> (8 * i));
  ParticleWorld w(ParticleConfig{.seed = 77, .budget = 60000}, &effects());
  try {
    w.load(bad);
    ADD_FAILURE() << "a budget of 4 000 001 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("particle budget 4000001 is outside 1..4000000"), std::string::npos) << e.what();
  }
}

// A member added to Cluster or LightningChannel and not to its visitor makes the aggregate count
// (the most initialisers T{...} accepts) exceed the visitor's. A live cluster is the probe: a
// free slot's visit stops after its generation.
TEST(ParticleSnapshot, EveryClusterMemberIsNamedByItsVisitor) {
  Cluster cluster;
  cluster.alive = true;
  LightningChannel channel;
  EXPECT_EQ(fields::visited_field_count(cluster), fields::aggregate_field_count<Cluster>());
  EXPECT_EQ(fields::visited_field_count(channel), fields::aggregate_field_count<LightningChannel>());
  Cluster free_slot;
  EXPECT_EQ(fields::visited_field_count(free_slot), 2u);
}

TEST(ParticleSnapshot, ClusterHashWordsAreNumberedWithoutGapsOrClashes) {
  Cluster cluster;
  cluster.alive = true;
  LightningChannel channel;
  for (int pass : {kClusterHashPass, kSummaryHashPass, kFullHashPass}) {
    SCOPED_TRACE("pass " + std::to_string(pass));
    EXPECT_EQ(fields::check_hash_words(fields::hash_slots(cluster, pass)), "");
    EXPECT_EQ(fields::check_hash_words(fields::hash_slots(channel, pass)), "");
  }
}

}  // namespace
}  // namespace arc
