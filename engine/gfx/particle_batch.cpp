// gfx/particle_batch.cpp — culling, soft-edge flags, sorting and the draw limit (no GL).
#include "gfx/particle_batch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>

namespace arc {
namespace {

// Per-cluster sorting: every particle gets the key of its cluster's mean depth along `forward`.
void cluster_depth_keys(const std::vector<ParticleInstance>& particles, const glm::vec3& forward,
                        std::vector<uint32_t>& keys) {
  std::vector<uint32_t> cluster_ids;
  for (auto& p : particles) cluster_ids.push_back(p.cluster);
  std::vector<uint32_t> unique_ids = cluster_ids;
  std::sort(unique_ids.begin(), unique_ids.end());
  unique_ids.erase(std::unique(unique_ids.begin(), unique_ids.end()), unique_ids.end());
  std::vector<double> sum(unique_ids.size(), 0.0);
  std::vector<int> cnt(unique_ids.size(), 0);
  std::vector<uint32_t> slot(particles.size());
  for (size_t i = 0; i < particles.size(); ++i) {
    slot[i] = uint32_t(std::lower_bound(unique_ids.begin(), unique_ids.end(), cluster_ids[i]) - unique_ids.begin());
    const float* pp = particles[i].pos;
    sum[slot[i]] += pp[0] * forward.x + pp[1] * forward.y + pp[2] * forward.z;
    ++cnt[slot[i]];
  }
  for (size_t i = 0; i < particles.size(); ++i) keys[i] = sortable_bits(float(sum[slot[i]] / cnt[slot[i]]));
}

}  // namespace

uint32_t sortable_bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return (u & 0x80000000u) ? ~u : (u | 0x80000000u);
}

void radix_sort_back_to_front(const std::vector<uint32_t>& keys, std::vector<uint32_t>& order) {
  // Descending keys = ascending of the complement.
  // The scratch keys are kept from call to call (per thread): fresh buffers of a large batch
  // would be mapped and faulted in every frame.
  size_t n = keys.size();
  thread_local std::vector<uint32_t> k, k2, o2;
  k.resize(n);
  k2.resize(n);
  o2.resize(n);
  order.resize(n);
  for (size_t i = 0; i < n; ++i) {
    k[i] = ~keys[i];
    order[i] = uint32_t(i);
  }
  for (int shift = 0; shift < 32; shift += 8) {
    std::array<uint32_t, 257> count{};
    for (size_t i = 0; i < n; ++i) ++count[((k[i] >> shift) & 0xFF) + 1];
    bool uniform_digit = false;  // all keys share this digit: the pass would be a plain copy
    for (int b = 1; b <= 256; ++b) uniform_digit = uniform_digit || count[b] == n;
    if (uniform_digit) continue;
    for (int b = 0; b < 256; ++b) count[b + 1] += count[b];
    for (size_t i = 0; i < n; ++i) {
      uint32_t dst = count[(k[i] >> shift) & 0xFF]++;
      k2[dst] = k[i];
      o2[dst] = order[i];
    }
    k.swap(k2);
    order.swap(o2);
  }
}

void ParticleBatch::prepare(const RenderView& v, const ViewProjection& vp, const ModelCoverBoxes& model_boxes,
                            const ParticleBatchOptions& options) {
  if (options.by_cluster) return prepare_by_cluster(v, vp, model_boxes, options);
  source = nullptr;
  soft_override = -1;
  order.clear();
  visible = culled_offscreen = over_draw_limit = sorted = soft_shaded = 0;
  any_soft = any_contrast = false;
  runs.clear();
  const glm::vec3 forward = -glm::vec3(glm::transpose(vp.view)[2]);  // camera −Z in world space
  const OverdrawFrame frame{glm::mat3(vp.view), 1.0f / vp.proj[1][1], float(v.camera.near_plane), options.size_clamp,
                            options.width, options.height, v.time_seconds, options.trim, options.trim_mode,
                            options.trim_height};
  cull_and_flag(v, vp, forward, model_boxes, options, frame);
  overdraw = budget_.apply(particles, areas, frame, options.overdraw, &boxes_);
  overdraw.reduced += small_left_out_;  // as the budget counts the ones it leaves out for their size
  overdraw.dropped += small_left_out_;
  coverage.reset(options.width, options.height);
  budget_.mark_coverage(coverage);
  visible = int(particles.size());
  if (particles.empty()) return;
  keys_.clear();
  any_ordered_ = false;
  for (const ParticleInstance& q : particles) {
    keys_.push_back(sortable_bits(q.pos[0] * forward.x + q.pos[1] * forward.y + q.pos[2] * forward.z));
    any_ordered_ = any_ordered_ || q.color[3] * (1.0f - q.burn) > 0.0f;
  }
  // Pure additive particles need no order; as soon as one is alpha blended, the whole set is
  // ordered, because an additive glow in front of smoke must not be darkened by it.
  if (any_ordered_ && options.sorting != RenderSettings::Sorting::Off)
    sort(options.sorting, forward);
  // A buffer texture reaches GL_MAX_TEXTURE_BUFFER_SIZE texels (at least 65536, so 16384
  // particles; 2^27 on llvmpipe and desktop GPUs): beyond that the nearest ones are kept when
  // sorted (the order is back to front), an arbitrary subset otherwise.
  if (particles.size() > options.max_particles) {
    over_draw_limit = int(particles.size() - options.max_particles);
    particles.erase(particles.begin(), particles.begin() + std::ptrdiff_t(particles.size() - options.max_particles));
    areas.erase(areas.begin(), areas.begin() + std::ptrdiff_t(areas.size() - options.max_particles));
    boxes_.erase(boxes_.begin(), boxes_.begin() + std::ptrdiff_t(boxes_.size() - options.max_particles));
  }
  // Runs by program, from the particles that are drawn; the depth copy only for a soft run.
  depth_reads.reset(options.width, options.height);
  if (options.depth_tiles && mixed_programs(particles)) mark_depth_reads(options.width, options.height);
  else if (options.depth_tiles && needs_depth(particles[0])) depth_reads.add_whole_screen();
  group_runs(particles, areas, boxes_, options.max_runs, runs);
  for (const ParticleInstance& q : particles) soft_shaded += needs_depth(q);
  for (const ParticleRun& r : runs) {
    any_soft = any_soft || r.soft;
    any_contrast = any_contrast || r.contrast;
  }
}

// Culling, per stretch of a cluster first (particle_batch_cluster.cpp gathers their bounds in
// one read), then per particle for the stretches neither wholly out nor wholly left out: in a
// big battle most particles are off screen or under the frame-time target's size, and only what
// can be drawn pays for the per-particle work (the reach test, the budget's estimate, the sort).
// A stretch goes whole only where every particle of it would go one by one, and is counted as
// they would be, so the batch and its figures are the per-particle ones.
void ParticleBatch::cull_and_flag(const RenderView& v, const ViewProjection& vp, const glm::vec3& fwd,
                                  const ModelCoverBoxes& model_boxes, const ParticleBatchOptions& options,
                                  const OverdrawFrame& frame) {
  const glm::mat3 to_view(vp.view);
  const float near = float(v.camera.near_plane);
  // The four side planes of the view frustum in view space, as unit normals pointing out: a
  // particle whose quad lies wholly outside one of them is not uploaded. Clusters are culled
  // whole before this (game/render); this drops the particles of a visible cluster that are off
  // screen, such as the far ends of a long beam, which would cost vertex work and setup.
  const float tx = 1.0f / vp.proj[0][0], ty = 1.0f / vp.proj[1][1];
  occluders_.gather(v, model_boxes, to_view, tx, ty);
  const glm::vec3 planes[4] = {glm::normalize(glm::vec3(1, 0, tx)), glm::normalize(glm::vec3(-1, 0, tx)),
                               glm::normalize(glm::vec3(0, 1, ty)), glm::normalize(glm::vec3(0, -1, ty))};
  particles.clear();
  small_left_out_ = 0;
  const float min_px = options.overdraw.min_px;
  // Stretch by stretch, so the particles of one are still in the cache when they are kept.
  for (size_t next = 0; next < v.particles.size();) {
    const Stretch s = next_stretch(v, next, fwd, nullptr);
    if (s.shown == 0 || stretch_left_out(s, to_view, planes, min_px, frame)) continue;
    for (uint32_t i = s.first; i < s.first + s.count; ++i)
      keep_particle(v.particles[i], to_view, fwd, planes, near, options.soft_override, min_px, frame);
  }
}

// Whether the whole stretch is wholly in front of the camera and either wholly outside a side
// of the frustum or wholly inside and under min_px (every particle of it then is): it is then
// counted as its particles would be. Its sphere is widened a little beyond the particles' own
// bounds (quad_bounds' 1.001, the view transform's rounding), so the answer is never a
// particle's other one.
bool ParticleBatch::stretch_left_out(const Stretch& s, const glm::mat3& to_view, const glm::vec3 (&planes)[4],
                                     float min_px, const OverdrawFrame& frame) {
  const glm::vec3 c = to_view * s.centre;
  const float radius = s.radius * 1.002f + 1e-5f * (std::abs(c.x) + std::abs(c.y) + std::abs(c.z));
  const float front = -c.z - radius;  // the stretch's nearest view depth
  if (!(front > 0.0f)) return false;
  float side = -std::numeric_limits<float>::max();
  for (const glm::vec3& n : planes) side = std::max(side, glm::dot(n, c));
  if (side > radius) {
    culled_offscreen += int(s.shown);
    return true;
  }
  if (!(min_px > 0.0f) || s.high || !(side < -radius)) return false;
  // Its largest on-screen extent: the widest reach at the nearest depth (the budget's size
  // clamp only shrinks it), a little over.
  const float d = std::max(front, frame.near);
  const float reach = s.reach + 1e-6f;
  const float extent = reach * 0.5f * float(frame.height) / (d * std::max(frame.tan_half_y, 1e-6f)) * 1.01f;
  if (!(extent < min_px)) return false;
  small_left_out_ += int(s.shown);
  return true;
}

// One particle of a stretch that may be drawn: culled, left out for its size, or kept with its
// soft-edge flag.
void ParticleBatch::keep_particle(const ParticleInstance& p, const glm::mat3& to_view, const glm::vec3& fwd,
                                  const glm::vec3 (&planes)[4], float near, int soft_override, float min_px,
                                  const OverdrawFrame& frame) {
  bool dark = p.color[0] <= 0 && p.color[1] <= 0 && p.color[2] <= 0 && p.color[3] <= 0;
  float depth = p.pos[0] * fwd.x + p.pos[1] * fwd.y + p.pos[2] * fwd.z;
  float axis_len = std::sqrt(p.axis[0] * p.axis[0] + p.axis[1] * p.axis[1] + p.axis[2] * p.axis[2]);
  float reach = std::max(p.size, 0.0f) + axis_len;
  if (dark || !(depth > -reach)) return;  // invisible or wholly behind the camera (NaN fails too)
  const QuadBounds b = quad_bounds(p, to_view, axis_len);
  if (glm::dot(planes[0], b.centre) > b.radius || glm::dot(planes[1], b.centre) > b.radius ||
      glm::dot(planes[2], b.centre) > b.radius || glm::dot(planes[3], b.centre) > b.radius) {
    ++culled_offscreen;
    return;
  }
  if (OverdrawBudget::below_min_px(p, frame, min_px)) {  // as the budget would, before its estimate
    ++small_left_out_;
    return;
  }
  ParticleInstance q = p;
  if (soft_override >= 0) q.soft_edge = uint8_t(soft_override);
  if (q.soft_edge != 0 && !occluders_.soft_can_matter(q, b, near)) q.soft_edge |= kSoftClear;
  particles.push_back(q);
}

// The tiles of the soft particles' screen boxes: only there does a fragment read the depth
// copy (a clear particle drawn by the soft program computes the read and discards it).
void ParticleBatch::mark_depth_reads(int width, int height) {
  const float hw = 0.5f * float(width), hh = 0.5f * float(height);
  for (size_t i = 0; i < particles.size(); ++i) {
    if (!needs_depth(particles[i])) continue;
    const ScreenBox& b = boxes_[i];
    depth_reads.add_box((0.5f * (b.x0 + b.x1) + 1.0f) * hw, (0.5f * (b.y0 + b.y1) + 1.0f) * hh, 0.5f * (b.x1 - b.x0) * hw,
                        0.5f * (b.y1 - b.y0) * hh);
  }
}

void ParticleBatch::sort(RenderSettings::Sorting sorting, const glm::vec3& forward) {
  if (sorting == RenderSettings::Sorting::Cluster) cluster_depth_keys(particles, forward, keys_);
  radix_sort_back_to_front(keys_, order_);
  sorted_.resize(particles.size());
  sorted_areas_.resize(areas.size());
  sorted_boxes_.resize(boxes_.size());
  for (size_t i = 0; i < order_.size(); ++i) {
    sorted_[i] = particles[order_[i]];
    sorted_areas_[i] = areas[order_[i]];
    sorted_boxes_[i] = boxes_[order_[i]];
  }
  particles.swap(sorted_);
  areas.swap(sorted_areas_);
  boxes_.swap(sorted_boxes_);
  sorted = int(particles.size());
}

}  // namespace arc
