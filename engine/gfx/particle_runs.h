// gfx/particle_runs.h — the particle draw split into runs by shader variant (no GL).
//
// llvmpipe runs every instruction of a fragment shader on every pixel, branches included, so a
// single draw with the soft-edge program makes every particle pixel pay the depth-copy read as
// soon as one particle needs it. Instead the sorted batch is drawn as a few runs, each a span of
// consecutive particles (back to front) drawn with one program: the hard one for particles whose
// soft factor is exactly 1 (method off, or kSoftClear: no mesh within reach), the soft one
// (with the contrast curve when a particle of the run uses it) for the rest, and the picture is
// the one-draw picture.
//
// The order matters only between particles that share a pixel, and not between two pure
// additive ones (alpha·(1 − burn) = 0: they commute). So each particle goes to the earliest
// run of its kind that comes at or after the run of every earlier particle it must follow:
// one whose screen box shares a cell of a 32 × 18 grid with its own, unless both are pure
// additive. Effects in different parts of the screen then do not interleave their soft and
// hard particles, and each pixel still sees its blends in the batch's order. And because a
// clear particle drawn with the soft program gets the same factor 1, the smallest hard runs
// (by estimated pixels) are folded into their soft neighbours until at most `max_runs` remain:
// each is a draw call and a program switch, which costs more than a few thousand pixels'
// depth reads.
//
// Example, compiled as GfxCpuExamples.GroupRuns in tests/unit/gfx/test_gfx_cpu_examples.cpp:
//   std::vector<ParticleRun> runs;
//   group_runs(particles, areas, boxes, /*max_runs=*/24, runs);
//   for (auto& r : runs) draw(r.first, r.count, r.soft ? soft[r.contrast][r.density_extent] : hard);
#pragma once
#include <cstdint>
#include <vector>

#include "gfx/particle_coverage.h"
#include "particles/render_output.h"

namespace arc {

struct ParticleRun {
  uint32_t first = 0, count = 0;  // a span of the batch
  bool soft = false;              // drawn with a soft-edge program (reads the depth copy)
  bool contrast = false;          // a particle of the run uses the contrast curve
  bool density_extent = false;    // a particle of the run uses density extent (its texture-alpha range)
  double pixels = 0;              // estimated blended pixels of the run
};

// Soft factor possibly below 1: a soft method and not flagged kSoftClear.
bool needs_depth(const ParticleInstance& p);

// Whether some particles need the depth read and others do not (group_runs has more to do
// than make one run).
bool mixed_programs(const std::vector<ParticleInstance>& particles);

// Reorders particles and areas into runs as above and fills `runs`: at most max(max_runs, 1).
// boxes[i] is particles[i]'s screen box; with no boxes every particle shares every pixel (only
// pure additive ones move). Hard runs under `min_hard_pixels` are folded into their soft
// neighbours first, then the smallest others until the count is met.
void group_runs(std::vector<ParticleInstance>& particles, std::vector<float>& areas, const std::vector<ScreenBox>& boxes,
                int max_runs, std::vector<ParticleRun>& runs, double min_hard_pixels = 4096.0);

}  // namespace arc
