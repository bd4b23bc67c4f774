// gfx/particle_runs.cpp — runs by shader variant under the order constraints, folding small hard runs (no GL).
#include "gfx/particle_runs.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "gfx/particle_occluders.h"

namespace arc {
namespace {

bool ordered(const ParticleInstance& p) { return p.color[3] * (1.0f - p.burn) > 0.0f; }

bool uses_contrast(const ParticleInstance& p) {
  return needs_depth(p) && (p.soft_edge & 0x7F) == uint8_t(SoftEdge::Contrast);
}

bool uses_density_extent(const ParticleInstance& p) {
  return needs_depth(p) && (p.soft_edge & 0x7F) == uint8_t(SoftEdge::DensityExtent);
}

// Adds a particle to a run: which soft variant the run needs, and its pixels.
void take(ParticleRun& r, const ParticleInstance& p, float area) {
  r.contrast = r.contrast || uses_contrast(p);
  r.density_extent = r.density_extent || uses_density_extent(p);
  r.pixels += area;
}

// The screen as a grid of cells for the order constraints: a particle must be drawn after
// every earlier one whose box shares a cell with its own, unless both are pure additive.
constexpr int kCellsX = 32, kCellsY = 18;

struct CellRange {
  int x0, y0, x1, y1;  // inclusive
};

CellRange cells_of(const ScreenBox& b) {
  auto cell = [](float v, int n) { return std::clamp(int(std::floor((v * 0.5f + 0.5f) * float(n))), 0, n - 1); };
  // NaN or unbounded boxes (whole screen) take every cell.
  if (!std::isfinite(b.x0) || !std::isfinite(b.y0) || !std::isfinite(b.x1) || !std::isfinite(b.y1))
    return {0, 0, kCellsX - 1, kCellsY - 1};
  return {cell(b.x0, kCellsX), cell(b.y0, kCellsY), cell(b.x1, kCellsX), cell(b.y1, kCellsY)};
}

// Gives each particle the earliest run it can take: runs alternate between the two programs
// (run 0 has the first particle's), and a particle's run is at or after the run of every
// earlier particle it must follow (one that shares a cell with it, unless both are pure
// additive). Particles of one run keep their order, so every pixel sees the blends it saw.
void assign_runs(const std::vector<ParticleInstance>& particles, const std::vector<ScreenBox>& boxes,
                 std::vector<uint32_t>& run_of) {
  const size_t n = particles.size();
  run_of.resize(n);
  const bool first_soft = needs_depth(particles[0]);
  std::vector<int> after_all(boxes.empty() ? 1 : kCellsX * kCellsY, -1);  // latest run of any particle
  std::vector<int> after_ordered(after_all.size(), -1);                   // latest run of an ordered one
  for (size_t i = 0; i < n; ++i) {
    const bool is_ordered = ordered(particles[i]);
    const std::vector<int>& must_follow = is_ordered ? after_all : after_ordered;
    const CellRange c = boxes.empty() ? CellRange{0, 0, 0, 0} : cells_of(boxes[i]);
    const int w = boxes.empty() ? 1 : kCellsX;
    int latest = 0;
    for (int y = c.y0; y <= c.y1; ++y)
      for (int x = c.x0; x <= c.x1; ++x) latest = std::max(latest, must_follow[size_t(y * w + x)]);
    const bool run_soft = first_soft == (latest % 2 == 0);
    const int run = run_soft == needs_depth(particles[i]) ? latest : latest + 1;
    run_of[i] = uint32_t(run);
    for (int y = c.y0; y <= c.y1; ++y)
      for (int x = c.x0; x <= c.x1; ++x) {
        const size_t k = size_t(y * w + x);
        after_all[k] = std::max(after_all[k], run);
        if (is_ordered) after_ordered[k] = std::max(after_ordered[k], run);
      }
  }
}

// Particles and areas put in run order, each run keeping the particles' order (a counting sort).
// Nothing moves when the runs are already in order. The copies are kept from call to call (per
// thread): a batch of thousands of particles is a few hundred kilobytes, which a fresh
// allocation would map and fault in every frame.
void order_by_run(std::vector<ParticleInstance>& particles, std::vector<float>& areas,
                  const std::vector<uint32_t>& run_of) {
  if (std::is_sorted(run_of.begin(), run_of.end())) return;
  const uint32_t runs = *std::max_element(run_of.begin(), run_of.end()) + 1;
  std::vector<uint32_t> start(runs + 1, 0);
  for (uint32_t r : run_of) ++start[r + 1];
  for (uint32_t r = 0; r < runs; ++r) start[r + 1] += start[r];
  thread_local std::vector<ParticleInstance> p;
  thread_local std::vector<float> a;
  p.resize(particles.size());
  a.resize(areas.size());
  for (size_t i = 0; i < particles.size(); ++i) {
    const uint32_t dst = start[run_of[i]]++;
    p[dst] = particles[i];
    a[dst] = areas[i];
  }
  particles.swap(p);
  areas.swap(a);
}

}  // namespace

bool needs_depth(const ParticleInstance& p) { return p.soft_edge != 0 && !(p.soft_edge & kSoftClear); }

bool mixed_programs(const std::vector<ParticleInstance>& particles) {
  return !particles.empty() && std::any_of(particles.begin(), particles.end(), [&](const ParticleInstance& p) {
    return needs_depth(p) != needs_depth(particles[0]);
  });
}

void group_runs(std::vector<ParticleInstance>& particles, std::vector<float>& areas, const std::vector<ScreenBox>& boxes,
                int max_runs, std::vector<ParticleRun>& runs, double min_hard_pixels) {
  runs.clear();
  if (particles.empty()) return;
  if (!mixed_programs(particles)) {  // one program for all: one run in the batch's order
    runs.push_back({0, uint32_t(particles.size()), needs_depth(particles[0])});
    for (size_t i = 0; i < particles.size(); ++i) take(runs[0], particles[i], areas[i]);
    return;
  }
  thread_local std::vector<uint32_t> run_of;
  assign_runs(particles, boxes, run_of);
  order_by_run(particles, areas, run_of);
  std::vector<ParticleRun> raw;
  for (size_t i = 0; i < particles.size(); ++i) {
    const bool soft = needs_depth(particles[i]);
    if (raw.empty() || raw.back().soft != soft) raw.push_back({uint32_t(i), 0, soft});
    ++raw.back().count;
    take(raw.back(), particles[i], areas[i]);
  }
  // Runs alternate hard and soft, so folding a hard run into the soft program joins it with
  // each neighbour it has: the count drops by one or two.
  std::vector<size_t> hard;
  for (size_t r = 0; r < raw.size(); ++r)
    if (!raw[r].soft) hard.push_back(r);
  std::stable_sort(hard.begin(), hard.end(), [&](size_t a, size_t b) { return raw[a].pixels < raw[b].pixels; });
  size_t count = raw.size();
  const size_t limit = size_t(std::max(max_runs, 1));
  std::vector<bool> fold(raw.size(), false);
  for (size_t h : hard) {
    if (count <= 1 || (count <= limit && raw[h].pixels >= min_hard_pixels)) break;
    fold[h] = true;
    count -= size_t(h > 0) + size_t(h + 1 < raw.size());
  }
  for (size_t r = 0; r < raw.size(); ++r) {
    const bool soft = raw[r].soft || fold[r];
    if (!runs.empty() && runs.back().soft == soft) {
      ParticleRun& last = runs.back();
      last.count += raw[r].count;
      last.contrast = last.contrast || raw[r].contrast;
      last.density_extent = last.density_extent || raw[r].density_extent;
      last.pixels += raw[r].pixels;
    } else {
      runs.push_back(raw[r]);
      runs.back().soft = soft;
    }
  }
}

}  // namespace arc
