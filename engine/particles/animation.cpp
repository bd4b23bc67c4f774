#include "particles/animation.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"

namespace arc {

double drag_g(double k, double t) {
  if (k * t < 1e-4) return t - 0.5 * k * t * t + k * k * t * t * t / 6.0;
  return -std::expm1(-k * t) / k;
}

double drag_f(double k, double t) {
  const double kt = k * t;
  // Below this, t − g(t) loses digits to cancellation; the series has all of them.
  if (kt < 1e-3) return t * t * (0.5 - kt / 6.0 + kt * kt / 24.0 - kt * kt * kt / 120.0);
  return (t - drag_g(k, t)) / k;
}

double drag_velocity_factor(double k, double t) { return std::exp(-k * t); }

std::shared_ptr<const MotionTable> MotionTable::build(double drag, double tick_seconds, double max_lifetime_seconds) {
  auto t = std::make_shared<MotionTable>();
  const size_t n = size_t(std::ceil(max_lifetime_seconds / tick_seconds)) + 2;
  t->g.resize(n);
  t->f.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const double age = double(i) * tick_seconds;
    t->g[i] = float(drag_g(drag, age));
    t->f[i] = float(drag_f(drag, age));
  }
  return t;
}

double sphere_radius(const SphereDef& s, double scale, double age, double life) {
  const double r0 = s.radius * scale;
  switch (s.radius_animation) {
    case RadiusAnimation::Constant: return r0;
    case RadiusAnimation::Pulsating: return r0 * (1.0 + s.amplitude * std::sin(6.283185307179586 * s.frequency * age));
    case RadiusAnimation::Contracting: {
      const double ramp = s.ramp * life;
      const double grow = age / ramp, shrink = (life - age) / ramp;
      return r0 * std::clamp(std::min(grow, shrink), 0.0, 1.0);
    }
    case RadiusAnimation::Exploding: return r0 + s.growth * scale * age;
  }
  return r0;
}

glm::dquat sphere_rotation(const glm::dvec3& rate, double h, uint64_t n) {
  const glm::dquat step = glm::angleAxis(rate.y * h, glm::dvec3(0, 1, 0)) * glm::angleAxis(rate.x * h, glm::dvec3(1, 0, 0)) *
                          glm::angleAxis(rate.z * h, glm::dvec3(0, 0, 1));
  const glm::dvec3 v(step.x, step.y, step.z);
  const double s = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  if (s < 1e-300) return glm::dquat(1, 0, 0, 0);
  const double angle = 2.0 * std::atan2(s, step.w);
  return glm::angleAxis(angle * double(n), v / s);
}

void animate_linear(ParticlePool& pool, uint32_t now, const MotionTable& table, const glm::vec3& acc) {
  const size_t n = pool.count();
  const uint32_t* __restrict birth = pool.birth.data();
  const float* __restrict x0 = pool.p0x.data();
  const float* __restrict y0 = pool.p0y.data();
  const float* __restrict z0 = pool.p0z.data();
  const float* __restrict vx = pool.vx.data();
  const float* __restrict vy = pool.vy.data();
  const float* __restrict vz = pool.vz.data();
  const float* __restrict G = table.g.data();
  const float* __restrict F = table.f.data();
  float* __restrict px = pool.px.data();
  float* __restrict py = pool.py.data();
  float* __restrict pz = pool.pz.data();
  const uint32_t last = table.last();
  const float ax = acc.x, ay = acc.y, az = acc.z;
  for (size_t i = 0; i < n; ++i) {
    const uint32_t age = std::min(now - birth[i], last);
    const float g = G[age], f = F[age];
    px[i] = x0[i] + vx[i] * g + ax * f;
    py[i] = y0[i] + vy[i] * g + ay * f;
    pz[i] = z0[i] + vz[i] * g + az * f;
  }
}

void animate_sphere(ParticlePool& pool, float radius, const glm::mat3& m) {
  const size_t n = pool.count();
  const float* __restrict dx = pool.p0x.data();
  const float* __restrict dy = pool.p0y.data();
  const float* __restrict dz = pool.p0z.data();
  float* __restrict px = pool.px.data();
  float* __restrict py = pool.py.data();
  float* __restrict pz = pool.pz.data();
  // Radius folded into the matrix: one multiply less per component.
  const float m00 = m[0][0] * radius, m01 = m[0][1] * radius, m02 = m[0][2] * radius;
  const float m10 = m[1][0] * radius, m11 = m[1][1] * radius, m12 = m[1][2] * radius;
  const float m20 = m[2][0] * radius, m21 = m[2][1] * radius, m22 = m[2][2] * radius;
  for (size_t i = 0; i < n; ++i) {
    const float x = dx[i], y = dy[i], z = dz[i];
    px[i] = m00 * x + m10 * y + m20 * z;
    py[i] = m01 * x + m11 * y + m21 * z;
    pz[i] = m02 * x + m12 * y + m22 * z;
  }
}

void animate_sphere_stochastic(ParticlePool& pool, float radius, uint64_t seed, uint64_t stream, uint64_t tick) {
  const Rng rng{seed, stream, tick};
  for (size_t i = 0; i < pool.count(); ++i) {
    const glm::dvec3 d = rng.unit_vector(pool.uid[i]);
    pool.px[i] = float(d.x) * radius;
    pool.py[i] = float(d.y) * radius;
    pool.pz[i] = float(d.z) * radius;
  }
}

namespace {

// One curve over all particles, from the per-particle table index and fraction.
void apply_curve(size_t n, const Curve& c, const int32_t* __restrict idx, const float* __restrict frac, float scale,
                 float* __restrict out) {
  if (c.constant) {
    const float v = c.keys.front().value * scale;
    for (size_t i = 0; i < n; ++i) out[i] = v;
    return;
  }
  const float* __restrict tab = c.table.data();
  for (size_t i = 0; i < n; ++i) {
    const float a = tab[idx[i]], b = tab[idx[i] + 1];
    out[i] = (a + (b - a) * frac[i]) * scale;
  }
}

}  // namespace

void animate_attributes(ParticlePool& pool, uint32_t now, double tick_seconds, const CurveSet& curves, float intensity,
                        float cluster_life_t) {
  const size_t n = pool.count();
  // The scratch index/fraction arrays keep each curve loop simple; thread_local keeps them allocation-free.
  thread_local std::vector<int32_t> idx;
  thread_local std::vector<float> frac;
  if (idx.size() < n) idx.resize(n), frac.resize(n);
  const uint32_t* __restrict birth = pool.birth.data();
  const uint32_t* __restrict death = pool.death.data();
  int32_t* __restrict ix = idx.data();
  float* __restrict fr = frac.data();
  const float samples = float(kCurveSamples);
  for (size_t i = 0; i < n; ++i) {
    const float age = float(now - birth[i]);
    const float life = float(death[i] - birth[i]);
    const float t = death[i] == kNeverDies ? cluster_life_t : std::min(age / life, 1.0f);
    const float x = t * samples;
    const int32_t j = std::min(int32_t(x), kCurveSamples - 1);
    ix[i] = j;
    fr[i] = x - float(j);
  }
  apply_curve(n, *curves.size, ix, fr, 1.0f, pool.size.data());
  apply_curve(n, *curves.red, ix, fr, 1.0f, pool.r.data());
  apply_curve(n, *curves.green, ix, fr, 1.0f, pool.g.data());
  apply_curve(n, *curves.blue, ix, fr, 1.0f, pool.b.data());
  apply_curve(n, *curves.alpha, ix, fr, intensity, pool.a.data());
  apply_curve(n, *curves.burn, ix, fr, 1.0f, pool.burn.data());
  const float h = float(tick_seconds);
  const float* __restrict size0 = pool.size0.data();
  const float* __restrict rot0 = pool.rot0.data();
  const float* __restrict spin = pool.spin.data();
  float* __restrict size = pool.size.data();
  float* __restrict rot = pool.rotation.data();
  float* __restrict alpha = pool.a.data();
  for (size_t i = 0; i < n; ++i) {
    size[i] = size0[i] * size[i];
    rot[i] = rot0[i] + spin[i] * (float(now - birth[i]) * h);
    alpha[i] = std::min(alpha[i], 1.0f);
  }
}

}  // namespace arc
