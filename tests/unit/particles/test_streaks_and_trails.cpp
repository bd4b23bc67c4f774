// Velocity billboards (sparks stretched along their motion) and trails emitted by distance
// travelled ("spacing").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/hash.h"
#include "particles/effect_library.h"
#include "particles/particle_world.h"

namespace arc {
namespace {

const EffectLibrary& library() {
  static EffectLibrary lib = [] {
    EffectLibrary l;
    // One spark fired along −Z at 20 m/s, stretched over 0.05 s of its motion.
    l.load_text(R"({ "clusters": [ { "sprite": "spark", "billboard": "velocity", "stretch": 0.05,
      "animation": { "type": "linear" }, "emitter": { "burst": 1, "direction": "forward" },
      "particles": { "speed": 20, "lifetime": 5, "size": 0.2, "inherit_velocity": 0 } } ] })",
                "streak.json");
    // The same with drag and gravity, and a camera-facing twin to compare positions with.
    for (const char* board : {"\"billboard\": \"velocity\", \"stretch\": 0.04,", ""})
      l.load_text(std::string(R"({ "clusters": [ { "sprite": "spark", )") + board + R"(
        "animation": { "type": "linear", "drag": 2, "acceleration": [0, -9.81, 0] },
        "emitter": { "shape": "cone", "angle_deg": 60, "burst": 30 },
        "particles": { "speed": [20, 90], "lifetime": 5, "size": 0.2, "inherit_velocity": 0 } } ] })",
                  std::string(*board ? "dragged_streak" : "dragged_plain") + ".json");
    // A smoke trail: one particle per 0.5 m of the emitter's path, nothing at rest.
    l.load_text(R"({ "clusters": [ { "sprite": "smoke", "animation": { "type": "linear" },
      "emitter": { "spacing": 0.5 }, "particles": { "speed": 0, "lifetime": 30, "size": 0.4, "inherit_velocity": 0 } } ] })",
                "trail.json");
    // A trail with everything that makes catch-up hard: rate and spacing, spread, drag, streaks.
    l.load_text(R"({ "clusters": [ { "sprite": "spark", "billboard": "velocity", "stretch": 0.03,
      "animation": { "type": "linear", "drag": 0.8, "acceleration": [0, -2, 0] },
      "emitter": { "shape": "sphere", "radius": 0.3, "rate": 45, "spacing": 0.7, "direction": "random" },
      "particles": { "speed": [1, 6], "lifetime": [0.5, 1.5], "size": [0.2, 0.4], "inherit_velocity": 0.1 } } ] })",
                "busy_trail.json");
    return l;
  }();
  return lib;
}

ParticleCamera camera_at(const glm::dvec3& position) {
  ParticleCamera c;
  c.position = position;
  return c;
}

std::vector<ParticleInstance> collected(const ParticleWorld& w, const ParticleCamera& camera) {
  std::vector<ParticleInstance> out;
  w.collect(camera, out);
  return out;
}

glm::dvec3 axis_of(const ParticleInstance& p) { return {p.axis[0], p.axis[1], p.axis[2]}; }

uint64_t hash_of(const ParticleWorld& w) {
  StateHasher h;
  w.hash(h);
  return h.value();
}

TEST(Streaks, AxisIsVelocityTimesStretchAndTheStreakEndsAtTheParticle) {
  ParticleWorld w(ParticleConfig{.seed = 9}, &library());
  w.spawn("streak", SpawnParams{});
  for (uint64_t t = 1; t <= 10; ++t) w.step(t, camera_at({0, 0, 100}));
  const std::vector<ParticleInstance> out = collected(w, camera_at({0, 0, 100}));
  ASSERT_EQ(out.size(), 1u);
  const ParticleInstance& p = out[0];
  EXPECT_EQ(p.billboard, uint8_t(Billboard::AxisLocked));
  EXPECT_FLOAT_EQ(p.axis[0], 0.0f);
  EXPECT_FLOAT_EQ(p.axis[1], 0.0f);
  EXPECT_FLOAT_EQ(p.axis[2], -20.0f * 0.05f);
  // Born at the origin at tick 1, 9 ticks of 20 m/s along −Z since: the streak's far end.
  const float head_z = -20.0f * 9.0f / 60.0f;
  EXPECT_NEAR(p.pos[2] + 0.5f * p.axis[2], head_z - 100.0f, 1e-4f);
  EXPECT_NEAR(p.size, 0.2f, 1e-6f);
}

TEST(Streaks, AxisFollowsDragGravityAndTheCameraVelocity) {
  ParticleWorld streaks(ParticleConfig{.seed = 4}, &library());
  ParticleWorld plain(ParticleConfig{.seed = 4}, &library());
  streaks.spawn("dragged_streak", SpawnParams{});
  plain.spawn("dragged_plain", SpawnParams{});
  const uint64_t ticks = 25;
  ParticleCamera cam = camera_at({0, 0, 150});
  for (uint64_t t = 1; t <= ticks; ++t) streaks.step(t, cam), plain.step(t, cam);
  cam.velocity = {3, -4, 12};
  const std::vector<ParticleInstance> s = collected(streaks, cam), p = collected(plain, cam);
  ASSERT_EQ(s.size(), 30u);
  ASSERT_EQ(p.size(), s.size());
  // The velocity of each particle from the finite difference of its camera-facing twin's
  // positions one tick apart, against the closed form the streak used.
  ParticleWorld plain_next = plain;
  plain_next.step(ticks + 1, cam);
  const std::vector<ParticleInstance> p2 = collected(plain_next, cam);
  const double h = 1.0 / 60.0, k = 2.0, age = double(ticks - 1) * h;
  for (size_t i = 0; i < s.size(); ++i) {
    EXPECT_EQ(p[i].billboard, uint8_t(Billboard::CameraFacing));
    const glm::dvec3 head(s[i].pos[0] + 0.5 * s[i].axis[0], s[i].pos[1] + 0.5 * s[i].axis[1], s[i].pos[2] + 0.5 * s[i].axis[2]);
    EXPECT_NEAR(glm::length(head - glm::dvec3(p[i].pos[0], p[i].pos[1], p[i].pos[2])), 0.0, 1e-4);
    const glm::dvec3 moved(p2[i].pos[0] - p[i].pos[0], p2[i].pos[1] - p[i].pos[1], p2[i].pos[2] - p[i].pos[2]);
    // Exact velocity at `age` from the displacement over the next tick: Δx = v·g(h) + a_term.
    const double g_h = -std::expm1(-k * h) / k, f_h = (h - g_h) / k;
    const glm::dvec3 gravity(0, -9.81, 0);
    const glm::dvec3 velocity = (moved - gravity * f_h) / g_h;
    const glm::dvec3 expected = (velocity - cam.velocity) * 0.04;
    EXPECT_NEAR(glm::length(axis_of(s[i]) - expected), 0.0, 2e-3 * std::max(1.0, glm::length(expected))) << i << " age " << age;
  }
}

TEST(Streaks, ASparkAtRestRelativeToTheCameraHasNoStreak) {
  ParticleWorld w(ParticleConfig{.seed = 9}, &library());
  w.spawn("streak", SpawnParams{});
  w.step(1, camera_at({0, 0, 100}));
  ParticleCamera riding_along = camera_at({0, 0, 100});
  riding_along.velocity = {0, 0, -20};  // moves with the spark: no relative motion
  const std::vector<ParticleInstance> out = collected(w, riding_along);
  ASSERT_EQ(out.size(), 1u);
  for (float a : out[0].axis) EXPECT_EQ(a, 0.0f);
  for (float q : out[0].pos) EXPECT_TRUE(std::isfinite(q));
}

// Birth positions of a trail's particles along X (they do not move: speed 0, no inheritance).
std::vector<double> trail_positions(const ParticleWorld& w, const glm::dvec3& camera) {
  std::vector<double> xs;
  for (const ParticleInstance& p : collected(w, camera_at(camera))) xs.push_back(double(p.pos[0]) + camera.x);
  std::sort(xs.begin(), xs.end());
  return xs;
}

double max_gap(const std::vector<double>& xs, double start) {
  double gap = xs.empty() ? 0.0 : xs.front() - start;
  for (size_t i = 1; i < xs.size(); ++i) gap = std::max(gap, xs[i] - xs[i - 1]);
  return gap;
}

TEST(Trails, ASpacingEmitterMovedInOneTickLaysItsParticlesAlongThePathAtAnySpeed) {
  for (double distance : {100.0, 1000.0}) {
    SCOPED_TRACE(distance);
    ParticleWorld w(ParticleConfig{.seed = 2}, &library());
    w.set_owner_transform(OwnerId{1u}, OwnerTransform{});
    w.spawn("trail", SpawnParams{.owner = OwnerId{1u}});
    w.set_owner_transform(OwnerId{1u}, OwnerTransform{.position = {distance, 0, 0}, .velocity = {distance * 60.0, 0, 0}});
    const glm::dvec3 camera(distance * 0.5, 0, distance * 1.5);
    w.step(1, camera_at(camera));
    const std::vector<double> xs = trail_positions(w, camera);
    ASSERT_EQ(xs.size(), size_t(distance / 0.5));
    EXPECT_LE(max_gap(xs, 0.0), 0.5 + 1e-3);
    EXPECT_NEAR(xs.back(), distance, 1e-3);
  }
}

TEST(Trails, SpacingCarriesAcrossTicksAndNothingIsEmittedAtRest) {
  ParticleWorld w(ParticleConfig{.seed = 2}, &library());
  w.set_owner_transform(OwnerId{1u}, OwnerTransform{});
  const EffectHandle trail = w.spawn("trail", SpawnParams{.owner = OwnerId{1u}});
  const glm::dvec3 camera(100, 0, 300);
  for (uint64_t t = 1; t <= 6; ++t) {
    w.set_owner_transform(OwnerId{1u}, OwnerTransform{.position = {37.25 * double(std::min<uint64_t>(t, 5)), 0, 0}});
    w.step(t, camera_at(camera));
  }
  const std::vector<double> xs = trail_positions(w, camera);
  ASSERT_EQ(xs.size(), 372u);  // ⌊5 · 37.25 / 0.5⌋: the sixth tick stood still
  for (size_t i = 1; i < xs.size(); ++i) EXPECT_NEAR(xs[i] - xs[i - 1], 0.5, 1e-3) << i;
  EXPECT_NEAR(xs.front(), 0.5, 1e-4);
  EXPECT_TRUE(w.alive(trail.clusters.at(0)));  // a trail at rest waits; it is not empty-and-done
}

TEST(Trails, SkippedTicksAndSnapshotsStayExact) {
  ParticleWorld a(ParticleConfig{.seed = 7}, &library());
  ParticleWorld b(ParticleConfig{.seed = 7}, &library());
  ParticleCamera looking = camera_at({0, 0, 400});
  ParticleCamera away = looking;
  away.orientation = glm::angleAxis(M_PI, glm::dvec3(0, 1, 0));
  OwnerTransform missile{.position = {-50, 0, 0}};
  for (ParticleWorld* w : {&a, &b}) {
    w->set_owner_transform(OwnerId{1u}, missile);
    w->spawn("busy_trail", SpawnParams{.owner = OwnerId{1u}});
  }
  uint32_t skipped = 0;
  std::vector<uint8_t> saved;
  for (uint64_t t = 1; t <= 90; ++t) {
    missile.velocity = {180.0 + 2.0 * double(t), 30.0 * std::sin(0.1 * double(t)), 0};
    missile.position += missile.velocity / 60.0;
    a.set_owner_transform(OwnerId{1u}, missile);
    b.set_owner_transform(OwnerId{1u}, missile);
    a.step(t, looking);
    b.step(t, t >= 20 && t < 70 ? away : looking);
    skipped += b.stats().skipped_clusters;
    if (t == 45) saved = b.save();
  }
  EXPECT_GT(skipped, 0u);
  EXPECT_GT(a.stats().live_particles, 100u);
  EXPECT_EQ(hash_of(a), hash_of(b));
  const std::vector<ParticleInstance> pa = collected(a, looking), pb = collected(b, looking);
  ASSERT_EQ(pa.size(), pb.size());
  EXPECT_EQ(std::memcmp(pa.data(), pb.data(), pa.size() * sizeof(ParticleInstance)), 0);

  // The snapshot holds the fractional distance: continuing from it gives the same trail.
  ParticleWorld c(ParticleConfig{.seed = 7}, &library());
  c.load(saved);
  missile.position = {-50, 0, 0};
  for (uint64_t t = 1; t <= 90; ++t) {
    missile.velocity = {180.0 + 2.0 * double(t), 30.0 * std::sin(0.1 * double(t)), 0};
    missile.position += missile.velocity / 60.0;
    if (t <= 45) continue;
    c.set_owner_transform(OwnerId{1u}, missile);
    c.step(t, looking);
  }
  EXPECT_EQ(hash_of(c), hash_of(a));
}

}  // namespace
}  // namespace arc
