// gfx/particle_runs.h — the particle draw split into runs by shader variant (no GL).
//
// llvmpipe runs every instruction of a fragment shader on every pixel, branches included, so a
// single draw with the soft-edge program makes every particle pixel pay the depth-copy read as
// soon as one particle needs it. Instead the sorted batch is drawn as a few runs, each a span of
// consecutive particles (back to front) drawn with one program: the hard one for particles whose
// soft factor is exactly 1 (method off, or kSoftClear: no mesh within reach), the soft one
// (with the contrast curve when a particle of the run uses it) for the rest. The order of the
// draw is the batch's order, so the picture is the one-draw picture.
//
// Pure additive particles (alpha·(1 − burn) = 0) commute with each other, so within each
// stretch of them between two ordered particles they are regrouped: those of the previous
// run's kind first, those of the next run's kind last. And because a clear particle drawn with
// the soft program gets the same factor 1, the smallest hard runs (by estimated pixels) are
// folded into their soft neighbours until at most `max_runs` remain: each is a draw call and
// a program switch, which costs more than a few thousand pixels' depth reads.
//
//   std::vector<ParticleRun> runs;
//   group_runs(batch.particles, areas, /*max_runs=*/24, runs);
//   for (auto& r : runs) draw(r.first, r.count, r.soft ? (r.contrast ? contrast : soft) : hard);
#pragma once
#include <cstdint>
#include <vector>

#include "particles/render_output.h"

namespace arc {

struct ParticleRun {
  uint32_t first = 0, count = 0;  // a span of the batch
  bool soft = false;              // drawn with a soft-edge program (reads the depth copy)
  bool contrast = false;          // a particle of the run uses the contrast curve
  double pixels = 0;              // estimated blended pixels of the run
};

// Soft factor possibly below 1: a soft method and not flagged kSoftClear.
bool needs_depth(const ParticleInstance& p);

// Reorders pure additive particles within their stretches (particles and areas together) and
// fills `runs`: at most max(max_runs, 1). Hard runs under `min_hard_pixels` are folded into
// their soft neighbours first, then the smallest others until the count is met.
void group_runs(std::vector<ParticleInstance>& particles, std::vector<float>& areas, int max_runs,
                std::vector<ParticleRun>& runs, double min_hard_pixels = 4096.0);

}  // namespace arc
