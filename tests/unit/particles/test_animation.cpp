// Every animation type against its closed form; exact drag against the analytic solution.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "particles/animation.h"
#include "core/rng.h"
#include "particles/curves.h"

namespace arc {
namespace {

// Analytic motion under drag k and constant acceleration a, evaluated in long double.
// Independent of the code under test: Taylor series in long double for small k·t (where the
// textbook form cancels), the textbook form otherwise.
long double exact_x(long double x0, long double v0, long double a, long double k, long double t) {
  if (k * t < 0.5L) {
    long double g = 0, f = 0, term = t;  // term = (−k)^(n−1) tⁿ / n!
    for (int n = 1; n < 40; ++n) {
      g += term;
      f += term * t / (n + 1);
      term *= -k * t / (n + 1);
    }
    return x0 + v0 * g + a * f;
  }
  return x0 + (a / k) * t + (v0 - a / k) * (1 - std::exp(-k * t)) / k;
}

TEST(Drag, ClosedFormMatchesAnalyticForKdtFrom0To100) {
  const double h = 1.0 / 60.0;
  for (double kdt : {0.0, 1e-9, 1e-5, 1e-3, 0.1, 0.5, 1.0, 2.0, 3.0, 10.0, 50.0, 100.0}) {
    const double k = kdt / h;
    for (int n : {0, 1, 2, 7, 60, 600}) {
      const double t = n * h;
      const double x = 3.0 + 20.0 * drag_g(k, t) + (-9.0) * drag_f(k, t);
      const long double want = exact_x(3.0L, 20.0L, -9.0L, k, t);
      EXPECT_NEAR(x, double(want), 1e-9 * (1.0 + std::fabs(double(want)))) << "k*dt=" << kdt << " n=" << n;
      EXPECT_TRUE(std::isfinite(x));
    }
  }
}

TEST(Drag, StepFormulaNeverFlipsOrDivergesAndMatchesClosedForm) {
  // DESIGN.md per-step formula iterated must agree with the closed form for any k·dt (Euler would flip at k·h > 1).
  const double h = 1.0 / 60.0;
  for (double kdt : {0.0, 0.5, 1.5, 2.5, 100.0}) {
    const double k = kdt / h;
    const double a = 4.0;
    double x = 0.0, v = 10.0;
    for (int i = 0; i < 120; ++i) {
      if (k == 0) {
        x += v * h + 0.5 * a * h * h;
        v += a * h;
      } else {
        const double ak = a / k;
        x = x + ak * h - (v - ak) * std::expm1(-k * h) / k;
        v = ak + (v - ak) * std::exp(-k * h);
      }
      if (k > 0) {
        EXPECT_GE(v, std::min(10.0, a / k) - 1e-9);
      }
    }
    const double t = 120 * h;
    EXPECT_NEAR(x, 10.0 * drag_g(k, t) + a * drag_f(k, t), 1e-9 * (1 + std::fabs(x))) << kdt;
    EXPECT_NEAR(v, 10.0 * drag_velocity_factor(k, t) + a * drag_g(k, t), 1e-9 * (1 + std::fabs(v))) << kdt;
  }
}

TEST(Linear, KernelMatchesClosedFormPerParticleAge) {
  const double h = 1.0 / 60.0, k = 2.0;
  auto table = MotionTable::build(k, h, 3.0);
  ParticlePool p;
  p.resize(4);
  const float v[4] = {0.0f, 5.0f, -12.0f, 40.0f};
  for (int i = 0; i < 4; ++i) {
    p.p0x[i] = float(i);
    p.vx[i] = v[i];
    p.vy[i] = 1.0f;
    p.birth[i] = uint32_t(i * 10);
  }
  const glm::vec3 acc(0.0f, -3.0f, 1.0f);
  animate_linear(p, 100, *table, acc);
  for (int i = 0; i < 4; ++i) {
    const double t = (100 - i * 10) * h;
    EXPECT_NEAR(p.px[i], double(exact_x(i, v[i], 0.0L, k, t)), 1e-4) << i;
    EXPECT_NEAR(p.py[i], double(exact_x(0, 1, -3.0L, k, t)), 1e-4) << i;
    EXPECT_NEAR(p.pz[i], double(exact_x(0, 0, 1.0L, k, t)), 1e-4) << i;
  }
}

TEST(Sphere, StaticAndRotationalStayOnTheSphereAndRotateAsClosedForm) {
  const double h = 1.0 / 60.0;
  const glm::dvec3 rate(0.3, 1.1, -0.7);
  // The per-tick rotation applied n times equals the closed form after n ticks.
  const glm::dquat step = sphere_rotation(rate, h, 1);
  glm::dquat acc(1, 0, 0, 0);
  for (int n = 1; n <= 500; ++n) {
    acc = step * acc;
    if (n % 50 == 0) {
      const glm::dquat q = sphere_rotation(rate, h, uint64_t(n));
      const glm::dvec3 a = acc * glm::dvec3(1, 2, 3), b = q * glm::dvec3(1, 2, 3);
      EXPECT_NEAR(glm::length(a - b), 0.0, 1e-9) << n;
    }
  }
  EXPECT_EQ(sphere_rotation(glm::dvec3(0.0), h, 77), glm::dquat(1, 0, 0, 0));

  ParticlePool p;
  p.resize(3);
  const glm::vec3 dirs[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0.6f, 0.8f}};
  for (int i = 0; i < 3; ++i) p.p0x[i] = dirs[i].x, p.p0y[i] = dirs[i].y, p.p0z[i] = dirs[i].z;
  const glm::dquat q = sphere_rotation(rate, h, 90);
  animate_sphere(p, 7.5f, glm::mat3(glm::mat3_cast(q)));
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 want = q * glm::dvec3(dirs[i]) * 7.5;
    EXPECT_NEAR(p.px[i], want.x, 1e-5);
    EXPECT_NEAR(p.py[i], want.y, 1e-5);
    EXPECT_NEAR(p.pz[i], want.z, 1e-5);
  }
}

TEST(Sphere, StochasticRedrawsEveryTickOnTheSphereAndIsKeyed) {
  ParticlePool p;
  p.resize(50);
  for (uint32_t i = 0; i < 50; ++i) p.uid[i] = i;
  animate_sphere_stochastic(p, 3.0f, 9, 4, 100);
  const std::vector<float> first(p.px.begin(), p.px.end());
  for (size_t i = 0; i < 50; ++i)
    EXPECT_NEAR(std::sqrt(p.px[i] * p.px[i] + p.py[i] * p.py[i] + p.pz[i] * p.pz[i]), 3.0, 1e-5);
  animate_sphere_stochastic(p, 3.0f, 9, 4, 101);
  int moved = 0;
  for (size_t i = 0; i < 50; ++i) moved += p.px[i] != first[i];
  EXPECT_GT(moved, 45);
  animate_sphere_stochastic(p, 3.0f, 9, 4, 100);
  EXPECT_EQ(std::vector<float>(p.px.begin(), p.px.end()), first);
}

TEST(Sphere, RadiusAnimationsFollowTheirClosedForms) {
  SphereDef s;
  s.radius = 10.0;
  EXPECT_DOUBLE_EQ(sphere_radius(s, 2.0, 5.0, 0.0), 20.0);

  s.radius_animation = RadiusAnimation::Pulsating;
  s.amplitude = 0.2;
  s.frequency = 0.5;
  for (double t : {0.0, 0.25, 0.5, 1.0, 1.7})
    EXPECT_NEAR(sphere_radius(s, 1.0, t, 0.0), 10.0 * (1.0 + 0.2 * std::sin(2 * M_PI * 0.5 * t)), 1e-12);

  s.radius_animation = RadiusAnimation::Contracting;
  s.ramp = 0.25;  // grows over the first quarter of a 2 s life, shrinks over the last
  EXPECT_DOUBLE_EQ(sphere_radius(s, 1.0, 0.0, 2.0), 0.0);
  EXPECT_NEAR(sphere_radius(s, 1.0, 0.25, 2.0), 5.0, 1e-12);
  EXPECT_DOUBLE_EQ(sphere_radius(s, 1.0, 0.5, 2.0), 10.0);
  EXPECT_DOUBLE_EQ(sphere_radius(s, 1.0, 1.0, 2.0), 10.0);
  EXPECT_NEAR(sphere_radius(s, 1.0, 1.75, 2.0), 5.0, 1e-12);
  EXPECT_DOUBLE_EQ(sphere_radius(s, 1.0, 2.0, 2.0), 0.0);

  s.radius_animation = RadiusAnimation::Exploding;
  s.growth = 30.0;
  for (double t : {0.0, 0.1, 1.0, 3.0}) EXPECT_DOUBLE_EQ(sphere_radius(s, 1.0, t, 1.0), 10.0 + 30.0 * t);
  EXPECT_DOUBLE_EQ(sphere_radius(s, 0.5, 1.0, 1.0), 5.0 + 15.0);
}

TEST(Curves, ExactAndTableAgree) {
  Curve c = Curve::from_keys({{0.0f, 1.0f}, {0.45f, 0.25f}, {0.7f, 0.0f}});
  EXPECT_FALSE(c.constant);
  EXPECT_FLOAT_EQ(c.exact(0.0f), 1.0f);
  EXPECT_FLOAT_EQ(c.exact(0.45f), 0.25f);
  EXPECT_FLOAT_EQ(c.exact(0.9f), 0.0f);
  EXPECT_NEAR(c.exact(0.225f), 0.625f, 1e-6);
  for (int i = 0; i <= kCurveSamples; ++i) EXPECT_FLOAT_EQ(c.table[size_t(i)], c.exact(float(i) / kCurveSamples));
  // The ramp-sum form used by the update kernel is the same piecewise-linear curve.
  for (int i = 0; i <= 1000; ++i) EXPECT_NEAR(c.ramp_value(i / 1000.0f), c.exact(i / 1000.0f), 1e-6) << i;
  EXPECT_TRUE(Curve::flat(0.3f).constant);
  EXPECT_TRUE(Curve::flat(0.3f).ramps.empty());
}

TEST(Attributes, BurnCurveTurnsFireIntoSmokeAndAlphaScalesWithIntensity) {
  Curve size = Curve::from_keys({{0, 1}, {1, 3}});
  Curve one = Curve::flat(1.0f);
  Curve alpha = Curve::from_keys({{0, 1}, {1, 0}});
  Curve burn = Curve::from_keys({{0, 1}, {0.5f, 0}});
  ParticlePool p;
  p.resize(3);
  for (int i = 0; i < 3; ++i) p.birth[i] = 0, p.death[i] = 100, p.size0[i] = 2.0f, p.spin[i] = 1.0f;
  p.birth[1] = 50;  // half as old as particle 0 at tick 100... and still younger
  p.death[1] = 150;
  p.death[2] = kNeverDies;
  animate_attributes(p, 50, 0.01, CurveSet{&size, &one, &one, &one, &alpha, &burn}, 0.5f, 0.25f);
  EXPECT_NEAR(p.size[0], 2.0f * 2.0f, 1e-5);   // t = 0.5
  EXPECT_NEAR(p.burn[0], 0.0f, 1e-6);
  EXPECT_NEAR(p.a[0], 0.5f * 0.5f, 1e-6);
  EXPECT_NEAR(p.burn[1], 1.0f, 1e-6);          // just born
  EXPECT_NEAR(p.rotation[0], 0.5f, 1e-6);      // 50 ticks · 0.01 s · 1 rad/s
  EXPECT_NEAR(p.burn[2], 0.5f, 1e-6);          // cluster-long life: the cluster's t = 0.25
}

// The attribute kernel against the ramp-sum form written out here, bit for bit: every path of
// the kernel (SIMD groups, unrolled ramp counts 0..4, the generic loop beyond, block tails, the
// scalar redo of a wrapped tick difference) must give exactly these values.
float ref_clamp01(float x) {
  x = x > 0.0f ? x : 0.0f;
  return x < 1.0f ? x : 1.0f;
}
float ref_curve(const Curve& c, float t) {
  float v = c.start;
  for (const CurveRamp& r : c.ramps) v += r.delta * ref_clamp01((t - r.t0) * r.inv_width);
  return v;
}

TEST(Attributes, KernelEqualsTheRampSumFormBitForBit) {
  const Rng rng{11, 12, 13};
  uint64_t k = 0;
  auto u = [&] { return float(rng.uniform(k++)); };
  // Six curves per round, with 1..9 keys: 0..8 ramps, some steps (equal t), some flat segments.
  auto random_curve = [&](int keys) {
    std::vector<CurveKey> v;
    float t = 0.0f;
    for (int i = 0; i < keys; ++i) {
      if (i > 0 && u() > 0.2f) t = std::min(1.0f, t + u() * 0.5f);
      const float value = u() < 0.15f && !v.empty() ? v.back().value : (u() - 0.3f) * 4.0f;
      v.push_back({t, value});
    }
    if (u() < 0.2f) v.front().value = -0.0f;
    return Curve::from_keys(v);
  };
  const uint32_t now = 1000;
  for (int round = 0; round < 40; ++round) {
    Curve c[6];
    for (int i = 0; i < 6; ++i) c[i] = random_curve(1 + (round + i) % 9);
    const CurveSet cs{&c[0], &c[1], &c[2], &c[3], &c[4], &c[5]};
    const size_t n = 1 + size_t(round) * 37;  // block tails and group tails of every length
    ParticlePool p;
    p.resize(n);
    for (size_t i = 0; i < n; ++i) {
      p.birth[i] = uint32_t(u() * 1000.0f);
      p.death[i] = p.birth[i] + uint32_t(u() * 300.0f);
      const float pick = u();
      if (pick < 0.1f) p.death[i] = kNeverDies;
      else if (pick < 0.15f) p.death[i] = p.birth[i];             // zero life
      else if (pick < 0.18f) p.birth[i] = now + 1 + uint32_t(u() * 5.0f);  // born after now: the age wraps
      else if (pick < 0.20f) p.death[i] = p.birth[i] + 0x80000001u;  // a life beyond 2^31 ticks
      p.size0[i] = u() * 3.0f;
      p.rot0[i] = u() * 6.0f;
      p.spin[i] = u() * 4.0f - 2.0f;
    }
    const float intensity = round % 3 == 0 ? 1.0f : u() * 3.0f;
    const float cluster_t = round % 4 == 0 ? -0.0f : u();
    const double h = 1.0 / 60.0;
    animate_attributes(p, now, h, cs, intensity, cluster_t);
    for (size_t i = 0; i < n; ++i) {
      const float age = float(now - p.birth[i]);
      const float life = float(p.death[i] - p.birth[i]);
      float q = age / life;
      q = q < 1.0f ? q : 1.0f;
      const float t = p.death[i] == kNeverDies ? cluster_t : q;
      const float a = ref_curve(c[4], t) * intensity;
      const float want[7] = {ref_curve(c[0], t) * p.size0[i], ref_curve(c[1], t), ref_curve(c[2], t), ref_curve(c[3], t),
                             a < 1.0f ? a : 1.0f, ref_curve(c[5], t), p.rot0[i] + p.spin[i] * (age * float(h))};
      const float got[7] = {p.size[i], p.r[i], p.g[i], p.b[i], p.a[i], p.burn[i], p.rotation[i]};
      for (int j = 0; j < 7; ++j)
        ASSERT_EQ(std::bit_cast<uint32_t>(got[j]), std::bit_cast<uint32_t>(want[j]))
            << "round " << round << " particle " << i << " attribute " << j << ": " << got[j] << " != " << want[j];
    }
  }
}

}  // namespace
}  // namespace arc
