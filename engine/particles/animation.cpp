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

namespace {

// The kernels take their arrays as restrict-qualified parameters: GCC honours restrict there
// (not on local pointers), which is what lets it vectorise without run-time alias checks.
void linear_kernel(size_t n, uint32_t now, uint32_t last, const uint32_t* __restrict birth, const float* __restrict x0,
                   const float* __restrict y0, const float* __restrict z0, const float* __restrict vx,
                   const float* __restrict vy, const float* __restrict vz, const float* __restrict G,
                   const float* __restrict F, float ax, float ay, float az, float* __restrict px, float* __restrict py,
                   float* __restrict pz) {
  for (size_t i = 0; i < n; ++i) {
    const uint32_t age = std::min(now - birth[i], last);
    const float g = G[age], f = F[age];
    px[i] = x0[i] + vx[i] * g + ax * f;
    py[i] = y0[i] + vy[i] * g + ay * f;
    pz[i] = z0[i] + vz[i] * g + az * f;
  }
}

void sphere_kernel(size_t n, const float* __restrict dx, const float* __restrict dy, const float* __restrict dz,
                   const float* __restrict m, float* __restrict px, float* __restrict py, float* __restrict pz) {
  const float m00 = m[0], m01 = m[1], m02 = m[2], m10 = m[3], m11 = m[4], m12 = m[5], m20 = m[6], m21 = m[7], m22 = m[8];
  for (size_t i = 0; i < n; ++i) {
    const float x = dx[i], y = dy[i], z = dz[i];
    px[i] = m00 * x + m10 * y + m20 * z;
    py[i] = m01 * x + m11 * y + m21 * z;
    pz[i] = m02 * x + m12 * y + m22 * z;
  }
}

}  // namespace

void animate_linear(ParticlePool& pool, uint32_t now, const MotionTable& table, const glm::vec3& acc) {
  linear_kernel(pool.count(), now, table.last(), pool.birth.data(), pool.p0x.data(), pool.p0y.data(), pool.p0z.data(),
                pool.vx.data(), pool.vy.data(), pool.vz.data(), table.g.data(), table.f.data(), acc.x, acc.y, acc.z,
                pool.px.data(), pool.py.data(), pool.pz.data());
}

void animate_sphere(ParticlePool& pool, float radius, const glm::mat3& m) {
  // Radius folded into the matrix: one multiply less per component.
  float mr[9];
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) mr[c * 3 + r] = m[c][r] * radius;
  sphere_kernel(pool.count(), pool.p0x.data(), pool.p0y.data(), pool.p0z.data(), mr, pool.px.data(), pool.py.data(),
                pool.pz.data());
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

// Particles are processed in blocks whose normalised ages and curve values stay in L1 between
// the passes; each pass is a plain loop the compiler vectorises (restrict parameters).
constexpr size_t kBlock = 512;

void life_fraction(size_t n, uint32_t now, float cluster_life_t, const uint32_t* __restrict birth,
                   const uint32_t* __restrict death, float* __restrict t) {
  for (size_t i = 0; i < n; ++i) {
    const float age = float(now - birth[i]);
    const float life = float(death[i] - birth[i]);
    // Divide unconditionally: a division inside the select would block if-conversion (trapping math).
    float q = age / life;
    q = q < 1.0f ? q : 1.0f;
    t[i] = death[i] == kNeverDies ? cluster_life_t : q;
  }
}

// The comparisons are written in the exact form of SSE max/min (x > 0 ? x : 0), so they map to
// maxps/minps without -ffast-math.
void add_ramp(size_t n, float t0, float k, float d, const float* __restrict t, float* __restrict out) {
  for (size_t i = 0; i < n; ++i) {
    float x = (t[i] - t0) * k;
    x = x > 0.0f ? x : 0.0f;
    x = x < 1.0f ? x : 1.0f;
    out[i] += d * x;
  }
}

void curve_values(size_t n, const Curve& c, const float* __restrict t, float* __restrict out) {
  const float start = c.start;
  for (size_t i = 0; i < n; ++i) out[i] = start;
  for (const CurveRamp& r : c.ramps) add_ramp(n, r.t0, r.inv_width, r.delta, t, out);
}

void scale_clamped(size_t n, float s, float* __restrict v) {
  for (size_t i = 0; i < n; ++i) {
    const float x = v[i] * s;
    v[i] = x < 1.0f ? x : 1.0f;
  }
}

void multiply(size_t n, const float* __restrict a, float* __restrict v) {
  for (size_t i = 0; i < n; ++i) v[i] *= a[i];
}

void spin_rotation(size_t n, uint32_t now, float h, const uint32_t* __restrict birth, const float* __restrict rot0,
                   const float* __restrict spin, float* __restrict rot) {
  for (size_t i = 0; i < n; ++i) rot[i] = rot0[i] + spin[i] * (float(now - birth[i]) * h);
}

}  // namespace

void animate_attributes(ParticlePool& pool, uint32_t now, double tick_seconds, const CurveSet& curves, float intensity,
                        float cluster_life_t) {
  const size_t n = pool.count();
  const float h = float(tick_seconds);
  float t[kBlock];
  for (size_t base = 0; base < n; base += kBlock) {
    const size_t m = std::min(kBlock, n - base);
    life_fraction(m, now, cluster_life_t, pool.birth.data() + base, pool.death.data() + base, t);
    curve_values(m, *curves.size, t, pool.size.data() + base);
    multiply(m, pool.size0.data() + base, pool.size.data() + base);
    curve_values(m, *curves.red, t, pool.r.data() + base);
    curve_values(m, *curves.green, t, pool.g.data() + base);
    curve_values(m, *curves.blue, t, pool.b.data() + base);
    curve_values(m, *curves.alpha, t, pool.a.data() + base);
    scale_clamped(m, intensity, pool.a.data() + base);
    curve_values(m, *curves.burn, t, pool.burn.data() + base);
    spin_rotation(m, now, h, pool.birth.data() + base, pool.rot0.data() + base, pool.spin.data() + base,
                  pool.rotation.data() + base);
  }
}

}  // namespace arc
