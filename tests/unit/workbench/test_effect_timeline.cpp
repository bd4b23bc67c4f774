// The workbench's time controls: scrubbing to a tick by the catch-up path gives the state that
// playing to it gives, for every effect of the game, forwards and backwards.
#include <gtest/gtest.h>

#include <filesystem>

#include "game/workbench/effect_timeline.h"
#include "core/data_root.h"

namespace arc {
namespace {

ParticleCamera stage_camera() {
  ParticleCamera c;
  c.position = {0.0, 6.0, 45.0};
  return c;
}

std::shared_ptr<const EffectLibrary> game_effects() {
  auto fx = std::make_shared<EffectLibrary>();
  fx->load_directory(arc::data_root() + "/assets/effects");
  return fx;
}

// Plays an effect tick by tick and checks, at several ticks over its life, that a fresh timeline
// scrubbed straight there has the same state hash; then scrubs backwards on the played one.
void expect_scrub_equals_play(const std::shared_ptr<const EffectLibrary>& fx, const std::string& name, StageMotion motion) {
  const ParticleCamera cam = stage_camera();
  StageOptions stage;
  stage.motion = motion;
  EffectTimeline played(fx, name, stage);
  const uint64_t last = uint64_t(played.life_seconds() * 60.0) + 2;
  std::vector<uint64_t> hashes{played.state_hash(cam)};
  size_t checked = 0, drawn_somewhere = 0;
  for (uint64_t t = 1; t <= last; ++t) {
    played.play_step(cam);
    hashes.push_back(played.state_hash(cam));
    if (t % 7 != 0 && t != last) continue;
    EffectTimeline scrubbed(fx, name, stage);
    scrubbed.scrub_to(t, cam);
    ASSERT_EQ(scrubbed.tick(), t);
    EXPECT_EQ(scrubbed.state_hash(cam), hashes[t]) << name << " tick " << t;
    drawn_somewhere += played.frame_stats().live_particles > 0;
    ++checked;
  }
  for (uint64_t t : {last / 2, last / 3, uint64_t(1)}) {
    played.scrub_to(t, cam);
    EXPECT_EQ(played.state_hash(cam), hashes[t]) << name << " back to tick " << t;
  }
  EXPECT_GT(checked, 2u) << name;
  EXPECT_GT(drawn_somewhere, 0u) << name << " never had a particle";
}

TEST(EffectTimeline, ScrubbingEqualsPlayingForEveryEffectStandingStill) {
  auto fx = game_effects();
  ASSERT_GE(fx->names().size(), 8u);
  for (const std::string& name : fx->names()) expect_scrub_equals_play(fx, name, StageMotion::Still);
}

TEST(EffectTimeline, ScrubbingEqualsPlayingForEveryEffectOnACirclingOwner) {
  auto fx = game_effects();
  for (const std::string& name : fx->names()) expect_scrub_equals_play(fx, name, StageMotion::Circle);
}

TEST(EffectTimeline, TheHashSeesADifferentTick) {
  auto fx = game_effects();
  EffectTimeline a(fx, "ship_explosion"), b(fx, "ship_explosion");
  a.scrub_to(10, stage_camera());
  b.scrub_to(11, stage_camera());
  EXPECT_NE(a.state_hash(stage_camera()), b.state_hash(stage_camera()));
}

TEST(EffectTimeline, CountsParticlesPerCluster) {
  auto fx = game_effects();
  EffectTimeline t(fx, "shield_hit");
  t.scrub_to(3, stage_camera());
  const EffectCounts s = t.frame_stats();
  ASSERT_EQ(s.cluster_particles.size(), fx->get("shield_hit").clusters.size());
  uint32_t sum = 0;
  for (uint32_t n : s.cluster_particles) sum += n;
  EXPECT_EQ(sum, s.live_particles);
  EXPECT_EQ(s.cluster_particles[0], 24u);  // the flash's burst
  t.scrub_to(uint64_t(t.life_seconds() * 60.0) + 2, stage_camera());
  EXPECT_EQ(t.frame_stats().live_particles, 0u);
}

// The stage runs under the user's particle budget, as the game would: a tweaker sees what a
// small budget refuses.
TEST(EffectTimeline, RunsUnderTheGivenParticleBudget) {
  auto fx = game_effects();
  EffectTimeline full(fx, "ship_explosion");
  full.scrub_to(6, stage_camera());
  ASSERT_GT(full.frame_stats().live_particles, 100u);
  StageOptions small;
  small.particle_budget = 100;
  EffectTimeline limited(fx, "ship_explosion", small);
  limited.scrub_to(6, stage_camera());
  EXPECT_LE(limited.frame_stats().live_particles, 100u);
  EXPECT_GT(limited.world().stats().refused_particles, 0u);
}

// Scrubbing back remakes the world, but not its particle store (written through at the budget,
// 20 MiB at 200 000): the new world takes the old one's, with all its room given back.
TEST(EffectTimeline, ScrubbingBackKeepsTheParticleStore) {
  EffectTimeline t(game_effects(), "ship_explosion");
  t.scrub_to(30, stage_camera());
  const std::shared_ptr<ParticleStore> store = t.world().store();
  ASSERT_GT(t.world().stats().store_in_use, 0u);
  t.scrub_to(10, stage_camera());
  EXPECT_EQ(t.world().store(), store);
  EXPECT_EQ(t.world().stats().pools_on_heap, 0u);
  EXPECT_GT(t.world().stats().live_particles, 0u);
  EffectTimeline fresh(game_effects(), "ship_explosion");
  fresh.scrub_to(10, stage_camera());
  EXPECT_EQ(t.world().stats().store_in_use, fresh.world().stats().store_in_use) << "the old world's blocks are back";
}

TEST(EffectTimeline, LifeEndsForBurstsAndLoopsForSteadyEmitters) {
  auto fx = game_effects();
  bool ends = false;
  EXPECT_NEAR(EffectTimeline::life_seconds(fx->get("shield_hit"), &ends), 0.55, 1e-9);
  EXPECT_TRUE(ends);
  EffectTimeline::life_seconds(fx->get("engine_exhaust"), &ends);
  EXPECT_FALSE(ends);
}

TEST(EffectTimeline, ACirclingOwnerFliesAlongMinusZ) {
  auto fx = game_effects();
  StageOptions stage;
  stage.motion = StageMotion::Circle;
  EffectTimeline t(fx, "missile_trail", stage);
  t.scrub_to(30, stage_camera());
  const OwnerTransform o = t.owner_transform();
  EXPECT_NEAR(glm::length(o.position), stage.circle_radius, 1e-9);
  const glm::dvec3 forward = o.orientation * glm::dvec3(0, 0, -1);
  EXPECT_NEAR(glm::dot(forward, o.velocity / stage.circle_speed), 1.0, 1e-9);
  EXPECT_GT(t.frame_stats().cluster_particles[1], 0u);  // the smoke trail is laid along the path
}

}  // namespace
}  // namespace arc
