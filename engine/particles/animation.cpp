#include "particles/animation.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

// ---- attributes ------------------------------------------------------------------------------
//
// Particles go in blocks of kBlock. One pass over a block computes each particle's life fraction
// t (kept in an L1 array) and its rotation; then one pass per curve evaluates all of that curve's
// ramps with the running sum in a register (ramp count a template parameter up to 4, so the
// ramps unroll with their constants in registers) and writes the attribute once. The arithmetic
// and its order are fixed, so every value is bit for bit the same whichever path computes it
// (SSE2 four at a time, or the scalar form for a block's tail, a wrapped tick difference, or a
// target without SSE2), and the same as the per-array passes this replaced:
//   age  = float(now − birth), life = float(death − birth)            (unsigned conversions)
//   t    = death == kNeverDies ? cluster_life_t : (age / life < 1 ? age / life : 1)
//   v    = start; for each ramp in order: x = (t − t0) · inv_width; x = x > 0 ? x : 0;
//          x = x < 1 ? x : 1; v += delta · x
//   size = v_size · size0;  a = (v_alpha · intensity < 1 ? v_alpha · intensity : 1)
//   rotation = rot0 + spin · (age · h)
// The clamps are written in the exact semantics of SSE maxps/minps (x > 0 ? x : 0 gives 0 for
// NaN and for −0), which is what the intrinsics compute. Intrinsics rather than auto-vectorised
// loops: without -ffast-math GCC rewrites `delta · clamp(x)` into compare-and-blend chains (it
// sinks the multiply into the selects), about twice the instructions of max, min, mul.
//
// Memory per particle: reads birth, death, size0, rot0, spin (5 × 4 B), writes rotation, size,
// r, g, b, a, burn (7 × 4 B): 48 B. The curve constants and the block's t array stay in L1.

enum Attr { kSize, kRed, kGreen, kBlue, kAlpha, kBurn, kAttrs };

inline float clamp01(float x) {
  x = x > 0.0f ? x : 0.0f;
  return x < 1.0f ? x : 1.0f;
}

inline float curve_scalar(const Curve& c, float t) {
  float v = c.start;
  for (const CurveRamp& r : c.ramps) v += r.delta * clamp01((t - r.t0) * r.inv_width);
  return v;
}

struct AttributeArrays {
  const uint32_t* __restrict birth;
  const uint32_t* __restrict death;
  const float* __restrict size0;
  const float* __restrict rot0;
  const float* __restrict spin;
  float* __restrict out[kAttrs];
  float* __restrict rotation;
};

// Life fraction of particle i by the scalar form (exact for every uint32 difference); also
// writes its rotation.
inline float life_scalar(const AttributeArrays& p, size_t i, uint32_t now, float h, float cluster_life_t) {
  const float age = float(now - p.birth[i]);
  const float life = float(p.death[i] - p.birth[i]);
  float q = age / life;
  q = q < 1.0f ? q : 1.0f;
  p.rotation[i] = p.rot0[i] + p.spin[i] * (age * h);
  return p.death[i] == kNeverDies ? cluster_life_t : q;
}

#if defined(__SSE2__)

constexpr size_t kBlock = 128;  // particles per block: its t values (512 B) stay in L1 between the passes

// Life fraction and rotation of particles [i0, i0 + m); t[j] gets particle i0 + j's t.
void life_fraction_sse(const AttributeArrays& p, size_t i0, size_t m, uint32_t now, float hs, float cluster_life_t,
                       float* __restrict t) {
  const __m128i nowv = _mm_set1_epi32(int32_t(now)), never = _mm_set1_epi32(-1);
  const __m128 one = _mm_set1_ps(1.0f), h = _mm_set1_ps(hs), cl = _mm_set1_ps(cluster_life_t);
  size_t j = 0;
  for (; j + 4 <= m; j += 4) {
    const size_t i = i0 + j;
    const __m128i birth = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p.birth + i));
    const __m128i death = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p.death + i));
    const __m128i age_i = _mm_sub_epi32(nowv, birth);
    const __m128i life_i = _mm_sub_epi32(death, birth);
    const __m128i forever = _mm_cmpeq_epi32(death, never);
    const __m128 age = _mm_cvtepi32_ps(age_i);
    const __m128 life = _mm_cvtepi32_ps(life_i);  // meaningless for kNeverDies: not selected
    const __m128 q = _mm_min_ps(_mm_div_ps(age, life), one);
    const __m128 fm = _mm_castsi128_ps(forever);
    _mm_store_ps(t + j, _mm_or_ps(_mm_and_ps(fm, cl), _mm_andnot_ps(fm, q)));
    _mm_storeu_ps(p.rotation + i,
                  _mm_add_ps(_mm_loadu_ps(p.rot0 + i), _mm_mul_ps(_mm_loadu_ps(p.spin + i), _mm_mul_ps(age, h))));
    // cvtdq2ps converts as signed: equal to the unsigned conversion below 2^31. A group with a
    // larger age or finite life (only a wrapped tick difference) is redone by the scalar form.
    if (_mm_movemask_ps(_mm_castsi128_ps(_mm_or_si128(age_i, _mm_andnot_si128(forever, life_i)))) != 0)
      for (size_t k = j; k < j + 4; ++k) t[k] = life_scalar(p, i0 + k, now, hs, cluster_life_t);
  }
  for (; j < m; ++j) t[j] = life_scalar(p, i0 + j, now, hs, cluster_life_t);
}

enum class Post { None, TimesArray, ScaleClamp };

inline __m128 ramp_v(__m128 v, __m128 t, __m128 t0, __m128 k, __m128 d) {
  __m128 x = _mm_mul_ps(_mm_sub_ps(t, t0), k);
  x = _mm_min_ps(_mm_max_ps(x, _mm_setzero_ps()), _mm_set1_ps(1.0f));  // maxps(x,0) = x > 0 ? x : 0; minps(x,1) = x < 1 ? x : 1
  return _mm_add_ps(v, _mm_mul_ps(d, x));
}

template <Post P>
inline float post_scalar(float v, float s, const float* factor, size_t j) {
  if constexpr (P == Post::TimesArray) return v * factor[j];
  if constexpr (P == Post::ScaleClamp) {
    v *= s;
    return v < 1.0f ? v : 1.0f;
  }
  return v;
}

template <Post P>
inline __m128 post_v(__m128 v, __m128 s, const float* factor, size_t j) {
  if constexpr (P == Post::TimesArray) return _mm_mul_ps(v, _mm_loadu_ps(factor + j));
  if constexpr (P == Post::ScaleClamp) return _mm_min_ps(_mm_mul_ps(v, s), _mm_set1_ps(1.0f));
  return v;
}

// One curve over a block, K ramps unrolled with their constants in registers.
template <size_t K, Post P>
void curve_block(size_t m, const Curve& c, float s, const float* __restrict t, const float* __restrict factor,
                 float* __restrict out) {
  __m128 t0[K + 1], k[K + 1], d[K + 1];
  for (size_t r = 0; r < K; ++r)
    t0[r] = _mm_set1_ps(c.ramps[r].t0), k[r] = _mm_set1_ps(c.ramps[r].inv_width), d[r] = _mm_set1_ps(c.ramps[r].delta);
  const __m128 start = _mm_set1_ps(c.start), sv = _mm_set1_ps(s);
  size_t j = 0;
  for (; j + 4 <= m; j += 4) {
    const __m128 tv = _mm_load_ps(t + j);
    __m128 v = start;
    for (size_t r = 0; r < K; ++r) v = ramp_v(v, tv, t0[r], k[r], d[r]);
    _mm_storeu_ps(out + j, post_v<P>(v, sv, factor, j));
  }
  for (; j < m; ++j) out[j] = post_scalar<P>(curve_scalar(c, t[j]), s, factor, j);
}

template <Post P>
void curve_block_generic(size_t m, const Curve& c, float s, const float* __restrict t, const float* __restrict factor,
                         float* __restrict out) {
  const __m128 start = _mm_set1_ps(c.start), sv = _mm_set1_ps(s);
  size_t j = 0;
  for (; j + 4 <= m; j += 4) {
    const __m128 tv = _mm_load_ps(t + j);
    __m128 v = start;
    for (const CurveRamp& r : c.ramps)
      v = ramp_v(v, tv, _mm_set1_ps(r.t0), _mm_set1_ps(r.inv_width), _mm_set1_ps(r.delta));
    _mm_storeu_ps(out + j, post_v<P>(v, sv, factor, j));
  }
  for (; j < m; ++j) out[j] = post_scalar<P>(curve_scalar(c, t[j]), s, factor, j);
}

template <Post P>
void curve_values(size_t m, const Curve& c, float s, const float* t, const float* factor, float* out) {
  switch (c.ramps.size()) {
    case 0: return curve_block<0, P>(m, c, s, t, factor, out);
    case 1: return curve_block<1, P>(m, c, s, t, factor, out);
    case 2: return curve_block<2, P>(m, c, s, t, factor, out);
    case 3: return curve_block<3, P>(m, c, s, t, factor, out);
    case 4: return curve_block<4, P>(m, c, s, t, factor, out);
    default: return curve_block_generic<P>(m, c, s, t, factor, out);
  }
}

void animate_attributes_sse(const AttributeArrays& p, size_t n, uint32_t now, float hs, const CurveSet& curves,
                            float intensity, float cluster_life_t) {
  alignas(16) float t[kBlock];
  for (size_t i = 0; i < n; i += kBlock) {
    const size_t m = std::min(kBlock, n - i);
    life_fraction_sse(p, i, m, now, hs, cluster_life_t, t);
    curve_values<Post::TimesArray>(m, *curves.size, 0.0f, t, p.size0 + i, p.out[kSize] + i);
    curve_values<Post::None>(m, *curves.red, 0.0f, t, nullptr, p.out[kRed] + i);
    curve_values<Post::None>(m, *curves.green, 0.0f, t, nullptr, p.out[kGreen] + i);
    curve_values<Post::None>(m, *curves.blue, 0.0f, t, nullptr, p.out[kBlue] + i);
    curve_values<Post::ScaleClamp>(m, *curves.alpha, intensity, t, nullptr, p.out[kAlpha] + i);
    curve_values<Post::None>(m, *curves.burn, 0.0f, t, nullptr, p.out[kBurn] + i);
  }
}

#else

// Without SSE2: one plain loop per array over blocks of kBlock, which the compiler vectorises
// for the target it has (same arithmetic, same order).
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

void curve_values_passes(size_t n, const Curve& c, const float* __restrict t, float* __restrict out) {
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

void animate_attributes_passes(ParticlePool& pool, uint32_t now, double tick_seconds, const CurveSet& curves,
                               float intensity, float cluster_life_t) {
  const size_t n = pool.count();
  const float h = float(tick_seconds);
  float t[kBlock];
  for (size_t base = 0; base < n; base += kBlock) {
    const size_t m = std::min(kBlock, n - base);
    life_fraction(m, now, cluster_life_t, pool.birth.data() + base, pool.death.data() + base, t);
    curve_values_passes(m, *curves.size, t, pool.size.data() + base);
    multiply(m, pool.size0.data() + base, pool.size.data() + base);
    curve_values_passes(m, *curves.red, t, pool.r.data() + base);
    curve_values_passes(m, *curves.green, t, pool.g.data() + base);
    curve_values_passes(m, *curves.blue, t, pool.b.data() + base);
    curve_values_passes(m, *curves.alpha, t, pool.a.data() + base);
    scale_clamped(m, intensity, pool.a.data() + base);
    curve_values_passes(m, *curves.burn, t, pool.burn.data() + base);
    spin_rotation(m, now, h, pool.birth.data() + base, pool.rot0.data() + base, pool.spin.data() + base,
                  pool.rotation.data() + base);
  }
}

#endif

}  // namespace

#if defined(__SSE2__)
void animate_attributes(ParticlePool& pool, uint32_t now, double tick_seconds, const CurveSet& curves, float intensity,
                        float cluster_life_t) {
  const AttributeArrays p{pool.birth.data(),
                          pool.death.data(),
                          pool.size0.data(),
                          pool.rot0.data(),
                          pool.spin.data(),
                          {pool.size.data(), pool.r.data(), pool.g.data(), pool.b.data(), pool.a.data(), pool.burn.data()},
                          pool.rotation.data()};
  const size_t n = pool.count();
  const float h = float(tick_seconds);
  animate_attributes_sse(p, n, now, h, curves, intensity, cluster_life_t);
}
#else
void animate_attributes(ParticlePool& pool, uint32_t now, double tick_seconds, const CurveSet& curves, float intensity,
                        float cluster_life_t) {
  animate_attributes_passes(pool, now, tick_seconds, curves, intensity, cluster_life_t);
}
#endif

}  // namespace arc
