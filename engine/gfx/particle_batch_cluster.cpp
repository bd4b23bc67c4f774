// gfx/particle_batch_cluster.cpp — the particle batch prepared per cluster stretch (no GL).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>

#include "gfx/particle_batch.h"

namespace arc {
namespace {

// A stretch longer than this is split, so one far-flung cluster does not keep a huge bound.
constexpr uint32_t kMaxStretch = 1024;

uint32_t method_bit(uint8_t soft_edge) { return 1u << (soft_edge & 7u); }

}  // namespace

// The stretch starting at particle i (consecutive particles of one cluster, at most
// kMaxStretch): its bounds, reach and soft methods and, with `depths`, every particle's depth
// along `forward`; i moves past it. Branch-light on purpose: this loop reads every particle.
ParticleBatch::Stretch ParticleBatch::next_stretch(const RenderView& v, size_t& i, const glm::vec3& forward,
                                                   float* depths) {
  const size_t n = v.particles.size();
  const ParticleInstance* p = v.particles.data();
  Stretch s;
  s.first = uint32_t(i);
  const uint32_t cluster = p[i].cluster;
  float lo[3] = {p[i].pos[0], p[i].pos[1], p[i].pos[2]};
  float hi[3] = {lo[0], lo[1], lo[2]};
  float reach = 0.0f, extent = 0.0f;
  uint32_t methods = 0, soft = 0, ordered = 0, lit = 0, shown = 0, high = 0;
  const size_t end = std::min(n, i + kMaxStretch);
  // Bitwise ors, not ||: no branch per particle.
  for (; i < end && p[i].cluster == cluster; ++i) {
    const ParticleInstance& q = p[i];
    if (depths) depths[i] = q.pos[0] * forward.x + q.pos[1] * forward.y + q.pos[2] * forward.z;
    lo[0] = std::min(lo[0], q.pos[0]), hi[0] = std::max(hi[0], q.pos[0]);
    lo[1] = std::min(lo[1], q.pos[1]), hi[1] = std::max(hi[1], q.pos[1]);
    lo[2] = std::min(lo[2], q.pos[2]), hi[2] = std::max(hi[2], q.pos[2]);
    const float size = std::max(q.size, 0.0f);
    // |a|₁ ≥ |a|₂: a bound without a square root.
    reach = std::max(reach, size + std::abs(q.axis[0]) + std::abs(q.axis[1]) + std::abs(q.axis[2]));
    extent = std::max(extent, std::max(q.soft_extent, size));
    methods |= method_bit(q.soft_edge);
    soft += uint32_t(q.soft_edge != 0);
    ordered |= uint32_t(q.color[3] * (1.0f - q.burn) > 0.0f);
    lit |= uint32_t(q.color[0] > 0) | uint32_t(q.color[1] > 0) | uint32_t(q.color[2] > 0) | uint32_t(q.color[3] > 0);
    shown += uint32_t(!(q.color[0] <= 0 && q.color[1] <= 0 && q.color[2] <= 0 && q.color[3] <= 0));
    high |= uint32_t(q.screen_priority >= uint8_t(ScreenPriority::High));
  }
  s.count = uint32_t(i) - s.first;
  s.centre = glm::vec3(0.5f * (lo[0] + hi[0]), 0.5f * (lo[1] + hi[1]), 0.5f * (lo[2] + hi[2]));
  const glm::vec3 half(0.5f * (hi[0] - lo[0]), 0.5f * (hi[1] - lo[1]), 0.5f * (hi[2] - lo[2]));
  // A quad's corners lie within √2 of its reach from its centre.
  s.radius = glm::length(half) * 1.001f + reach * 1.4143f + 1e-6f;
  s.extent = extent;
  s.reach = reach;
  s.methods = methods;
  s.soft_count = soft;
  s.ordered = ordered != 0;
  s.lit = lit != 0;
  s.shown = shown;
  s.high = high != 0;
  return s;
}

// Every stretch of the view, in one read of its particles (and their depths, for a full sort).
void ParticleBatch::gather_stretches(const RenderView& v, const glm::vec3& forward, bool depths) {
  stretches_.clear();
  const size_t n = v.particles.size();
  if (depths) depths_.resize(n);
  size_t i = 0;
  while (i < n) stretches_.push_back(next_stretch(v, i, forward, depths ? depths_.data() : nullptr));
}

namespace {

// One stretch's pairs and digit counts; Digits and Exact fixed, so the loop has no branch and
// counts no digit every key shares.
template <int Digits, bool Exact>
void fill_stretch(const float* depth, uint32_t count, uint32_t low, float hi, float scale, float top, uint64_t* out,
                  uint32_t* hist) {
  for (uint32_t j = 0; j < count; ++j) {
    uint32_t key;
    if constexpr (Exact) {
      key = ~sortable_bits(depth[j]);
    } else {
      float t = (hi - depth[j]) * scale;
      t = t > 0.0f ? t : 0.0f;  // NaN too
      key = uint32_t(std::min(t, top));
    }
    out[j] = (uint64_t(key) << 32) | (low + j);
    ++hist[key & 2047];
    if constexpr (Digits > 1) ++hist[2048 + ((key >> 11) & 2047)];
    if constexpr (Digits > 2) ++hist[4096 + (key >> 22)];
  }
}

}  // namespace

// (key, clear bit | source index) pairs of the kept stretches in kept_ order (the view's), and
// the 11-bit digit histograms of the keys, in one read of the depths. Keys ascend from back to
// front: above 22 bits the depth's own float bits, complemented (three passes); with at most 22,
// the depth quantised over the kept stretches' depth range [lo, hi], one pass per 11 bits.
void ParticleBatch::fill_pairs(size_t total, int bits, float lo, float hi) {
  pairs_.resize(total);
  pairs_tmp_.resize(total);
  hist_.assign(3 * 2048, 0);
  uint64_t* out = pairs_.data();
  const bool exact = bits > 22;  // a float holds 24 bits exactly: quantised keys stop at 22
  const float top = float((1u << std::clamp(bits, 1, 22)) - 1u);
  const float scale = top / std::max(hi - lo, 1e-30f);
  auto fill = exact ? fill_stretch<3, true> : bits > 11 ? fill_stretch<2, false> : fill_stretch<1, false>;
  for (uint32_t k : kept_) {
    const Stretch& s = stretches_[k];
    fill(depths_.data() + s.first, s.count, (s.clear ? kOrderClear : 0u) | s.first, hi, scale, top, out, hist_.data());
    out += s.count;
  }
}

namespace {

// The soft-edge byte as drawn: the override, then the clear flag.
inline void set_soft(ParticleInstance& q, int soft_override, bool clear) {
  if (soft_override >= 0) q.soft_edge = uint8_t(soft_override);
  if (clear && q.soft_edge != 0) q.soft_edge |= kSoftClear;
}

}  // namespace

// The kept stretches copied as they are, in kept_ order.
void ParticleBatch::gather_in_order(const RenderView& v, size_t total, int soft_override) {
  particles.resize(total);
  ParticleInstance* out = particles.data();
  for (uint32_t k : kept_) {
    const Stretch& s = stretches_[k];
    std::memcpy(out, v.particles.data() + s.first, s.count * sizeof(ParticleInstance));
    if (soft_override >= 0 || s.clear)
      for (uint32_t j = 0; j < s.count; ++j) set_soft(out[j], soft_override, s.clear);
    out += s.count;
  }
}

// The kept stretches' indices in kept_ order, each with its stretch's clear bit.
void ParticleBatch::index_in_order(size_t total) {
  order.resize(total);
  uint32_t* out = order.data();
  for (uint32_t k : kept_) {
    const Stretch& s = stretches_[k];
    const uint32_t clear = s.clear ? kOrderClear : 0u;
    for (uint32_t j = 0; j < s.count; ++j) out[j] = (s.first + j) | clear;
    out += s.count;
  }
}

// LSD radix passes over pairs_ by 11-bit digits of the key, skipping a digit all keys share
// (the pass would be a plain copy). Stable, so equal keys keep their view order, as
// radix_sort_back_to_front does. With to_order the last pass that moves anything writes the
// pairs' low halves straight into `order`; returns whether it did.
bool ParticleBatch::radix_passes(size_t total, bool to_order) {
  uint32_t* hist = hist_.data();
  bool skip[3];
  int last = -1;
  for (int pass = 0; pass < 3; ++pass) {
    uint32_t* h = hist + pass * 2048;
    uint32_t sum = 0;
    skip[pass] = false;
    for (int b = 0; b < 2048; ++b) {
      skip[pass] = skip[pass] || h[b] == total;
      const uint32_t c = h[b];
      h[b] = sum;
      sum += c;
    }
    if (!skip[pass]) last = pass;
  }
  for (int pass = 0; pass < 3; ++pass) {
    if (skip[pass]) continue;
    uint32_t* h = hist + pass * 2048;
    const int shift = 32 + 11 * pass;
    const uint64_t* in = pairs_.data();
    if (to_order && pass == last) {
      order.resize(total);
      uint32_t* o = order.data();
      for (size_t i = 0; i < total; ++i) o[h[(in[i] >> shift) & 2047]++] = uint32_t(in[i]);
      return true;
    }
    uint64_t* o = pairs_tmp_.data();
    for (size_t i = 0; i < total; ++i) o[h[(in[i] >> shift) & 2047]++] = in[i];
    pairs_.swap(pairs_tmp_);
  }
  return false;
}

// The kept indices back to front by depth: only 4 bytes per particle leave the sort.
void ParticleBatch::index_sorted(size_t total) {
  if (radix_passes(total, true)) return;
  order.resize(total);
  for (size_t i = 0; i < total; ++i) order[i] = uint32_t(pairs_[i]);
}

// The kept particles copied back to front by depth, the soft byte patched: for a view larger
// than the particle buffer takes whole.
void ParticleBatch::gather_sorted(const RenderView& v, size_t total, int soft_override) {
  radix_passes(total, false);
  particles.resize(total);
  const bool patch = soft_override >= 0;
  for (size_t i = 0; i < total; ++i) {
    const uint32_t e = uint32_t(pairs_[i]);
    particles[i] = v.particles[e & kOrderIndex];
    if (patch || (e & kOrderClear)) set_soft(particles[i], soft_override, (e & kOrderClear) != 0);
  }
}

// The kept stretches' particles in draw order: indexed when the view fits one buffer, copied
// otherwise; and the soft-shaded count, by stretch.
void ParticleBatch::list_kept(const RenderView& v, size_t total, const ParticleBatchOptions& options, bool full_sort,
                              float depth_lo, float depth_hi) {
  const bool index = v.particles.size() <= options.max_source;
  source = index ? &v.particles : nullptr;
  soft_override = index ? options.soft_override : -1;
  particles.clear();
  order.clear();
  if (full_sort) fill_pairs(total, options.sort_bits, depth_lo, depth_hi);
  if (index) full_sort ? index_sorted(total) : index_in_order(total);
  else if (full_sort) gather_sorted(v, total, options.soft_override);
  else gather_in_order(v, total, options.soft_override);
  for (uint32_t k : kept_) {
    const Stretch& s = stretches_[k];
    if (s.clear) continue;
    if (options.soft_override >= 0) soft_shaded += options.soft_override != 0 ? int(s.count) : 0;
    else soft_shaded += int(s.soft_count);
  }
}

void ParticleBatch::prepare_by_cluster(const RenderView& v, const ViewProjection& vp, const ModelCoverBoxes& model_boxes,
                                       const ParticleBatchOptions& options) {
  visible = culled_offscreen = over_draw_limit = sorted = soft_shaded = 0;
  any_soft = any_contrast = false;
  runs.clear(), areas.clear(), boxes_.clear();
  overdraw = OverdrawStats{};
  const glm::vec3 forward = -glm::vec3(glm::transpose(vp.view)[2]);
  const glm::mat3 to_view(vp.view);
  const float near = float(v.camera.near_plane);
  const float tx = 1.0f / vp.proj[0][0], ty = 1.0f / vp.proj[1][1];
  occluders_.gather(v, model_boxes, to_view, tx, ty);
  const glm::vec3 planes[4] = {glm::normalize(glm::vec3(1, 0, tx)), glm::normalize(glm::vec3(-1, 0, tx)),
                               glm::normalize(glm::vec3(0, 1, ty)), glm::normalize(glm::vec3(0, -1, ty))};
  gather_stretches(v, forward, options.sorting == RenderSettings::Sorting::Full);
  // Cull whole stretches by their bounding sphere and decide their soft flag once. A stretch
  // kept as a whole may hold particles the per-particle path drops: they are off screen or
  // dark, so the GPU clips them or blends zero, and the picture is the same.
  const bool override_soft = options.soft_override >= 0;
  const uint32_t override_bit = override_soft ? method_bit(uint8_t(options.soft_override)) : 0;
  kept_.clear();
  size_t total = 0;
  float depth_lo = std::numeric_limits<float>::max(), depth_hi = -depth_lo;
  uint32_t methods_drawn = 0;
  any_ordered_ = false;
  for (Stretch& s : stretches_) {
    const glm::vec3 c = to_view * s.centre;
    const bool outside = glm::dot(planes[0], c) > s.radius || glm::dot(planes[1], c) > s.radius ||
                         glm::dot(planes[2], c) > s.radius || glm::dot(planes[3], c) > s.radius;
    if (!s.lit || !(-c.z > -s.radius) || outside) {
      if (s.lit && outside) culled_offscreen += int(s.count);
      continue;
    }
    const uint32_t methods = override_soft ? override_bit : s.methods;
    s.clear = false;
    if (methods & ~1u) {
      // Density extent pushes furthest towards the camera: the bound of every method.
      s.clear = !occluders_.reach_can_matter(sphere_footprint(c, s.radius, near), s.extent, s.extent, near);
    }
    if (!s.clear) methods_drawn |= methods;
    s.depth = glm::dot(forward, s.centre);
    depth_lo = std::min(depth_lo, s.depth - s.radius);
    depth_hi = std::max(depth_hi, s.depth + s.radius);
    any_ordered_ = any_ordered_ || s.ordered;
    kept_.push_back(uint32_t(&s - stretches_.data()));
    total += s.count;
  }
  if (any_ordered_ && options.sorting == RenderSettings::Sorting::Cluster)
    std::stable_sort(kept_.begin(), kept_.end(),
                     [&](uint32_t a, uint32_t b) { return stretches_[a].depth > stretches_[b].depth; });
  const bool full_sort = any_ordered_ && options.sorting == RenderSettings::Sorting::Full;
  list_kept(v, total, options, full_sort, depth_lo, depth_hi);
  visible = int(drawn());
  coverage.reset(options.width, options.height);
  depth_reads.reset(options.width, options.height);
  if (drawn() == 0) return;
  coverage.add_whole_screen();
  if (any_ordered_ && options.sorting != RenderSettings::Sorting::Off) sorted = int(drawn());
  if (drawn() > options.max_particles) {  // the farthest go: the order is back to front
    const auto cut = std::ptrdiff_t(drawn() - options.max_particles);
    over_draw_limit = int(cut);
    if (indexed()) order.erase(order.begin(), order.begin() + cut);
    else particles.erase(particles.begin(), particles.begin() + cut);
  }
  // One draw: the soft programs give a clear or hard particle exactly 1, and the contrast and
  // density-extent variants apply their curve per particle (particle.frag), so the most general
  // variant the batch needs draws every particle as its own program would.
  ParticleRun run;
  run.count = uint32_t(drawn());
  run.soft = (methods_drawn & ~1u) != 0;
  run.contrast = (methods_drawn & method_bit(uint8_t(SoftEdge::Contrast))) != 0;
  run.density_extent = (methods_drawn & method_bit(uint8_t(SoftEdge::DensityExtent))) != 0;
  runs.push_back(run);
  any_soft = run.soft;
  any_contrast = run.contrast;
  if (any_soft && options.depth_tiles) depth_reads.add_whole_screen();
}

}  // namespace arc
