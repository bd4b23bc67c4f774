// gfx/overdraw_budget.cpp — blended-area estimate, the per-frame cap and its smoothing (no GL).
#include "gfx/overdraw_budget.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace arc {
namespace {

constexpr double kMinCap = 1e-4;          // smallest k: a 0.07-pixel half-size at 720 lines
constexpr double kAttackSeconds = 0.08;   // time constant toward more reduction
constexpr double kReleaseSeconds = 0.3;   // and toward less
constexpr double kAttackRate = 12.0;      // at most this many e-folds of k per second (about 18 %
constexpr double kReleaseRate = 4.0;      // of a particle's size per 60 Hz frame) and back
constexpr double kRestartSeconds = 0.5;   // a longer step (or one back) starts afresh
constexpr float kDropFade = 1.0f / 512.0f;

float overlap(float centre, float half, float size) {
  return std::max(0.0f, std::min(centre + half, size) - std::max(centre - half, 0.0f));
}

}  // namespace

double OverdrawBudget::total_area(double k) const {
  double sum = 0;
  for (uint32_t i : candidates_) {
    const Footprint& f = fp_[i];
    const float r = float(std::min(1.0, k / double(f.threshold)));
    sum += double(f.frac) * 4.0 * double(r * f.w_px) * double(f.half_axis_px + r * f.w_px);
  }
  return sum;
}

// The largest k whose total meets the budget (the candidates' share of it).
double OverdrawBudget::solve(double budget_px, double k_none) const {
  if (total_area(k_none) <= budget_px) return k_none;
  double lo = std::log(kMinCap), hi = std::log(k_none);
  if (total_area(kMinCap) > budget_px) return kMinCap;
  for (int it = 0; it < 24; ++it) {
    const double mid = 0.5 * (lo + hi);
    (total_area(std::exp(mid)) > budget_px ? hi : lo) = mid;
  }
  return std::exp(lo);
}

// Long: one pass estimates every particle's footprint, the solve and the smoothing follow, and
// a last pass applies the caps; splitting it would hand the footprints around for no gain.
OverdrawStats OverdrawBudget::apply(std::vector<ParticleInstance>& particles, std::vector<float>& areas,
                                    const OverdrawFrame& frame, const OverdrawOptions& o) {
  OverdrawStats s;
  const float W = float(frame.width), H = float(frame.height);
  const double screen = double(W) * double(H);
  const float tan_y = std::max(frame.tan_half_y, 1e-6f);
  const float near_m = std::max(o.near, 1e-3f);
  fp_.resize(particles.size());
  areas.resize(particles.size());
  candidates_.clear();
  double fixed = 0;  // the area of particles no cap can reach
  for (size_t i = 0; i < particles.size(); ++i) {
    const ParticleInstance& p = particles[i];
    const glm::vec3 c = frame.to_view * glm::vec3(p.pos[0], p.pos[1], p.pos[2]);
    const float d = std::max(-c.z, frame.near);
    const float ppu = 0.5f * H / (d * tan_y);  // pixels per metre at this depth
    const float size = std::min(std::max(p.size, 1e-6f), std::max(frame.size_clamp * d * tan_y, 1e-6f));
    Footprint& f = fp_[i];
    f.size = size;
    f.w_px = size * ppu;
    f.half_axis_px = 0;
    glm::vec2 dir(0.0f, 1.0f);
    if (p.billboard == uint8_t(Billboard::AxisLocked)) {
      // particle.vert: the part of the segment seen across the view sets the quad's length.
      const glm::vec3 a = frame.to_view * glm::vec3(p.axis[0], p.axis[1], p.axis[2]);
      const float len_c = glm::length(c);
      const glm::vec3 to_p = len_c > 1e-6f ? c / len_c : glm::vec3(0, 0, -1);
      const glm::vec3 across = a - glm::dot(a, to_p) * to_p;
      const float a_len = glm::length(across);
      if (a_len > 1e-6f * std::max(1.0f, glm::length(a))) {
        f.half_axis_px = 0.5f * a_len * ppu;
        const float xy = std::hypot(across.x, across.y);
        if (xy > 1e-12f) dir = glm::vec2(across.x, across.y) / xy;
      }
    }
    const float len = f.half_axis_px + f.w_px;
    const float hx = std::abs(dir.x) * len + std::abs(dir.y) * f.w_px;
    const float hy = std::abs(dir.y) * len + std::abs(dir.x) * f.w_px;
    const float sx = 0.5f * W + c.x * ppu, sy = 0.5f * H - c.y * ppu;
    const float box = std::max(4.0f * hx * hy, 1e-12f);
    f.frac = std::min(1.0f, overlap(sx, hx, W) * overlap(sy, hy, H) / box);
    f.area = float(std::min(double(f.frac) * 4.0 * double(f.w_px) * double(len), screen));
    const int prio = std::min<int>(p.screen_priority, 2);
    const float g = std::max(1.0f, (d / near_m) * (d / near_m));
    // What the particle does to a pixel: the light it adds (rgb is premultiplied) or the
    // light it blocks; a faint one is capped before a strong one of the same priority.
    const float strength = std::max({p.color[0], p.color[1], p.color[2], p.color[3] * (1.0f - p.burn)});
    const float visible = std::clamp(0.25f + strength, 0.25f, 1.25f);
    f.threshold = f.w_px / (H * kOverdrawWeight[prio] * visible * g);
    s.estimated_layers += f.area;
    if (f.threshold > kMinCap && f.area > 0.0f) candidates_.push_back(uint32_t(i));
    else fixed += f.area;
  }
  s.estimated_layers /= screen;
  const double k_none = std::max(4.0 * double(frame.size_clamp), 1e-2);  // above every threshold
  double target = k_none;
  if (o.budget_layers > 0.0f) target = solve(std::max(0.0, double(o.budget_layers) * screen - fixed), k_none);
  // Smoothing in log k by game time: attack fast, release slower; a still frame keeps k.
  const double dt = frame.time_seconds - last_time_;
  const double lt = std::log(target);
  if (!has_state_ || dt < 0.0 || dt > kRestartSeconds) log_k_ = lt;
  else if (dt > 0.0) {
    const bool attack = lt < log_k_;
    const double step = (lt - log_k_) * (1.0 - std::exp(-dt / (attack ? kAttackSeconds : kReleaseSeconds)));
    const double most = (attack ? kAttackRate : kReleaseRate) * dt;
    log_k_ += std::clamp(step, -most, most);
  }
  log_k_ = std::clamp(log_k_, std::log(kMinCap), std::log(k_none));
  has_state_ = true;
  last_time_ = frame.time_seconds;
  const double k = std::exp(log_k_);
  s.cap = k < k_none * 0.999 ? k : 0.0;

  size_t kept = 0;
  for (size_t i = 0; i < particles.size(); ++i) {
    ParticleInstance p = particles[i];
    const Footprint& f = fp_[i];
    float area = f.area;
    if (s.cap > 0.0 && double(f.threshold) > k) {
      const float r = float(k / double(f.threshold));
      const float fade = std::pow(r, kOverdrawFadeGamma[std::min<int>(p.screen_priority, 2)]);
      ++s.reduced;
      if (fade < kDropFade) {
        ++s.dropped;
        continue;
      }
      p.size = f.size * r;
      for (float& ch : p.color) ch *= fade;
      area = float(std::min(double(f.frac) * 4.0 * double(r * f.w_px) * double(f.half_axis_px + r * f.w_px), screen));
    }
    s.budgeted_layers += area;
    areas[kept] = area;
    particles[kept++] = p;
  }
  particles.resize(kept);
  areas.resize(kept);
  s.budgeted_layers /= screen;
  return s;
}

}  // namespace arc
