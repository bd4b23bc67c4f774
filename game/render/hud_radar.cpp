// The radar: contacts around the followed ship, its range fitted to the nearest threats.
#include "game/render/hud_radar.h"

#include <algorithm>
#include <cmath>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "game/render/hud_draw.h"
#include "game/sim/world.h"

namespace arc {
namespace {

const glm::vec4 kRadarGrid{0.4f, 0.8f, 0.5f, 0.3f};

// The smallest 1, 2 or 5 × 10^n not below x.
double round_up_to_nice(double x) {
  if (!(x > 0)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= x * (1.0 - 1e-12)) return m * decade;
  return 10.0 * decade;
}

std::string range_label(double metres) {
  return metres >= 1000.0 ? fmt("%g km", metres / 1000.0) : fmt("%g m", metres);
}

// A contact at `local` (the ship's frame) as a dot of side `size`, clamped to the radar's edge.
RadarBlip blip(double cx, double cy, double half, const glm::dvec3& local, double range, double size,
               RadarBlipKind kind, bool target) {
  double x = local.x / range, y = local.z / range;
  const double len = std::sqrt(x * x + y * y);
  if (len > 1.0) x /= len, y /= len;
  // Above or below: a short tick shows the height, as in most space-sim radars.
  const double rise = std::clamp(local.y / range, -1.0, 1.0) * half * 0.5;
  return {{cx + x * half, cy + y * half}, size, rise, kind, target};
}

}  // namespace

// At the bottom right above the weapon lines, clear of the lower middle where the chase view
// draws the own ship.
HudRect radar_rect(double canvas_w, double canvas_h) {
  const double size = std::min(canvas_w, canvas_h) * 0.22, k = hud_height_scale(int(canvas_h));
  return {canvas_w - size - 12.0 * k, hud_weapon_top(int(canvas_h)) - 10.0 * k - size, size, size};
}

double radar_range(const World& w, const Ship& me, const HudRules& rules) {
  std::vector<double> threats;
  for (const Ship& s : w.ships)
    if (s.alive && s.id != me.id && w.hostile(me, s)) threats.push_back(glm::length(s.position - me.position));
  for (const Projectile& p : w.projectiles)
    if (p.target == me.id && p.kind == SecondaryWeapon::Missile) threats.push_back(glm::length(p.position - me.position));
  if (threats.empty()) return rules.radar_max_range;
  const size_t k = std::min(threats.size(), size_t(std::max(rules.radar_threats, 1))) - 1;
  std::nth_element(threats.begin(), threats.begin() + std::ptrdiff_t(k), threats.end());
  const double fitted = round_up_to_nice(threats[k] * rules.radar_margin);
  return std::clamp(fitted, rules.radar_min_range, std::max(rules.radar_min_range, rules.radar_max_range));
}

std::vector<RadarBlip> radar_blips(const World& w, const Ship& me, const HudRules& rules, double canvas_w,
                                   double canvas_h) {
  const HudRect r = radar_rect(canvas_w, canvas_h);
  const double cx = r.x + r.w * 0.5, cy = r.y + r.h * 0.5, half = r.w * 0.5;
  const double range = radar_range(w, me, rules);
  const glm::dquat inv = glm::conjugate(me.orientation);
  // Blips grow with the radar, never below 4 canvas units: a lone pixel reads as a star.
  const double dot = std::max(4.0, r.w * 0.035), target_dot = std::max(6.0, r.w * 0.06);
  std::vector<RadarBlip> out;
  for (const Ship& s : w.ships) {
    if (!s.alive || s.id == me.id) continue;
    const bool target = s.id == me.target;
    out.push_back(blip(cx, cy, half, inv * (s.position - me.position), range, target ? target_dot : dot,
                       w.hostile(me, s) ? RadarBlipKind::Hostile : RadarBlipKind::Friendly, target));
  }
  for (const Projectile& p : w.projectiles)
    if (p.target == me.id && p.kind == SecondaryWeapon::Missile)
      out.push_back(blip(cx, cy, half, inv * (p.position - me.position), range, dot * 0.75, RadarBlipKind::Missile, false));
  return out;
}

void layout_radar(const World& w, const Ship& me, const HudRules& rules, double canvas_w, double canvas_h,
                  HudLayer& h) {
  const HudRect r = radar_rect(canvas_w, canvas_h);
  const double cx = r.x + r.w * 0.5, cy = r.y + r.h * 0.5, half = r.w * 0.5;
  quad(h, r.x, r.y, r.w, r.h, kHudBack);
  line(h, r.x, cy, r.x + r.w, cy, kRadarGrid, 1.0f);
  line(h, cx, r.y, cx, r.y + r.h, kRadarGrid, 1.0f);
  const int segments = 24;  // the half-range ring
  for (int i = 0; i < segments; ++i) {
    const double a0 = 6.283185307179586 * i / segments, a1 = 6.283185307179586 * (i + 1) / segments;
    line(h, cx + std::cos(a0) * half * 0.5, cy + std::sin(a0) * half * 0.5, cx + std::cos(a1) * half * 0.5,
         cy + std::sin(a1) * half * 0.5, kRadarGrid, 1.0f);
  }
  const double range = radar_range(w, me, rules);
  // The range on a backing of its own: in the chase camera the radar sits over the ship's
  // engine glow, which showed through the panel's and washed the label out.
  const std::string label = range_label(range);
  quad(h, r.x + 2, r.y + 2, kGlyphAdvance * 0.9 * double(label.size()) + 5.0, 15.0, kHudBack);
  text(h, r.x + 4, r.y + 4, 0.9, kHudGreen, label);
  for (const RadarBlip& b : radar_blips(w, me, rules, canvas_w, canvas_h)) {
    const glm::vec4 c = b.kind == RadarBlipKind::Hostile    ? kHudRed
                        : b.kind == RadarBlipKind::Friendly ? kHudBlue
                                                            : kHudWhite;
    quad(h, b.at.x - b.size * 0.5, b.at.y - b.size * 0.5, b.size, b.size, c);
    line(h, b.at.x, b.at.y, b.at.x, b.at.y - b.rise, c, 1.0f);
  }
}

}  // namespace arc
