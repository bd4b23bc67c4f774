// The overdraw budget on the CPU, no GL: the blended-area estimate, what it reduces first
// (near before far, low screen priority before high, lightning thinned not shortened), that it
// meets the budget, and that it never pops: smooth in distance and in time.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "gfx/overdraw_budget.h"
#include "scene_models.h"

namespace arc {
namespace {

using scenes::particle;

constexpr int kW = 1280, kH = 720;

OverdrawFrame frame(double time = 0.0) {
  OverdrawFrame f;
  f.tan_half_y = std::tan(0.45f);
  f.near = 0.1f;
  f.size_clamp = 0.5f;
  f.width = kW;
  f.height = kH;
  f.time_seconds = time;
  return f;
}

// Half-size in pixels of a camera-facing particle of half-width `size` at `depth`.
float half_px(float size, float depth) { return size * 0.5f * kH / (depth * std::tan(0.45f)); }

TEST(OverdrawBudget, EstimatesTheClampedQuadAreaOnScreen) {
  std::vector<ParticleInstance> ps = {particle({0, 0, -20}, 1.0f, glm::vec3(1), 1.0f, 1.0f)};
  std::vector<float> areas;
  OverdrawBudget b;
  OverdrawStats s = b.apply(ps, areas, frame(), {});
  const float h = half_px(1.0f, 20.0f);
  ASSERT_EQ(areas.size(), 1u);
  EXPECT_NEAR(areas[0], 4.0f * h * h, 1.0f);
  EXPECT_NEAR(s.estimated_layers, 4.0 * h * h / (kW * kH), 1e-6);
  // Half of it off the right edge: half the area. Past the size clamp (half the screen
  // height across): the clamped size, as particle.vert draws it.
  ps = {particle({20.0f * std::tan(0.45f) * kW / kH, 0, -20}, 1.0f, glm::vec3(1), 1.0f, 1.0f),
        particle({0, 0, -1}, 50.0f, glm::vec3(1), 1.0f, 1.0f)};
  b.reset();
  b.apply(ps, areas, frame(), {});
  EXPECT_NEAR(areas[0], 2.0f * h * h, 2.0f);
  EXPECT_NEAR(areas[1], (0.5f * kH) * (0.5f * kH), 2.0f);
}

TEST(OverdrawBudget, UnderBudgetChangesNothing) {
  std::vector<ParticleInstance> ps = {particle({0, 0, -5}, 1.0f, glm::vec3(1), 1.0f, 0.5f),
                                      particle({1, 0, -30}, 0.5f, glm::vec3(0.5f), 0.5f, 0.0f)};
  const std::vector<ParticleInstance> before = ps;
  std::vector<float> areas;
  OverdrawBudget b;
  const OverdrawStats s = b.apply(ps, areas, frame(), {.budget_layers = 4.0f});
  EXPECT_EQ(s.reduced, 0);
  EXPECT_EQ(s.cap, 0.0);
  ASSERT_EQ(ps.size(), before.size());
  for (size_t i = 0; i < ps.size(); ++i) EXPECT_EQ(std::memcmp(&ps[i], &before[i], sizeof(ParticleInstance)), 0);
}

// A crowd: 30 big faint puffs a few metres from the eye and 200 small sparks far away.
std::vector<ParticleInstance> crowd() {
  std::vector<ParticleInstance> ps;
  for (int i = 0; i < 30; ++i) ps.push_back(particle({float(i % 6) - 2.5f, float(i / 6) - 2.0f, -4.0f}, 0.9f, glm::vec3(0.3f), 0.3f, 0.0f));
  for (int i = 0; i < 200; ++i) ps.push_back(particle({float(i % 20) * 4 - 40, float(i / 20) * 2 - 10, -150.0f}, 0.3f, glm::vec3(1), 1.0f, 1.0f));
  return ps;
}

TEST(OverdrawBudget, MeetsTheBudgetByShrinkingTheNearestFirst) {
  std::vector<ParticleInstance> ps = crowd();
  const std::vector<ParticleInstance> before = ps;
  std::vector<float> areas;
  OverdrawBudget b;
  const OverdrawStats s = b.apply(ps, areas, frame(), {.budget_layers = 1.5f, .near = 40.0f});
  ASSERT_GT(s.estimated_layers, 2.5);  // the test needs a crowd over budget
  EXPECT_NEAR(s.budgeted_layers, 1.5, 0.05);
  ASSERT_EQ(ps.size(), before.size());
  double sum = 0;
  for (float a : areas) sum += a;
  EXPECT_NEAR(sum / (kW * kH), s.budgeted_layers, 1e-3);
  for (int i = 0; i < 30; ++i) EXPECT_LT(ps[size_t(i)].size, before[size_t(i)].size) << "near puff " << i;
  for (size_t i = 30; i < ps.size(); ++i) EXPECT_EQ(ps[i].size, before[i].size) << "far spark " << i;
  EXPECT_EQ(s.reduced, 30);
}

TEST(OverdrawBudget, ReducesLowPriorityBeforeHighAndThinsLightning) {
  ParticleInstance spark = particle({-2, 0, -6}, 1.2f, glm::vec3(1), 1.0f, 1.0f);
  spark.screen_priority = uint8_t(ScreenPriority::Low);
  ParticleInstance shield = spark;
  shield.pos[0] = 2;
  shield.screen_priority = uint8_t(ScreenPriority::Normal);
  ParticleInstance bolt = spark;
  bolt.pos[0] = 0;
  bolt.billboard = uint8_t(Billboard::AxisLocked);
  bolt.axis[1] = 3.0f;
  bolt.screen_priority = uint8_t(ScreenPriority::High);
  std::vector<ParticleInstance> ps = {spark, shield, bolt};
  std::vector<float> areas;
  OverdrawBudget b;
  const OverdrawStats s = b.apply(ps, areas, frame(), {.budget_layers = 0.05f});
  ASSERT_EQ(ps.size(), 3u);
  EXPECT_LT(ps[0].size, ps[1].size);  // same footprint: the spark is capped harder
  EXPECT_LT(ps[1].size, spark.size);
  EXPECT_LT(ps[0].color[3], ps[1].color[3]);  // and fades more
  // Both fade only a little: by (cap / size)^(1/4), the shrink's fourth root (fading removes no
  // pixel, so it would cost picture and buy no time).
  for (int i = 0; i < 2; ++i) {
    const float r = ps[size_t(i)].size / spark.size;
    EXPECT_NEAR(ps[size_t(i)].color[3], std::pow(r, 0.25f), 1e-5f) << "particle " << i;
  }
  EXPECT_LT(ps[2].size, bolt.size);            // the bolt is thinned ...
  EXPECT_EQ(ps[2].axis[1], bolt.axis[1]);      // ... not shortened
  EXPECT_EQ(ps[2].color[0], bolt.color[0]);    // and not faded
  EXPECT_EQ(s.reduced, 3);
}

TEST(OverdrawBudget, DropsLowPriorityParticlesShrunkToNothing) {
  std::vector<ParticleInstance> ps;
  for (int i = 0; i < 20; ++i) {
    ParticleInstance p = particle({0, 0, -0.6f}, 2.0f, glm::vec3(1), 1.0f, 1.0f);  // filling the screen
    p.screen_priority = uint8_t(i % 2 ? ScreenPriority::Low : ScreenPriority::High);
    ps.push_back(p);
  }
  std::vector<float> areas;
  OverdrawBudget b;
  const OverdrawStats s = b.apply(ps, areas, frame(), {.budget_layers = 1e-5f});
  EXPECT_EQ(s.dropped, 10);
  ASSERT_EQ(ps.size(), 10u);
  for (const ParticleInstance& p : ps) EXPECT_EQ(p.screen_priority, uint8_t(ScreenPriority::High));
  EXPECT_EQ(areas.size(), ps.size());
  // Only below 1/512 of its size: one shrunk to a few pixels stays (faded a little, not gone),
  // and a normal-priority one is never dropped.
  std::vector<ParticleInstance> few;
  for (int i = 0; i < 2; ++i) {
    ParticleInstance p = particle({float(i) - 0.5f, 0, -0.6f}, 2.0f, glm::vec3(1), 1.0f, 1.0f);
    p.screen_priority = uint8_t(i ? ScreenPriority::Normal : ScreenPriority::Low);
    few.push_back(p);
  }
  b.reset();
  const OverdrawStats s2 = b.apply(few, areas, frame(), {.budget_layers = 1e-4f});
  EXPECT_EQ(s2.dropped, 0);
  ASSERT_EQ(few.size(), 2u);
  const float r = few[0].size / (0.5f * 0.6f * std::tan(0.45f));  // of its size after particle.vert's clamp
  EXPECT_GT(r, 1.0f / 512.0f);
  EXPECT_LT(r, 0.05f);
  EXPECT_GT(few[0].color[3], 0.2f);
}

TEST(OverdrawBudget, IsSmoothInDistance) {
  // One puff flying toward the camera among a fixed crowd: its drawn size changes by small
  // steps for small steps in distance (no threshold where it snaps).
  OverdrawBudget b;
  float last = -1;
  for (int step = 0; step <= 400; ++step) {
    std::vector<ParticleInstance> ps = crowd();
    const float z = -30.0f * std::pow(2.0f / 30.0f, float(step) / 400.0f);  // 30 m to 2 m, 0.7 % a step
    ps.push_back(particle({1, 1, z}, 1.0f, glm::vec3(0.8f), 0.8f, 0.5f));
    std::vector<float> areas;
    b.reset();
    b.apply(ps, areas, frame(), {.budget_layers = 2.0f});
    const float drawn = std::min(ps.back().size, 0.5f * -z * std::tan(0.45f));  // particle.vert's size clamp
    const float px = drawn * 0.5f * kH / (-z * std::tan(0.45f));
    if (last >= 0) {
      EXPECT_LT(std::abs(px - last), 0.05f * std::max(px, last) + 1.0f) << "z " << z;
    }
    last = px;
  }
}

TEST(OverdrawBudget, IsSmoothInTime) {
  // A crowd seen whole, then the budget tightens at once (as when something else comes on
  // screen): the cap eases in over frames instead of snapping, every step shrinks a puff by a
  // bounded factor, and within half a second the budget holds.
  OverdrawBudget b;
  std::vector<float> areas;
  std::vector<ParticleInstance> ps = crowd();
  b.apply(ps, areas, frame(0.0), {.budget_layers = 6.0f});
  const float clamp = 0.5f * 4.0f * std::tan(0.45f);  // particle.vert's size clamp at 4 m
  auto drawn = [&](const ParticleInstance& p) { return std::min(p.size, clamp); };
  float last = drawn(ps[0]);
  ASSERT_EQ(last, drawn(crowd()[0]));
  OverdrawStats s;
  for (int f = 1; f <= 30; ++f) {
    ps = crowd();
    s = b.apply(ps, areas, frame(f / 60.0), {.budget_layers = 1.0f});
    EXPECT_GE(drawn(ps[0]), 0.8f * last) << "frame " << f;
    if (f == 1) {
      EXPECT_LT(drawn(ps[0]), last) << "the reduction starts in the first frame over budget";
    }
    last = drawn(ps[0]);
  }
  EXPECT_LT(last, 0.6f * clamp);
  EXPECT_NEAR(s.budgeted_layers, 1.0, 0.1);
  // A frame that stands still keeps the cap.
  ps = crowd();
  b.apply(ps, areas, frame(30 / 60.0), {.budget_layers = 6.0f});
  EXPECT_EQ(drawn(ps[0]), last);
  // The budget loosens: the puffs grow back by a bounded factor a frame, whole within 0.4 s.
  for (int f = 31; f <= 54; ++f) {
    ps = crowd();
    s = b.apply(ps, areas, frame(f / 60.0), {.budget_layers = 6.0f});
    EXPECT_LE(drawn(ps[0]), 1.16f * last) << "frame " << f;
    last = drawn(ps[0]);
  }
  EXPECT_EQ(s.reduced, 0);
  EXPECT_EQ(last, drawn(crowd()[0]));
  // A frame half a second or more away starts afresh.
  b.apply(ps, areas, frame(1.0), {.budget_layers = 1.0f});
  ps = crowd();
  s = b.apply(ps, areas, frame(2.0), {.budget_layers = 6.0f});
  EXPECT_EQ(s.reduced, 0);
}

TEST(OverdrawBudget, AGrowingExplosionIsCappedWhereItsCapBites) {
  // An explosion's puffs at 5 m grow by 10 % a frame, under the budget at first. A cap that
  // binds none of them waits at their largest threshold, so the frame they pass the budget
  // is the frame their reduction starts: the budget holds within a few frames of it, and no
  // puff ever shrinks by more than the rate limit from one frame to the next.
  auto explosion = [](int f) {
    std::vector<ParticleInstance> ps;
    const float size = 0.15f * std::pow(1.1f, float(f));
    for (int i = 0; i < 12; ++i) ps.push_back(particle({float(i % 4) - 1.5f, float(i / 4) - 1.0f, -5.0f}, size, glm::vec3(0.6f), 0.6f, 0.5f));
    return ps;
  };
  const float clamp = 0.5f * 5.0f * std::tan(0.45f);
  OverdrawBudget b;
  std::vector<float> areas;
  std::vector<float> last(12, 0.0f);
  int first_over = -1, over_after = 0;
  double worst_after = 0;
  for (int f = 0; f <= 40; ++f) {
    std::vector<ParticleInstance> ps = explosion(f);
    const OverdrawStats s = b.apply(ps, areas, frame(f / 60.0), {.budget_layers = 1.0f});
    ASSERT_EQ(ps.size(), 12u);
    if (first_over < 0 && s.estimated_layers > 1.0) first_over = f;
    if (first_over >= 0 && f >= first_over + 3) {
      worst_after = std::max(worst_after, s.budgeted_layers);
      over_after += s.budgeted_layers > 1.05;
    }
    for (size_t i = 0; i < ps.size(); ++i) {
      EXPECT_GE(std::min(ps[i].size, clamp), 0.8f * last[i]) << "puff " << i << " frame " << f;
      last[i] = std::min(ps[i].size, clamp);
    }
  }
  ASSERT_GT(first_over, 5) << "the test needs the explosion under budget at first";
  ASSERT_LT(first_over, 30);
  EXPECT_EQ(over_after, 0) << "worst " << worst_after << " layers from three frames after the first over budget";
}

TEST(OverdrawBudget, ANewClusterStartsAtTheFramesSolution) {
  // A calm crowd under budget, then an explosion (a cluster not drawn before) right at the eye:
  // the explosion is capped in its first frame as a budget without history would cap it, while
  // the crowd, already on screen, eases toward its cap.
  std::vector<ParticleInstance> calm = crowd();
  for (auto& p : calm) p.cluster = 1;
  OverdrawBudget b;
  std::vector<float> areas;
  std::vector<ParticleInstance> ps = calm;
  b.apply(ps, areas, frame(0.0), {.budget_layers = 4.0f});
  ps = calm;
  for (int i = 0; i < 30; ++i) {
    ParticleInstance flash = particle({float(i % 6) - 2.5f, float(i / 6) * 0.5f - 1.0f, -3.0f}, 2.0f, glm::vec3(0.5f), 0.5f, 1.0f);
    flash.cluster = 2;
    ps.push_back(flash);
  }
  std::vector<ParticleInstance> fresh = ps;
  const OverdrawStats s = b.apply(ps, areas, frame(1 / 60.0), {.budget_layers = 4.0f});
  OverdrawBudget first;
  first.apply(fresh, areas, frame(1 / 60.0), {.budget_layers = 4.0f});
  ASSERT_GT(s.estimated_layers, 6.0);
  EXPECT_LT(ps.back().size, 2.0f) << "the explosion is capped at once";
  EXPECT_EQ(ps.back().size, fresh.back().size) << "at the frame's own solution";
  const float clamp = 0.5f * 4.0f * std::tan(0.45f);
  EXPECT_GE(std::min(ps[0].size, clamp), 0.8f * std::min(calm[0].size, clamp)) << "the crowd does not jump";
  EXPECT_GT(ps[0].size, fresh[0].size) << "the crowd eases toward its cap";
}

}  // namespace
}  // namespace arc
