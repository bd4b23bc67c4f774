// gfx/overdraw_budget.cpp — blended-area estimate, the per-frame cap and its smoothing (no GL).
#include "gfx/overdraw_budget.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace arc {
namespace {

constexpr double kMinCap = 1e-4;          // smallest k: a 0.07-pixel half-size at 720 lines
constexpr double kAttackSeconds = 0.08;   // time constant toward more reduction
constexpr double kReleaseSeconds = 0.12;  // and toward less
constexpr double kAttackRate = 12.0;      // at most this many e-folds of k per second (about 18 %
constexpr double kReleaseRate = 8.0;      // of a particle's size per 60 Hz frame) and back (14 %)
constexpr double kRestartSeconds = 0.5;   // a longer step (or one back) starts afresh

float overlap(float centre, float half, float size) {
  return std::max(0.0f, std::min(centre + half, size) - std::max(centre - half, 0.0f));
}

// One step of a cluster's log k toward the frame's solution: attack fast, release slower.
double step_toward(double log_k, double log_target, double dt) {
  const bool attack = log_target < log_k;
  const double step = (log_target - log_k) * (1.0 - std::exp(-dt / (attack ? kAttackSeconds : kReleaseSeconds)));
  const double most = (attack ? kAttackRate : kReleaseRate) * dt;
  return log_k + std::clamp(step, -most, most);
}

}  // namespace

double OverdrawBudget::area_at(uint32_t i, double k) const {
  const Footprint& f = fp_[i];
  const float r = float(std::min(1.0, k / double(f.threshold)));
  return double(f.frac) * double(r * f.w_px * (f.trim_a1 - f.trim_a0)) *
         double((f.half_axis_px + r * f.w_px) * (f.trim_b1 - f.trim_b0));
}

double OverdrawBudget::total_area(const std::vector<uint32_t>& set, double k) const {
  double sum = 0;
  for (uint32_t i : set) sum += area_at(i, k);
  return sum;
}

// The largest k in [k_lo, k_hi] whose total over `set` meets budget_px (k_lo when none does).
double OverdrawBudget::solve(const std::vector<uint32_t>& set, double budget_px, double k_lo, double k_hi) const {
  if (total_area(set, k_hi) <= budget_px) return k_hi;
  if (total_area(set, k_lo) > budget_px) return k_lo;
  double lo = std::log(k_lo), hi = std::log(k_hi);
  for (int it = 0; it < 24; ++it) {
    const double mid = 0.5 * (lo + hi);
    (total_area(set, std::exp(mid)) > budget_px ? hi : lo) = mid;
  }
  return std::exp(lo);
}

const OverdrawBudget::ClusterCap* OverdrawBudget::cap_of(uint32_t cluster) const {
  auto it = std::lower_bound(caps_.begin(), caps_.end(), cluster,
                             [](const ClusterCap& c, uint32_t id) { return c.cluster < id; });
  return it != caps_.end() && it->cluster == cluster ? &*it : nullptr;
}

// A camera-facing quad lies in the view plane at its centre's depth (particle.vert turns it
// there), so its screen box is exact: the centre projected, half-widths grown by the rotation's
// |cos| + |sin|; the trimmed quad's box the same for its part of the quad, off centre.
void OverdrawBudget::set_facing_box(Footprint& f, const glm::vec3& c, float rotation, float ppu, const OverdrawFrame& frame) {
  const float cs = std::cos(rotation), sn = std::sin(rotation);
  f.x = 0.5f * float(frame.width) + c.x * ppu;
  f.y = 0.5f * float(frame.height) + c.y * ppu;
  f.hx = f.hy = f.w_px * (std::abs(cs) + std::abs(sn));
  const float ma = 0.5f * (f.trim_a0 + f.trim_a1) * f.w_px, mb = 0.5f * (f.trim_b0 + f.trim_b1) * f.w_px;
  const float ha = 0.5f * (f.trim_a1 - f.trim_a0) * f.w_px, hb = 0.5f * (f.trim_b1 - f.trim_b0) * f.w_px;
  f.tx = f.x + ma * cs - mb * sn;
  f.ty = f.y + ma * sn + mb * cs;
  f.thx = std::abs(cs) * ha + std::abs(sn) * hb;
  f.thy = std::abs(sn) * ha + std::abs(cs) * hb;
  f.past_near = false;
}

// An axis-locked quad tilts in depth along its segment, so its four corners (as particle.vert
// places them) are projected one by one; a corner at or behind the near plane leaves the box
// unbounded.
void OverdrawBudget::set_segment_box(Footprint& f, const glm::vec3& c, const glm::vec3& across, const glm::vec3& to_p,
                                     const OverdrawFrame& frame) {
  const float a_len = glm::length(across);
  const glm::vec3 up = across / a_len;
  const glm::vec3 right = glm::normalize(glm::cross(up, to_p));
  const float half_long = 0.5f * a_len + f.size;
  const float focal = 0.5f * float(frame.height) / std::max(frame.tan_half_y, 1e-6f);
  f.past_near = false;
  // The box of the quad's part [a0, a1] across × [b0, b1] along (in [−1, 1]).
  auto box = [&](float a0, float a1, float b0, float b1, float& x, float& y, float& hx, float& hy) {
    float x0 = 1e30f, x1 = -1e30f, y0 = 1e30f, y1 = -1e30f;
    for (int k = 0; k < 4; ++k) {
      const glm::vec3 q = c + right * (((k & 1) ? a1 : a0) * f.size) + up * (((k & 2) ? b1 : b0) * half_long);
      if (!(-q.z > frame.near)) f.past_near = true;
      const float s = focal / std::max(-q.z, 1e-6f);
      x0 = std::min(x0, q.x * s);
      x1 = std::max(x1, q.x * s);
      y0 = std::min(y0, q.y * s);
      y1 = std::max(y1, q.y * s);
    }
    x = 0.5f * float(frame.width) + 0.5f * (x0 + x1);
    y = 0.5f * float(frame.height) + 0.5f * (y0 + y1);
    hx = 0.5f * (x1 - x0);
    hy = 0.5f * (y1 - y0);
  };
  box(-1.0f, 1.0f, -1.0f, 1.0f, f.x, f.y, f.hx, f.hy);
  box(f.trim_a0, f.trim_a1, f.trim_b0, f.trim_b1, f.tx, f.ty, f.thx, f.thy);
}

OverdrawBudget::ViewExtent OverdrawBudget::view_extent(const ParticleInstance& p, const OverdrawFrame& frame) {
  ViewExtent e;
  const float tan_y = std::max(frame.tan_half_y, 1e-6f);
  e.c = frame.to_view * glm::vec3(p.pos[0], p.pos[1], p.pos[2]);
  e.d = std::max(-e.c.z, frame.near);
  e.ppu = 0.5f * float(frame.height) / (e.d * tan_y);
  e.size = std::min(std::max(p.size, 1e-6f), std::max(frame.size_clamp * e.d * tan_y, 1e-6f));
  e.w_px = e.size * e.ppu;
  if (p.billboard == uint8_t(Billboard::AxisLocked)) {
    // particle.vert: the part of the segment seen across the view sets the quad's length.
    const glm::vec3 a = frame.to_view * glm::vec3(p.axis[0], p.axis[1], p.axis[2]);
    const float len_c = glm::length(e.c);
    if (len_c > 1e-6f) e.to_p = e.c / len_c;
    e.across = a - glm::dot(a, e.to_p) * e.to_p;
    const float a_len = glm::length(e.across);
    if (a_len > 1e-6f * std::max(1.0f, glm::length(a))) e.half_axis_px = 0.5f * a_len * e.ppu;
  }
  return e;
}

bool OverdrawBudget::below_min_px(const ParticleInstance& p, const OverdrawFrame& frame, float min_px) {
  if (!(min_px > 0.0f) || p.screen_priority >= uint8_t(ScreenPriority::High)) return false;
  const ViewExtent e = view_extent(p, frame);
  return e.w_px + e.half_axis_px < min_px;
}

// The footprint of every particle (fp_), the candidates whose cap can bind, and the area of
// the rest; returns the estimated blended pixels. One under min_px is left out here, before the
// solve: the budget is spent on what is drawn.
double OverdrawBudget::estimate(const std::vector<ParticleInstance>& particles, const OverdrawFrame& frame,
                                float near_m, float min_px, double& fixed) {
  const float W = float(frame.width), H = float(frame.height);
  const double screen = double(W) * double(H);
  const float tan_y = std::max(frame.tan_half_y, 1e-6f);
  fp_.resize(particles.size());
  candidates_.clear();
  fixed = 0;
  double total = 0;
  for (size_t i = 0; i < particles.size(); ++i) {
    const ParticleInstance& p = particles[i];
    const ViewExtent e = view_extent(p, frame);
    const glm::vec3& c = e.c;
    const float d = e.d, ppu = e.ppu;  // ppu: pixels per metre at this depth
    Footprint& f = fp_[i];
    f.size = e.size;
    f.w_px = e.w_px;
    f.half_axis_px = e.half_axis_px;
    f.small = min_px > 0.0f && p.screen_priority < uint8_t(ScreenPriority::High) && f.w_px + f.half_axis_px < min_px;
    if (f.small) {
      f.area = 0.0f, f.reduced = true, f.past_near = false;
      continue;
    }
    glm::vec2 dir(0.0f, 1.0f);
    const glm::vec3 across = e.across, to_p = e.to_p;
    if (f.half_axis_px > 0.0f) {
      const float xy = std::hypot(across.x, across.y);
      if (xy > 1e-12f) dir = glm::vec2(across.x, across.y) / xy;
    }
    const float len = f.half_axis_px + f.w_px;
    f.trim_a0 = f.trim_b0 = -1.0f;
    f.trim_a1 = f.trim_b1 = 1.0f;
    f.reduced = false;
    if (frame.trim && frame.trim_mode != TrimMode::Off) {
      const float lod_scale = frame.trim->lod_scale(tan_y, frame.trim_height);
      const float depth = f.half_axis_px > 0.0f ? SpriteTrim::segment_depth(glm::length(c), f.size, len / ppu, frame.near)
                                                : SpriteTrim::facing_depth(-c.z, frame.near);
      const TrimBox b = frame.trim->box(frame.trim_mode, p.sprite, lod_scale, f.size, depth);
      // particle.vert: corner (2u − 1, 1 − 2v) along (right, up).
      f.trim_a0 = 2.0f * b.u0 - 1.0f, f.trim_a1 = 2.0f * b.u1 - 1.0f;
      f.trim_b0 = 1.0f - 2.0f * b.v1, f.trim_b1 = 1.0f - 2.0f * b.v0;
    }
    const float hx = std::abs(dir.x) * len + std::abs(dir.y) * f.w_px;
    const float hy = std::abs(dir.y) * len + std::abs(dir.x) * f.w_px;
    if (f.half_axis_px > 0.0f) set_segment_box(f, c, across, to_p, frame);
    else set_facing_box(f, c, p.rotation, ppu, frame);
    const float sx = 0.5f * W + c.x * ppu, sy = 0.5f * H - c.y * ppu;
    const float box = std::max(4.0f * hx * hy, 1e-12f);
    f.frac = std::min(1.0f, overlap(sx, hx, W) * overlap(sy, hy, H) / box);
    f.area = float(std::min(double(f.frac) * double(f.w_px * (f.trim_a1 - f.trim_a0)) * double(len * (f.trim_b1 - f.trim_b0)), screen));
    const int prio = std::min<int>(p.screen_priority, 2);
    const float g = std::max(1.0f, (d / near_m) * (d / near_m));
    // What the particle does to a pixel: the light it adds (rgb is premultiplied) or the
    // light it blocks; a faint one is capped before a strong one of the same priority.
    const float strength = std::max({p.color[0], p.color[1], p.color[2], p.color[3] * (1.0f - p.burn)});
    const float visible = std::clamp(0.25f + strength, 0.25f, 1.25f);
    f.threshold = f.w_px / (H * kOverdrawWeight[prio] * visible * g);
    total += f.area;
    if (f.threshold > kMinCap && f.area > 0.0f) candidates_.push_back(uint32_t(i));
    else fixed += f.area;
  }
  return total;
}

// Each cluster drawn before moves its cap toward the frame's solution; a cluster new this
// frame (nothing of it on screen to jump from) starts at the solution. Then a cap above every
// threshold of the cluster's on-screen particles comes down to the largest of them (see the
// header: the highest k that changes nothing).
void OverdrawBudget::update_caps(const std::vector<ParticleInstance>& particles, double target, double time_seconds) {
  const double dt = time_seconds - last_time_;
  const bool continuing = has_state_ && dt >= 0.0 && dt <= kRestartSeconds;
  next_caps_.clear();
  // A cluster's particles mostly come together: one entry per stretch, then sorted and merged.
  for (size_t i = 0; i < particles.size(); ++i) {
    const double top = fp_[i].area > 0.0f ? double(fp_[i].threshold) : 0.0;
    if (next_caps_.empty() || next_caps_.back().cluster != particles[i].cluster)
      next_caps_.push_back({particles[i].cluster, 0.0, top, false});
    else next_caps_.back().top = std::max(next_caps_.back().top, top);
  }
  std::sort(next_caps_.begin(), next_caps_.end(), [](const ClusterCap& a, const ClusterCap& b) {
    return a.cluster < b.cluster || (a.cluster == b.cluster && a.top > b.top);
  });
  next_caps_.erase(std::unique(next_caps_.begin(), next_caps_.end(),
                               [](const ClusterCap& a, const ClusterCap& b) { return a.cluster == b.cluster; }),
                   next_caps_.end());
  const double lt = std::log(target);
  for (ClusterCap& c : next_caps_) {
    if (!(c.top > 0.0)) {  // nothing of it on screen: nothing seen to keep
      c.log_k = lt;
      c.free = true;
      continue;
    }
    const double log_top = std::log(c.top) + 1e-6;  // just above the largest threshold, past float rounding
    const ClusterCap* before = continuing ? cap_of(c.cluster) : nullptr;
    if (!before || (before->free && lt >= before->log_k)) c.log_k = lt;
    else c.log_k = dt > 0.0 ? step_toward(before->log_k, lt, dt) : before->log_k;
    c.free = c.log_k >= log_top;
    if (c.free) c.log_k = log_top;
  }
  caps_.swap(next_caps_);
  has_state_ = true;
  last_time_ = time_seconds;
}

OverdrawStats OverdrawBudget::apply(std::vector<ParticleInstance>& particles, std::vector<float>& areas,
                                    const OverdrawFrame& frame, const OverdrawOptions& o, std::vector<ScreenBox>* boxes) {
  OverdrawStats s;
  const double screen = double(frame.width) * double(frame.height);
  double fixed = 0;
  s.estimated_layers = estimate(particles, frame, std::max(o.near, 1e-3f), o.min_px, fixed) / screen;
  const double k_none = std::max(4.0 * double(frame.size_clamp), 1e-2);  // above every threshold
  const bool budgeted = o.budget_layers > 0.0f;
  const double budget_px = std::max(0.0, double(o.budget_layers) * screen - fixed);
  const double target = budgeted ? solve(candidates_, budget_px, kMinCap, k_none) : k_none;
  update_caps(particles, target, frame.time_seconds);
  s.cap = target < k_none * 0.999 ? target : 0.0;

  areas.resize(particles.size());
  if (boxes) boxes->clear();
  // Screen boxes in units of half the screen, a pixel wider each way than the estimate.
  const float to_x = 2.0f / float(frame.width), to_y = 2.0f / float(frame.height);
  const float inf = std::numeric_limits<float>::infinity();
  size_t kept = 0;
  uint32_t cluster = 0;
  double k = k_none;
  for (size_t i = 0; i < particles.size(); ++i) {
    ParticleInstance p = particles[i];
    Footprint& f = fp_[i];
    float area = f.area;
    if (i == 0 || p.cluster != cluster) {  // a cluster's particles come together: one look-up each
      cluster = p.cluster;
      // A free cap binds nothing on screen, and off it nothing is seen: the cluster is left whole.
      const ClusterCap* c = cap_of(cluster);
      k = c && !c->free ? std::exp(c->log_k) : k_none;
    }
    if (f.small) {
      ++s.reduced, ++s.dropped;
      continue;
    }
    if (o.min_px > 0.0f && p.screen_priority < uint8_t(ScreenPriority::High)) {
      const float extent = f.w_px + f.half_axis_px;
      if (extent < 2.0f * o.min_px) {
        const float fade = extent / o.min_px - 1.0f;
        for (float& ch : p.color) ch *= fade;
        ++s.reduced;
      }
    }
    if (k < k_none * 0.999 && double(f.threshold) > k) {
      const float r = float(k / double(f.threshold));
      ++s.reduced;
      f.reduced = true;
      if (p.screen_priority == uint8_t(ScreenPriority::Low) && r < kOverdrawDropRatio) {
        ++s.dropped;
        continue;
      }
      const float fade = std::pow(r, kOverdrawFadeGamma[std::min<int>(p.screen_priority, 2)]);
      p.size = f.size * r;
      for (float& ch : p.color) ch *= fade;
      area = float(std::min(area_at(uint32_t(i), k), screen));
    }
    s.budgeted_layers += area;
    if (boxes && f.past_near) boxes->push_back({-inf, -inf, inf, inf});
    else if (boxes) {
      const float x = f.reduced ? f.x : f.tx, y = f.reduced ? f.y : f.ty;
      const float hx = f.reduced ? f.hx : f.thx, hy = f.reduced ? f.hy : f.thy;
      boxes->push_back({(x - hx - 1.0f) * to_x - 1.0f, (y - hy - 1.0f) * to_y - 1.0f, (x + hx + 1.0f) * to_x - 1.0f,
                        (y + hy + 1.0f) * to_y - 1.0f});
    }
    areas[kept] = area;
    particles[kept++] = p;
  }
  particles.resize(kept);
  areas.resize(kept);
  s.budgeted_layers /= screen;
  return s;
}

void OverdrawBudget::mark_coverage(ParticleCoverage& coverage) const {
  for (const Footprint& f : fp_) {
    if (f.small) continue;  // left out: nothing of it is drawn
    if (f.past_near) coverage.add_whole_screen();
    else if (f.reduced) coverage.add_box(f.x, f.y, f.hx, f.hy);
    else coverage.add_box(f.tx, f.ty, f.thx, f.thy);
  }
}

}  // namespace arc
