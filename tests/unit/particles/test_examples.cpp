// The usage examples of the particle headers' banners, as tests: each TEST body holds its
// banner's example line for line (HeaderExamples.MatchTheirTests in tests/unit/core checks
// that), so an example that stops compiling or working fails here. Also the drawn-owner
// placement collect() offers the renderer.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "particles/effect_library.h"
#include "particles/effect_schema.h"
#include "particles/particle_store.h"
#include "particles/particle_world.h"
#include "core/data_root.h"

namespace arc {
namespace {

const std::string kRoot = arc::data_root();

glm::dvec3 mean_position(const std::vector<ParticleInstance>& ps, uint32_t cluster) {
  glm::dvec3 sum(0.0);
  int n = 0;
  for (const ParticleInstance& p : ps)
    if (p.cluster == cluster) sum += glm::dvec3(p.pos[0], p.pos[1], p.pos[2]), ++n;
  return n ? sum / double(n) : sum;
}

TEST(EffectLibraryExample, LoadsTheGameEffects) {
  const std::string cwd = std::filesystem::current_path();
  std::filesystem::current_path(kRoot);
  EffectLibrary fx;
  fx.load_directory("assets/effects");
  const EffectDef& boom = fx.get("ship_explosion");
  const EffectId explosion = fx.id("ship_explosion");   // fx.get(explosion) is the same definition
  std::filesystem::current_path(cwd);
  EXPECT_EQ(boom.name, "ship_explosion");
  EXPECT_FALSE(boom.clusters.empty());
  EXPECT_EQ(&fx.get(explosion), &boom);
  EXPECT_NE(fx.id("shield_sphere"), explosion);
}

TEST(ParticleWorldExample, SpawnStepCollect) {
  const std::string cwd = std::filesystem::current_path();
  std::filesystem::current_path(kRoot);
  const uint64_t level_seed = 7;
  const OwnerId ship_owner{1u};
  const glm::dvec3 where(0, 0, -50), mount(2, 0, -4), forward(0, 0, -1);
  const glm::dvec3 ship_position(0, 0, -20), ship_velocity(0, 0, -30);
  const glm::dquat ship_rotation(1, 0, 0, 0);
  ParticleCamera camera;
  camera.position = {0, 0, 100};
  std::vector<ParticleInstance> particles;
  std::vector<DrawnOwner> drawn_owners;
  uint64_t tick = 1;

  EffectLibrary fx;
  fx.load_directory("assets/effects");
  ParticleWorld world(ParticleConfig{.seed = level_seed}, &fx);
  const EffectId explosion = fx.id("ship_explosion");   // once, at load
  EffectHandle boom = world.spawn(explosion, SpawnParams{.position = where});
  ClusterHandle beam = world.spawn_lightning(fx.id("lightning_beam"), ship_owner, mount, forward);
  world.set_owner_transform(ship_owner, OwnerTransform{ship_position, ship_rotation, ship_velocity});
  world.step(tick, camera);
  world.collect(camera, particles, drawn_owners);

  std::filesystem::current_path(cwd);
  EXPECT_FALSE(boom.clusters.empty());
  EXPECT_TRUE(world.alive(beam));
  EXPECT_GT(world.stats().live_particles, 0u);
  EXPECT_FALSE(particles.empty());
}

// An attached cluster is drawn where its owner is drawn: the renderer interpolates the owner
// between ticks, and a shield collected with that pose keeps its place on it for any alpha.
// The shield's particle centroid sits at a fixed offset from its owner (64 random points on a
// sphere do not average to its centre), so the test compares that offset at the tick and drawn.
TEST(ParticleWorldDrawnOwners, AttachedClusterFollowsTheDrawnOwner) {
  EffectLibrary fx;
  fx.load_text(R"({ "clusters": [ { "sprite": "shield", "space": "owner",
    "animation": { "type": "sphere", "motion": "static", "radius": 10 },
    "emitter": { "burst": 64 }, "particles": { "lifetime": 0 } } ] })",
               "shield.json");
  ParticleWorld world(ParticleConfig{.seed = 3}, &fx);
  const OwnerId owner{5u};
  const EffectHandle shield = world.spawn("shield", SpawnParams{.owner = owner});
  ParticleCamera camera;
  camera.position = {0, 0, 200};
  const glm::dvec3 velocity(40, 0, 0);  // 40 m/s: 0.67 m a tick at 60 Hz
  const glm::dquat turn = glm::angleAxis(0.3, glm::dvec3(0, 1, 0));
  glm::dvec3 prev(0.0), now(0.0);
  for (uint64_t t = 1; t <= 10; ++t) {
    prev = now;
    now = glm::dvec3(velocity.x * double(t) / 60.0, 0, 0);
    world.set_owner_transform(owner, OwnerTransform{now, turn, velocity});
    world.step(t, camera);
  }
  const uint32_t cluster = shield.clusters.at(0).index;
  std::vector<ParticleInstance> at_tick;
  world.collect(camera, at_tick);
  ASSERT_EQ(at_tick.size(), 64u);
  const glm::dvec3 offset = mean_position(at_tick, cluster) + camera.position - now;
  for (double alpha : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const glm::dvec3 drawn_at = prev + (now - prev) * alpha;
    const std::vector<DrawnOwner> drawn{{owner, drawn_at, turn}, {OwnerId{6u}, glm::dvec3(1e6), turn}};
    std::vector<ParticleInstance> out;
    world.collect(camera, out, drawn);
    const glm::dvec3 centre = mean_position(out, cluster) + camera.position;
    EXPECT_NEAR(glm::length(centre - drawn_at - offset), 0.0, 1e-3) << "alpha " << alpha;
  }
  // An owner the list does not name keeps the tick's pose.
  const std::vector<DrawnOwner> others{{OwnerId{6u}, glm::dvec3(1e6), turn}};
  std::vector<ParticleInstance> out;
  world.collect(camera, out, others);
  EXPECT_NEAR(glm::length(mean_position(out, cluster) + camera.position - now - offset), 0.0, 1e-3);
}

TEST(EffectSchemaExample, LookUpAKey) {
  const EffectField& rate = effect_field(EffectBlock::Emitter, "rate");    // kind Number, [0, 1e7]
  const EffectField* f = effect_field_at("/clusters/0/curves/alpha");       // kind Curve, [0, 1]
  EXPECT_EQ(std::string(rate.key), "rate");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(std::string(f->key), "alpha");
  EXPECT_EQ(effect_field_at("/clusters/0/curves/alpha/0"), nullptr) << "inside a value";
}

TEST(ParticleStoreExample, TakeAndGiveBack) {
  const uint32_t budget = 4096;
  ParticleStore store(budget);
  ParticleBlock b = store.take(300);           // b.capacity == 512, or 0 when none is free
  std::byte* px = store.column(0);              // ParticlePool binds its columns (particle_pool.h)
  store.give_back(b);
  EXPECT_EQ(b.capacity, 512u);
  EXPECT_NE(px, nullptr);
  EXPECT_EQ(store.take(300).first, b.first) << "the freed block is handed out again";
}

}  // namespace
}  // namespace arc
