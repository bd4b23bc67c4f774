// gfx/particle_batch.h — the particle pass's CPU half: what is drawn, in which order (no GL).
//
// From the view's particles and the frame's camera, prepare() keeps the visible ones (not dark,
// not wholly behind the camera, not wholly outside a side of the frustum), applies the global
// soft-edge override, flags with kSoftClear those no opaque mesh can reach (particle_occluders.h),
// holds the frame to its screen-space overdraw budget (overdraw_budget.h), sorts back to front
// when any kept particle is alpha blended (DESIGN.md "Rendering": pure additive ones need no
// order), drops the farthest beyond the draw limit and splits the result into runs by shader
// variant (particle_runs.h). The particle pass uploads `particles` as they are and draws each
// run with its program. Per cluster (ParticleBatchOptions::by_cluster) the batch is usually
// indexed instead: the view's particles are uploaded untouched and only their order is written.
//
// Example, compiled as GfxCpuExamples.PrepareABatch in tests/unit/gfx/test_gfx_cpu_examples.cpp:
//   ParticleBatch batch;
//   batch.prepare(view, make_view_projection(view.camera, aspect, true, true), model_boxes, {});
//   if (batch.any_soft) depth_copies += 1;                 // the depth buffer is copied first
//   for (const ParticleRun& run : batch.runs) draws.push_back(run.count);  // one draw each
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "gfx/cover_boxes.h"
#include "gfx/overdraw_budget.h"
#include "gfx/particle_coverage.h"
#include "gfx/particle_runs.h"
#include "gfx/particle_occluders.h"
#include "gfx/render_settings.h"
#include "gfx/render_view.h"
#include "gfx/view_projection.h"

namespace arc {

struct ParticleBatchOptions {
  int soft_override = -1;  // RenderSettings::soft_override
  RenderSettings::Sorting sorting = RenderSettings::Sorting::Full;
  size_t max_particles = std::numeric_limits<size_t>::max();  // what one draw can pull
  OverdrawOptions overdraw;  // the screen-space budget (0 layers: none, areas still estimated)
  float size_clamp = 0.5f;   // RenderSettings::size_clamp, as particle.vert applies it
  int width = 1280, height = 720;  // scene pixels, for the blended-area estimate
  int max_runs = 24;         // draws the batch may be split into (particle_runs.h)
  bool depth_tiles = true;   // mark depth_reads (the copy's tiles); not needed when the depth is fetched
  const SpriteTrim* trim = nullptr;  // the sprites' trim boxes, for the area estimate
  TrimMode trim_mode = TrimMode::Off;
  int trim_height = 720;  // pixel rows of the target drawn into: the half-resolution one's when it is likely
  // Per cluster (RenderSettings::ParticlePrep): whole stretches of a cluster are culled and
  // flagged, listed by index (or copied, beyond max_source), sorted by full radix or by stretch,
  // drawn in one run; no overdraw budget (a GPU's fill rate needs none). Per particle otherwise,
  // as described above.
  bool by_cluster = false;
  // Per cluster, when the view holds at most this many particles (what the particle buffer
  // takes): the batch is an order of indices into the view's particles, uploaded as they are.
  size_t max_source = 0;
  // Per cluster, full sorting: depth key bits (RenderSettings::particle_sort_bits). Up to 22, the
  // depth quantised over the kept depth range, one radix pass per 11 bits; above, its float bits
  // in three passes (the per-particle path's exact order).
  int sort_bits = 32;
};

struct ParticleBatch {
  // Copies of the kept particles in draw order, soft_edge overridden and flagged, reduced by
  // the overdraw budget; areas[i]: particles[i]'s estimated blended pixels.
  std::vector<ParticleInstance> particles;
  // An indexed batch (per cluster within max_source): `particles` stays empty and the draw pulls
  // (*source)[order[i] & kOrderIndex], bit 31 set for a clear stretch, with soft_override applied
  // by the vertex shader; only 4 bytes per particle are written in draw order. `source` is the
  // view prepare() was given, so it is valid while that view is.
  std::vector<uint32_t> order;
  const std::vector<ParticleInstance>* source = nullptr;
  int soft_override = -1;
  static constexpr uint32_t kOrderIndex = 0x7FFFFFFFu, kOrderClear = 0x80000000u;
  bool indexed() const { return source != nullptr; }
  size_t drawn() const { return indexed() ? order.size() : particles.size(); }
  std::vector<float> areas;
  std::vector<ParticleRun> runs;  // spans of `particles`, one draw each
  ParticleCoverage coverage;      // the scene tiles the particles can touch (particle_coverage.h)
  ParticleCoverage depth_reads;   // the scene tiles where a soft particle can read the depth copy (with depth_tiles)
  OverdrawStats overdraw;
  int visible = 0;           // kept before the draw limit (FrameStats::particles_drawn)
  int culled_offscreen = 0;  // quad wholly outside a side of the frustum
  int over_draw_limit = 0;   // farthest ones left out beyond max_particles
  int sorted = 0;            // put in back-to-front order (0 when unsorted)
  int soft_shaded = 0;       // soft and not kSoftClear: they read the depth copy
  bool any_soft = false;     // the depth copy is needed
  bool any_contrast = false; // a soft one uses the contrast curve

  void prepare(const RenderView& view, const ViewProjection& vp, const ModelCoverBoxes& model_boxes,
               const ParticleBatchOptions& options);
  void restart_smoothing() { budget_.reset(); }

 private:
  // A stretch: consecutive particles of one cluster (at most 1024) taken as one for culling.
  struct Stretch {
    uint32_t first = 0, count = 0;
    glm::vec3 centre{0.0f};  // camera-relative, of the positions' box
    float radius = 0;        // a sphere around centre holding every quad
    float extent = 0;        // the largest soft-edge depth extent
    float reach = 0;         // the largest size + |axis|₁ (a bound on each quad's half extent)
    float depth = 0;         // centre along the view direction
    uint32_t methods = 0;    // bit per SoftEdge present
    uint32_t soft_count = 0; // particles with a soft-edge method
    uint32_t shown = 0;      // particles not wholly dark (the per-particle path's test)
    bool ordered = false, lit = false, clear = false;
    bool high = false;       // one has high screen priority (never left out for its size)
  };
  void prepare_by_cluster(const RenderView& view, const ViewProjection& vp, const ModelCoverBoxes& model_boxes,
                          const ParticleBatchOptions& options);
  void gather_stretches(const RenderView& view, const glm::vec3& forward, bool pairs);
  static Stretch next_stretch(const RenderView& view, size_t& i, const glm::vec3& forward, float* depths);
  void gather_in_order(const RenderView& view, size_t total, int soft_override);
  void gather_sorted(const RenderView& view, size_t total, int soft_override);
  void list_kept(const RenderView& view, size_t total, const ParticleBatchOptions& options, bool full_sort,
                 float depth_lo, float depth_hi);
  void index_in_order(size_t total);
  void index_sorted(size_t total);
  void fill_pairs(size_t total, int bits, float lo, float hi);
  bool radix_passes(size_t total, bool to_order);
  std::vector<uint32_t> hist_;
  std::vector<uint64_t> pairs_, pairs_tmp_;  // (depth key, source index) for the full sort
  std::vector<float> depths_;  // each view particle's depth along the view direction
  std::vector<Stretch> stretches_;
  std::vector<uint32_t> kept_;  // indices of the stretches drawn, in draw order
  void cull_and_flag(const RenderView& view, const ViewProjection& vp, const glm::vec3& forward,
                     const ModelCoverBoxes& model_boxes, const ParticleBatchOptions& options,
                     const OverdrawFrame& frame);
  bool stretch_left_out(const Stretch& s, const glm::mat3& to_view, const glm::vec3 (&planes)[4], float min_px,
                        const OverdrawFrame& frame);
  void keep_particle(const ParticleInstance& p, const glm::mat3& to_view, const glm::vec3& forward,
                     const glm::vec3 (&planes)[4], float near, int soft_override, float min_px, const OverdrawFrame& frame);
  int small_left_out_ = 0;  // per particle: left out for their size before the budget (OverdrawOptions::min_px)
  void sort(RenderSettings::Sorting sorting, const glm::vec3& forward);
  void mark_depth_reads(int width, int height);  // depth_reads from boxes_
  std::vector<ScreenBox> boxes_, sorted_boxes_;  // screen boxes of `particles` (the budget's estimate)
  std::vector<uint32_t> keys_, order_;  // depth keys of `particles`, and the sorted order
  std::vector<ParticleInstance> sorted_;
  std::vector<float> sorted_areas_;
  OverdrawBudget budget_;  // keeps its smoothing from frame to frame
  OccluderSet occluders_;
  bool any_ordered_ = false;  // some kept particle has alpha·(1 − burn) > 0
};

// An order-preserving map from float to unsigned: larger floats give larger keys.
uint32_t sortable_bits(float f);

// Back-to-front order by 32-bit depth keys (larger distance first), an LSD radix sort in
// four 8-bit passes; stable, so equal keys keep their input order.
void radix_sort_back_to_front(const std::vector<uint32_t>& keys, std::vector<uint32_t>& order);

}  // namespace arc
