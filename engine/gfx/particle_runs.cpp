// gfx/particle_runs.cpp — additive regrouping, runs by shader variant, folding small hard runs (no GL).
#include "gfx/particle_runs.h"

#include <algorithm>
#include <numeric>

#include "gfx/particle_occluders.h"

namespace arc {
namespace {

bool ordered(const ParticleInstance& p) { return p.color[3] * (1.0f - p.burn) > 0.0f; }

bool uses_contrast(const ParticleInstance& p) {
  return needs_depth(p) && (p.soft_edge & 0x7F) == uint8_t(SoftEdge::Contrast);
}

// Within each stretch of pure additive particles, those of `first` kind (soft or hard) come
// first: the previous particle's kind, or when the stretch opens the batch, the kind the next
// particle does not have.
void regroup_additive(std::vector<ParticleInstance>& particles, std::vector<float>& areas) {
  std::vector<ParticleInstance> tail;
  std::vector<float> tail_areas;
  const size_t n = particles.size();
  for (size_t i = 0; i < n;) {
    if (ordered(particles[i])) {
      ++i;
      continue;
    }
    size_t j = i;
    while (j < n && !ordered(particles[j])) ++j;
    const bool first = i > 0 ? needs_depth(particles[i - 1]) : j < n ? !needs_depth(particles[j]) : false;
    tail.clear();
    tail_areas.clear();
    size_t out = i;
    for (size_t k = i; k < j; ++k) {
      if (needs_depth(particles[k]) == first) {
        particles[out] = particles[k];
        areas[out++] = areas[k];
      } else {
        tail.push_back(particles[k]);
        tail_areas.push_back(areas[k]);
      }
    }
    std::copy(tail.begin(), tail.end(), particles.begin() + std::ptrdiff_t(out));
    std::copy(tail_areas.begin(), tail_areas.end(), areas.begin() + std::ptrdiff_t(out));
    i = j;
  }
}

}  // namespace

bool needs_depth(const ParticleInstance& p) { return p.soft_edge != 0 && !(p.soft_edge & kSoftClear); }

void group_runs(std::vector<ParticleInstance>& particles, std::vector<float>& areas, int max_runs,
                std::vector<ParticleRun>& runs, double min_hard_pixels) {
  runs.clear();
  if (particles.empty()) return;
  regroup_additive(particles, areas);
  std::vector<ParticleRun> raw;
  for (size_t i = 0; i < particles.size(); ++i) {
    const bool soft = needs_depth(particles[i]);
    if (raw.empty() || raw.back().soft != soft) raw.push_back({uint32_t(i), 0, soft, false, 0.0});
    ParticleRun& r = raw.back();
    ++r.count;
    r.contrast = r.contrast || uses_contrast(particles[i]);
    r.pixels += areas[i];
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
      last.pixels += raw[r].pixels;
    } else {
      runs.push_back(raw[r]);
      runs.back().soft = soft;
    }
  }
}

}  // namespace arc
