// gfx/overdraw_budget.h — a screen-space budget for particle blending (no GL).
//
// A software rasteriser blends a few full-screen layers per 60 Hz frame in all (DESIGN.md:
// about six on llvmpipe with two cores), and the particles that cost most are the ones at the
// player's eye: a shield a few metres from the cockpit, impact glows, the flares of a beam
// passing the camera. Before the particle draw, OverdrawBudget estimates each particle's
// blended area on screen (its quad as particle.vert builds it, size clamp included, clipped to
// the screen) and, when the frame's total exceeds render.overdraw_budget screen layers, caps
// the on-screen half-size of the largest contributors:
//
//   cap_px(particle) = k · screen height · weight(screen priority) · max(1, (distance / near)²)
//
// where each frame solves by bisection for the k at which the estimated total meets the
// budget. A particle above its cap is shrunk to it (an axis-locked lightning segment is
// thinned: its width shrinks, its length stays) and faded by (cap / size)^γ(priority). Low
// priority (sparks, debris) has the smallest weight and is dropped once shrunk below 1/512
// of its size (less than a pixel: no pop); normal (shields, smoke, trails) has a middle
// weight; both shrink with a little fade (γ 1/4). High (beams, fireballs: γ 0) has the
// largest weight and only shrinks. So sparks go before shields and smoke, and those before
// beams. Shrinking with little fade keeps the picture closest (the bench's PSNR of budgeted
// against unbudgeted frames): a near particle's faint rim goes, its core stays. Fading
// removes no pixel, so it buys no time and only dims the picture (a stronger fade scores a
// lower PSNR for the same layers and drops). The distance term makes the reduction fall off
// smoothly beyond `near` metres: it is the near-camera particles that shrink first. A faint
// particle (little light added or blocked) is capped before a strong one.
//
// Each cluster keeps its own k, which moves toward the frame's solution in log space with a
// time constant and a rate limit (0.08 s and 12 e-folds a second toward more reduction, 0.12 s
// and 8 toward less: at 60 Hz no particle shrinks by more than 18 % from one frame to the
// next, nor grows back by more than 14 %), by the view's game time, so nothing pops. The way
// back is nearly as quick as the way in, so frames under budget after an explosion's peak do
// not stay reduced.
// A cluster that was not drawn the frame before (an explosion's first frame) has no size to
// jump from: it starts at the frame's solution and then follows it like the rest. A cluster
// whose k binds none of its particles keeps it at its largest on-screen particle's threshold,
// the highest k that changes nothing: k above that is unseen, and walking it down at the rate
// limit would only delay the reduction (from the no-budget k to a growing explosion's
// threshold took 13 frames) while the frame runs over budget. From there the rate limit still
// bounds every particle's shrink (one uncapped at threshold T keeps its size down to k = T,
// and k moves 18 % a frame at most), and when the solution rises above it k follows at once,
// since nothing was capped to grow back. A frame that stands still in time keeps the caps; one
// that jumps back or by more than half a second starts every cluster from the solution.
//
// Example, compiled as GfxCpuExamples.OverdrawBudget in tests/unit/gfx/test_gfx_cpu_examples.cpp:
//   OverdrawBudget budget;
//   OverdrawStats s = budget.apply(particles, areas, frame, {.budget_layers = 3, .near = 40});
//   // particles: shrunk, faded and thinned in place; areas[i]: each one's blended pixels after it
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/mat3x3.hpp>

#include "gfx/particle_coverage.h"
#include "gfx/sprite_trim.h"
#include "particles/render_output.h"

namespace arc {

struct OverdrawFrame {
  glm::mat3 to_view{1.0f};   // world → view rotation (particles are camera-relative)
  float tan_half_y = 0.5f;   // tan(fov_y / 2)
  float near = 0.5f;         // near plane, m
  float size_clamp = 0.5f;   // render.particle_size_clamp, as particle.vert applies it
  int width = 1, height = 1; // scene pixels
  double time_seconds = 0;   // RenderView::time_seconds
  // Quads cut to their sprites' boxes (sprite_trim.h), as particle.vert draws them: each
  // particle's area is its box's share of the quad, taken at its unreduced size.
  const SpriteTrim* trim = nullptr;
  TrimMode trim_mode = TrimMode::Off;
  int trim_height = 1;  // pixel rows of the target the particles are drawn into (its level of detail)
};

struct OverdrawOptions {
  float budget_layers = 0.0f;  // 0: no budget (areas are still estimated)
  float near = 40.0f;          // m
  // Below high screen priority, a particle whose on-screen extent (half its longest side) is
  // under min_px pixels is left out (before the solve, so the budget is spent on what is drawn),
  // and one under twice that fades toward it, so a particle shrinking or receding past it goes
  // without a pop. A software rasteriser pays for every particle drawn, however small; the
  // frame-time target sets it (frame_time_target.h). 0: none.
  float min_px = 0.0f;
};

struct OverdrawStats {
  double estimated_layers = 0;  // Σ blended pixels ÷ screen pixels before any reduction
  double budgeted_layers = 0;   // the same after it
  int reduced = 0;              // particles shrunk or faded
  int dropped = 0;              // particles faded to nothing and left out
  double cap = 0;               // k this frame (0: no reduction)
};

// Weights and fade exponents per ScreenPriority (Low, Normal, High).
constexpr float kOverdrawWeight[3] = {0.5f, 0.75f, 1.0f};
constexpr float kOverdrawFadeGamma[3] = {0.25f, 0.25f, 0.0f};
constexpr float kOverdrawDropRatio = 1.0f / 512.0f;  // a low-priority particle shrunk below this share goes

class OverdrawBudget {
 public:
  // Estimates, and reduces in place when over budget; `areas` gets each remaining particle's
  // estimated blended pixels, in the order of `particles` (dropped ones are erased from both),
  // and `boxes`, when given, each one's screen box: its quad cut to its trim box, or for one the
  // budget reduced the whole quad before the reduction (which only shrinks it).
  OverdrawStats apply(std::vector<ParticleInstance>& particles, std::vector<float>& areas, const OverdrawFrame& frame,
                      const OverdrawOptions& options, std::vector<ScreenBox>* boxes = nullptr);
  // Marks the screen box of every particle the last apply() was given (its quad cut to its trim
  // box, or the whole quad before any reduction when the budget reduced it): the tiles the
  // frame's particles can touch.
  void mark_coverage(ParticleCoverage& coverage) const;
  // Forgets the smoothing (the next frame starts from its own solution).
  void reset() { has_state_ = false; }
  // Whether apply() with this min_px leaves the particle out for its size (the same test, so a
  // caller may leave it out before and count it as dropped): below high screen priority and
  // under min_px pixels on screen.
  static bool below_min_px(const ParticleInstance& p, const OverdrawFrame& frame, float min_px);

 private:
  struct ClusterCap {
    uint32_t cluster;
    double log_k;
    double top;  // the largest threshold of its particles on screen this frame (0: none there)
    bool free;   // k binds none of them: it sits at that threshold
  };
  struct Footprint {
    float size;          // half-width, m, after particle.vert's size clamp
    float w_px;          // half-width on screen, pixels
    float half_axis_px;  // half the axis-locked segment's on-screen length, pixels (0: square)
    float frac;          // share of the quad's bounding box on screen
    float threshold;     // the k below which its cap binds
    float area;          // blended pixels unreduced
    float x, y, hx, hy;  // screen box: centre (GL window pixels, y up) and half-extents, unreduced
    // The trim box in the quad's own axes (across, along), each in [−1, 1]: it keeps
    // (trim_a1 − trim_a0)/2 of the width and (trim_b1 − trim_b0)/2 of the length. Then the screen
    // box of the quad cut to it: what is drawn when the budget leaves the particle as it is. A
    // reduced one is smaller but may take a coarser level's box, so it keeps the whole quad's box.
    float trim_a0, trim_a1, trim_b0, trim_b1;
    float tx, ty, thx, thy;
    bool reduced;        // shrunk, faded or dropped this frame
    bool past_near;      // axis-locked and may reach past the near plane: its projection is unbounded
    bool small;          // under OverdrawOptions::min_px: left out before the solve
  };
  // A particle's view-space centre and on-screen half-width and half segment length, as
  // particle.vert draws it (its size clamp included).
  struct ViewExtent {
    glm::vec3 c{0.0f};
    float d = 0, ppu = 0, size = 0, w_px = 0, half_axis_px = 0;
    glm::vec3 across{0.0f}, to_p{0.0f, 0.0f, -1.0f};  // an axis-locked one's segment across the view
  };
  static ViewExtent view_extent(const ParticleInstance& p, const OverdrawFrame& frame);
  static void set_facing_box(Footprint& f, const glm::vec3& c, float rotation, float ppu, const OverdrawFrame& frame);
  static void set_segment_box(Footprint& f, const glm::vec3& c, const glm::vec3& across, const glm::vec3& to_p,
                              const OverdrawFrame& frame);
  double area_at(uint32_t i, double k) const;
  double total_area(const std::vector<uint32_t>& set, double k) const;
  double solve(const std::vector<uint32_t>& set, double budget_px, double k_lo, double k_hi) const;
  double estimate(const std::vector<ParticleInstance>& particles, const OverdrawFrame& frame, float near_m, float min_px,
                  double& fixed);
  void update_caps(const std::vector<ParticleInstance>& particles, double target, double time_seconds);
  const ClusterCap* cap_of(uint32_t cluster) const;  // null when the cluster has none

  std::vector<Footprint> fp_;
  std::vector<uint32_t> candidates_;  // particles whose cap can bind at all
  std::vector<ClusterCap> caps_, next_caps_;  // by cluster id, sorted
  double last_time_ = 0;
  bool has_state_ = false;
};

}  // namespace arc
