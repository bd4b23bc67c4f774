// ParticleWorld: attachment, owner destruction, skip-and-catch-up equality, budget, output, copies,
// free lightning channels that end.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/error.h"
#include "core/hash.h"
#include "particles/effect_library.h"
#include "particles/particle_world.h"

namespace arc {
namespace {

// One effect per animation type, plus an attached shield and a lightning beam.
const EffectLibrary& library() {
  static EffectLibrary lib = [] {
    EffectLibrary l;
    l.load_text(R"({ "clusters": [ { "sprite": "smoke",
      "animation": { "type": "linear", "drag": 1.5, "acceleration": [0, -2, 0] },
      "emitter": { "shape": "sphere", "radius": 1, "rate": 50, "burst": 20 },
      "particles": { "speed": [2, 9], "lifetime": [0.5, 2], "size": [1, 2], "spin_deg": [-90, 90] },
      "curves": { "burn": [[0, 1], [1, 0]], "alpha": [[0, 1], [1, 0]], "size": [[0, 1], [1, 3]] } } ] })",
                "linear.json");
    for (const char* motion : {"static", "stochastic", "rotational"})
      for (const char* radius : {"constant", "pulsating", "contracting", "exploding"})
        l.load_text(std::string(R"({ "clusters": [ { "sprite": "glow", "lifetime": 3,
          "animation": { "type": "sphere", "motion": ")") + motion + R"(", "radius": 5, "rotation_deg": [10, 40, -25],
            "radius_animation": ")" + radius + R"(", "amplitude": 0.3, "frequency_hz": 1.3, "growth": 4 },
          "emitter": { "burst": 40, "rate": 10 }, "particles": { "lifetime": [0, 0] } } ] })",
                    std::string("sphere_") + motion + "_" + radius + ".json");
    l.load_text(R"({ "clusters": [ { "sprite": "shield", "space": "owner",
      "animation": { "type": "sphere", "motion": "rotational", "radius": 10, "rotation_deg": [0, 30, 0] },
      "emitter": { "burst": 100 }, "particles": { "lifetime": 0 } } ] })",
                "shield.json");
    l.load_text(R"({ "clusters": [ { "sprite": "spark",
      "animation": { "type": "lightning", "seed_length": 5, "max_length": 200, "max_angle_deg": 20, "sizzle_ticks": 4 } } ] })",
                "beam.json");
    l.load_text(R"({ "clusters": [ { "sprite": "blob", "space": "owner", "animation": { "type": "linear" },
      "emitter": { "rate": 30 }, "particles": { "lifetime": 100, "speed": 0 } } ] })",
                "trickle.json");
    return l;
  }();
  return lib;
}

ParticleCamera looking_at_origin() {
  ParticleCamera c;
  c.position = {0, 0, 100};
  return c;
}

ParticleCamera looking_away() {
  ParticleCamera c = looking_at_origin();
  c.orientation = glm::angleAxis(M_PI, glm::dvec3(0, 1, 0));  // facing +Z, the scene behind
  return c;
}

uint64_t hash_of(const ParticleWorld& w) {
  StateHasher h;
  w.hash(h);
  return h.value();
}

std::vector<std::string> all_effects() {
  std::vector<std::string> out = {"linear", "beam"};
  for (const char* motion : {"static", "stochastic", "rotational"})
    for (const char* radius : {"constant", "pulsating", "contracting", "exploding"})
      out.push_back(std::string("sphere_") + motion + "_" + radius);
  return out;
}

TEST(World, SkippedClustersCatchUpBitForBitForEveryAnimationType) {
  for (const std::string& fx : all_effects()) {
    ParticleWorld a(ParticleConfig{.seed = 3}, &library());
    ParticleWorld b(ParticleConfig{.seed = 3}, &library());
    OwnerTransform ship{{0, 0, 0}, glm::angleAxis(0.3, glm::dvec3(0, 1, 0)), {0, 0, 0}};
    for (ParticleWorld* w : {&a, &b}) {
      w->set_owner_transform(OwnerId{1u}, ship);
      if (fx == "beam") w->spawn_lightning(fx, OwnerId{1u}, {0, 0, 0}, {0, 0, -1});
      else w->spawn(fx, SpawnParams{.position = {1, 2, 3}, .velocity = {3, 0, 0}});
    }
    uint32_t skipped = 0;
    for (uint64_t t = 1; t <= 90; ++t) {
      ship.position.x += 0.5;
      ship.orientation = glm::angleAxis(0.01, glm::dvec3(0, 0, 1)) * ship.orientation;
      a.set_owner_transform(OwnerId{1u}, ship);
      b.set_owner_transform(OwnerId{1u}, ship);
      a.step(t, looking_at_origin());
      b.step(t, t >= 20 && t < 70 ? looking_away() : looking_at_origin());
      skipped += b.stats().skipped_clusters;
      EXPECT_EQ(a.stats().live_particles, b.stats().live_particles) << fx << " tick " << t;
    }
    EXPECT_GT(skipped, 0u) << fx << ": the culled run never skipped";
    EXPECT_GT(a.stats().live_particles, 0u) << fx;
    EXPECT_EQ(hash_of(a), hash_of(b)) << fx;
    std::vector<ParticleInstance> pa, pb;
    a.collect(looking_at_origin(), pa);
    b.collect(looking_at_origin(), pb);
    ASSERT_EQ(pa.size(), pb.size()) << fx;
    ASSERT_GT(pa.size(), 0u) << fx;
    EXPECT_EQ(std::memcmp(pa.data(), pb.data(), pa.size() * sizeof(ParticleInstance)), 0) << fx;
  }
}

TEST(World, CollectEvaluatesAClusterThatWasCulledAtStep) {
  ParticleWorld a(ParticleConfig{.seed = 3}, &library());
  ParticleWorld b(ParticleConfig{.seed = 3}, &library());
  a.spawn("linear", {});
  b.spawn("linear", {});
  for (uint64_t t = 1; t <= 30; ++t) a.step(t, looking_at_origin()), b.step(t, looking_away());
  std::vector<ParticleInstance> pa, pb;
  a.collect(looking_at_origin(), pa);
  b.collect(looking_at_origin(), pb);
  ASSERT_EQ(pa.size(), pb.size());
  EXPECT_EQ(std::memcmp(pa.data(), pb.data(), pa.size() * sizeof(ParticleInstance)), 0);
}

// Whole clusters outside the view frustum are left out of the frame's output before any
// per-particle work; turning back shows them again.
TEST(World, CollectLeavesOutClustersOutsideTheFrustum) {
  ParticleWorld w(ParticleConfig{.seed = 3}, &library());
  w.spawn("linear", {});
  for (uint64_t t = 1; t <= 10; ++t) w.step(t, looking_at_origin());
  std::vector<ParticleInstance> seen, behind;
  w.collect(looking_at_origin(), seen);
  w.collect(looking_away(), behind);
  EXPECT_GT(seen.size(), 0u);
  EXPECT_EQ(behind.size(), 0u);
}

TEST(World, AttachedShieldMovesAndTurnsWithItsOwner) {
  ParticleWorld w(ParticleConfig{}, &library());
  OwnerTransform t{{1000, 0, 0}, glm::dquat(1, 0, 0, 0), {}};
  w.set_owner_transform(OwnerId{7u}, t);
  EffectHandle e = w.spawn("shield", SpawnParams{.owner = OwnerId{7u}});
  w.step(1, looking_at_origin());
  ParticleCamera cam;
  cam.position = {1000, 0, 50};
  std::vector<ParticleInstance> before;
  w.collect(cam, before);
  ASSERT_EQ(before.size(), 100u);
  // Move and turn the owner a quarter turn about Y, and move the camera with it.
  t.position = {2000, 500, 0};
  t.orientation = glm::angleAxis(M_PI / 2, glm::dvec3(0, 1, 0));
  w.set_owner_transform(OwnerId{7u}, t);
  w.step(2, looking_at_origin());
  ParticleCamera cam2;
  cam2.position = {2000, 500, 50};
  std::vector<ParticleInstance> after;
  w.collect(cam2, after);
  ASSERT_EQ(after.size(), 100u);
  const glm::dquat spin_one_tick = glm::angleAxis(30.0 * M_PI / 180.0 / 60.0, glm::dvec3(0, 1, 0));
  for (size_t i = 0; i < after.size(); ++i) {
    const glm::dvec3 p0(before[i].pos[0], before[i].pos[1], before[i].pos[2] + 50);
    const glm::dvec3 want = t.orientation * (spin_one_tick * p0);
    const glm::dvec3 got(after[i].pos[0], after[i].pos[1], after[i].pos[2] + 50);
    EXPECT_NEAR(glm::length(got - want), 0.0, 1e-3) << i;
    EXPECT_NEAR(glm::length(got), 10.0, 1e-3);
  }
  EXPECT_TRUE(w.alive(e.clusters[0]));
}

TEST(World, DestroyingTheOwnerDestroysAttachedClustersAtOnce) {
  ParticleWorld w(ParticleConfig{}, &library());
  w.set_owner_transform(OwnerId{7u}, {});
  w.set_owner_transform(OwnerId{8u}, {});
  EffectHandle shield = w.spawn("shield", SpawnParams{.owner = OwnerId{7u}});
  ClusterHandle beam = w.spawn_lightning("beam", OwnerId{7u}, {0, 0, -5}, {0, 0, -1});
  EffectHandle other = w.spawn("shield", SpawnParams{.owner = OwnerId{8u}});
  w.step(1, looking_at_origin());
  EXPECT_EQ(w.stats().live_clusters, 3u);
  w.destroy_owner(OwnerId{7u});
  EXPECT_FALSE(w.alive(shield.clusters[0]));
  EXPECT_FALSE(w.alive(beam));
  EXPECT_TRUE(w.alive(other.clusters[0]));
  EXPECT_EQ(w.stats().live_clusters, 1u);
  EXPECT_EQ(w.stats().live_particles, 100u);
  // A stale handle stays dead even when its slot is reused.
  EffectHandle again = w.spawn("shield", SpawnParams{.owner = OwnerId{8u}});
  EXPECT_FALSE(w.alive(shield.clusters[0]));
  EXPECT_TRUE(w.alive(again.clusters[0]));
  EXPECT_FALSE(ClusterHandle{});
}

TEST(World, LightningIsAttachedCutAndReadable) {
  ParticleWorld w(ParticleConfig{.seed = 9}, &library());
  w.set_owner_transform(OwnerId{1u}, {{0, 0, 0}, glm::dquat(1, 0, 0, 0), {}});
  ClusterHandle ch = w.spawn_lightning("beam", OwnerId{1u}, {0, 0, -2}, {0, 0, -1});
  std::vector<glm::dvec3> pts = w.lightning_points(ch);
  ASSERT_GE(pts.size(), 3u);  // available the tick it is spawned
  EXPECT_EQ(pts[0], glm::dvec3(0, 0, -2));
  w.step(1, looking_at_origin());
  const double len = w.lightning_length(ch);
  EXPECT_LE(len, 200.0);
  EXPECT_GT(len, 190.0);
  std::vector<ParticleInstance> full, cut;
  w.collect(looking_at_origin(), full);
  w.cut_lightning(ch, 50.0);
  w.collect(looking_at_origin(), cut);
  EXPECT_LT(cut.size(), full.size());
  double drawn = 0.0;
  for (const ParticleInstance& p : cut) {
    EXPECT_EQ(p.billboard, uint8_t(Billboard::AxisLocked));
    drawn += std::sqrt(p.axis[0] * p.axis[0] + p.axis[1] * p.axis[1] + p.axis[2] * p.axis[2]);
  }
  EXPECT_NEAR(drawn, 50.0, 1e-3);
  const glm::dvec3 hit = w.lightning_point_at(ch, 50.0);
  EXPECT_GT(glm::length(hit - glm::dvec3(0, 0, -2)), 40.0);
  // Moving the owner moves the channel.
  w.set_owner_transform(OwnerId{1u}, {{0, 100, 0}, glm::dquat(1, 0, 0, 0), {}});
  EXPECT_NEAR(w.lightning_points(ch)[1].y, 100.0, 1e-9);
  // The seed segment survives a sizzle; later segments change.
  const std::vector<glm::dvec3> before = w.lightning_points(ch);
  for (uint64_t t = 2; t <= 6; ++t) w.step(t, looking_at_origin());
  const std::vector<glm::dvec3> after = w.lightning_points(ch);
  EXPECT_EQ(before[1], after[1]);
  EXPECT_NE(before[3], after[3]);
}

TEST(World, FractionalSpawnRateAccumulates) {
  ParticleWorld w(ParticleConfig{.tick_seconds = 1.0 / 60.0}, &library());
  w.set_owner_transform(OwnerId{2u}, {});
  w.spawn("trickle", SpawnParams{.owner = OwnerId{2u}});
  for (uint64_t t = 1; t <= 60; ++t) w.step(t, looking_at_origin());
  EXPECT_EQ(w.stats().live_particles, 30u);  // 30 per second at 60 Hz: one every other tick
}

TEST(World, BudgetRefusesAndCountsCosmeticFirst) {
  ParticleWorld w(ParticleConfig{.budget = 1000}, &library());
  for (int i = 0; i < 20; ++i) w.spawn("shield", SpawnParams{.priority = 0});
  w.step(1, looking_at_origin());
  EXPECT_EQ(w.stats().live_particles, 900u);  // cosmetic particles stop at 90%
  EXPECT_EQ(w.stats().refused_particles, 1100u);
  for (int i = 0; i < 5; ++i) w.spawn("shield", SpawnParams{.priority = 1});
  w.step(2, looking_at_origin());
  EXPECT_EQ(w.stats().live_particles, 1000u);
  EXPECT_EQ(w.stats().refused_particles, 1100u + 400u);
}

// Every effect spawned again and again for five seconds: each live cluster's pool takes its room
// from the world's store (none from the heap), the store hands out no less than the live
// particles, and once every cluster has ended (and the step released it) all room is back.
TEST(World, EveryPoolTakesItsRoomFromTheStoreAndGivesItBack) {
  ParticleWorld w(ParticleConfig{.seed = 6, .budget = 60000}, &library());
  std::vector<EffectHandle> handles;
  for (uint64_t t = 1; t <= 300; ++t) {
    if (t % 30 == 1)
      for (const std::string& e : all_effects()) handles.push_back(w.spawn(e, SpawnParams{.position = {double(t % 7), 0, 0}}));
    w.step(t, looking_at_origin());
    const ParticleStats st = w.stats();
    ASSERT_EQ(st.pools_on_heap, 0u) << "tick " << t;
    ASSERT_GE(st.store_in_use, st.live_particles) << "tick " << t;
    ASSERT_LE(st.store_in_use, st.store_capacity) << "tick " << t;
  }
  EXPECT_GT(w.stats().live_particles, 1000u);
  EXPECT_GE(w.stats().store_capacity, 60000u);
  for (const EffectHandle& h : handles) w.destroy(h);
  w.step(301, looking_at_origin());
  EXPECT_EQ(w.stats().live_clusters, 0u);
  EXPECT_EQ(w.stats().store_in_use, 0u);
}

TEST(World, OutputIsCameraRelativeAndIndependentOfWorldOffset) {
  auto run = [](glm::dvec3 offset) {
    ParticleWorld w(ParticleConfig{.seed = 4}, &library());
    w.spawn("linear", SpawnParams{.position = offset});
    ParticleCamera cam = looking_at_origin();
    cam.position += offset;
    for (uint64_t t = 1; t <= 20; ++t) w.step(t, cam);
    std::vector<ParticleInstance> out;
    w.collect(cam, out);
    return out;
  };
  const auto near = run({0, 0, 0});
  const auto far = run({1e9, -1e9, 1e9});
  ASSERT_EQ(near.size(), far.size());
  ASSERT_GT(near.size(), 0u);
  for (size_t i = 0; i < near.size(); ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(near[i].pos[k], far[i].pos[k], 1e-3);
    // Premultiplied colour: rgb ≤ alpha for white particles.
    EXPECT_NEAR(near[i].color[0], near[i].color[3], 1e-6);
    EXPECT_GE(near[i].burn, 0.0f);
    EXPECT_LE(near[i].burn, 1.0f);
    EXPECT_EQ(near[i].sprite, 3);
  }
}

TEST(World, CopyIsDeepAndStepsIdentically) {
  ParticleWorld w(ParticleConfig{.seed = 11}, &library());
  w.set_owner_transform(OwnerId{1u}, {});
  w.spawn("linear", {});
  w.spawn("shield", SpawnParams{.owner = OwnerId{1u}});
  w.spawn_lightning("beam", OwnerId{1u}, {}, {0, 0, -1});
  for (uint64_t t = 1; t <= 10; ++t) w.step(t, looking_at_origin());
  ParticleWorld copy(w);
  EXPECT_EQ(hash_of(copy), hash_of(w));
  for (uint64_t t = 11; t <= 40; ++t) {
    w.step(t, looking_at_origin());
    copy.step(t, looking_at_origin());
    ASSERT_EQ(hash_of(copy), hash_of(w)) << t;
  }
  copy.destroy_owner(OwnerId{1u});
  copy.step(41, looking_at_origin());
  w.step(41, looking_at_origin());
  EXPECT_NE(hash_of(copy), hash_of(w));
  EXPECT_EQ(w.stats().live_clusters, 3u);
}

TEST(World, HashCoversParticleAttributesAndClusterState) {
  ParticleWorld a(ParticleConfig{.seed = 1}, &library());
  ParticleWorld b(ParticleConfig{.seed = 2}, &library());
  a.spawn("linear", {});
  b.spawn("linear", {});
  a.step(1, looking_at_origin());
  b.step(1, looking_at_origin());
  EXPECT_NE(hash_of(a), hash_of(b));  // same counts, different random attributes
  ParticleWorld c(ParticleConfig{.seed = 1}, &library());
  EffectHandle e = c.spawn("linear", {});
  c.step(1, looking_at_origin());
  EXPECT_EQ(hash_of(a), hash_of(c));
  c.set_intensity(e.clusters[0], 0.5);
  EXPECT_NE(hash_of(a), hash_of(c));
}

TEST(World, ShieldFlashBrightensNearTheImpactAndFades) {
  ParticleWorld w(ParticleConfig{}, &library());
  w.set_owner_transform(OwnerId{1u}, {});
  EffectHandle s = w.spawn("shield", SpawnParams{.owner = OwnerId{1u}, .intensity = 0.2});
  w.step(1, looking_at_origin());
  std::vector<ParticleInstance> calm, lit, later;
  w.collect(looking_at_origin(), calm);
  w.flash(s.clusters[0], {0, 0, 10}, 0.5);
  w.collect(looking_at_origin(), lit);
  ASSERT_EQ(calm.size(), lit.size());
  float gain_near = 0, gain_far = 0;
  for (size_t i = 0; i < lit.size(); ++i) {
    const float g = lit[i].color[3] / calm[i].color[3];
    if (lit[i].pos[2] + 100 > 8) gain_near = std::max(gain_near, g);
    if (lit[i].pos[2] + 100 < -5) gain_far = std::max(gain_far, g);
  }
  EXPECT_GT(gain_near, 2.0f);
  EXPECT_FLOAT_EQ(gain_far, 1.0f);
  for (uint64_t t = 2; t <= 40; ++t) w.step(t, looking_at_origin());
  w.collect(looking_at_origin(), later);
  for (size_t i = 0; i < later.size(); ++i) EXPECT_FLOAT_EQ(later[i].color[3], calm[i].color[3]);
}

TEST(World, UnknownEffectIsInputError) {
  ParticleWorld w(ParticleConfig{}, &library());
  EXPECT_THROW(w.spawn("nope", {}), InputError);
  EXPECT_THROW(w.spawn_lightning("linear", OwnerId{1u}, {}, {0, 0, -1}), InputError);
}

}  // namespace

TEST(World, ReleasingAnOwnerLetsItsWorldSpaceTrailFadeAndDropsTheRest) {
  ParticleWorld w(ParticleConfig{}, &library());
  w.set_owner_transform(OwnerId{9u}, {{500, 0, 0}, glm::dquat(1, 0, 0, 0), {}});
  EffectHandle trail = w.spawn("linear", SpawnParams{.owner = OwnerId{9u}});
  EffectHandle shield = w.spawn("shield", SpawnParams{.owner = OwnerId{9u}});
  for (uint64_t t = 1; t <= 10; ++t) w.step(t, looking_at_origin());
  const uint32_t before = w.stats().live_particles;
  w.release_owner(OwnerId{9u});
  EXPECT_FALSE(w.alive(shield.clusters[0]));  // it moved with the owner: gone with it
  ASSERT_TRUE(w.alive(trail.clusters[0]));    // world-space smoke stays and fades
  uint32_t last = w.stats().live_particles;
  EXPECT_LT(last, before);
  for (uint64_t t = 11; t <= 200; ++t) {
    w.step(t, looking_at_origin());
    EXPECT_LE(w.stats().live_particles, last) << "tick " << t << ": no new particles after release";
    last = w.stats().live_particles;
  }
  EXPECT_FALSE(w.alive(trail.clusters[0]));  // empty and not emitting: released
  EXPECT_EQ(w.stats().live_particles, 0u);
}

// A channel spawned as a free effect (a level effect with repeat_ticks) has nobody to end it:
// it lives its "free_lifetime" (2 s by default); a channel on an owner lives until destroyed.
TEST(World, AFreeLightningChannelEndsAfterItsFreeLifetime) {
  ParticleWorld w(ParticleConfig{.seed = 5}, &library());
  w.set_owner_transform(OwnerId{1u}, OwnerTransform{});
  const EffectHandle free_bolt = w.spawn("beam", SpawnParams{});
  const ClusterHandle held = w.spawn_lightning("beam", OwnerId{1u}, {0, 0, 0}, {0, 0, -1});
  for (uint64_t t = 1; t <= 120; ++t) w.step(t, looking_at_origin());
  EXPECT_TRUE(w.alive(free_bolt.clusters.at(0)));
  w.step(121, looking_at_origin());  // 120 ticks (2 s) after its first
  EXPECT_FALSE(w.alive(free_bolt.clusters.at(0)));
  for (uint64_t t = 122; t <= 1200; ++t) w.step(t, looking_at_origin());
  EXPECT_TRUE(w.alive(held));
  EXPECT_EQ(w.stats().live_clusters, 1u);
}

}  // namespace arc
