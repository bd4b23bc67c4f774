// The chase view's lift: per hostile near the nose, the least rise of the eye that shows it
// above the own hull's silhouette, eased in at the silhouette's sides and bottom.
#include "game/render/chase_framing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "game/render/screen_projection.h"
#include "game/sim/world.h"

namespace arc {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

double ease(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// The hull's box corners and a point as seen from one eye: tangent-plane coordinates (+y up).
struct Picture {
  std::array<glm::dvec2, 8> corners;
  glm::dvec2 point{0.0};
  double xmin = 0, xmax = 0;
  bool ok = false;  // everything in front of the eye

  // The silhouette's (the corners' convex hull's) upper and lower edge at x within [xmin, xmax]:
  // every hull edge is a segment between two corners, so the envelope of all such segments.
  void edges_at(double x, double& top, double& bottom) const {
    top = -1e30, bottom = 1e30;
    for (size_t i = 0; i < corners.size(); ++i)
      for (size_t j = i; j < corners.size(); ++j) {
        const glm::dvec2 a = corners[i], b = corners[j];
        if (x < std::min(a.x, b.x) || x > std::max(a.x, b.x)) continue;
        const double dx = b.x - a.x;
        const double y = std::fabs(dx) < 1e-12 ? std::max(a.y, b.y) : a.y + (b.y - a.y) * (x - a.x) / dx;
        const double y_low = std::fabs(dx) < 1e-12 ? std::min(a.y, b.y) : y;
        top = std::max(top, y), bottom = std::min(bottom, y_low);
      }
  }
};

Picture picture(const glm::dvec3& eye, const glm::dquat& inv, const glm::dvec3& ship_pos, const glm::dquat& ship_q,
                const HullBox& box, const glm::dvec3& point) {
  Picture p;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 local(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y, i & 4 ? box.hi.z : box.lo.z);
    const glm::dvec3 v = inv * (ship_pos + ship_q * local - eye);
    if (v.z >= -1e-6) return p;
    p.corners[size_t(i)] = {v.x / -v.z, v.y / -v.z};
  }
  const glm::dvec3 t = inv * (point - eye);
  if (t.z >= -1e-6) return p;
  p.point = {t.x / -t.z, t.y / -t.z};
  p.xmin = p.xmax = p.corners[0].x;
  for (const glm::dvec2& c : p.corners) p.xmin = std::min(p.xmin, c.x), p.xmax = std::max(p.xmax, c.x);
  p.ok = true;
  return p;
}

// Above the silhouette's upper edge by `margin`, or beside its sides widened by it.
bool clear_above(const Picture& p, double margin) {
  if (!p.ok) return true;
  if (p.point.x < p.xmin - margin || p.point.x > p.xmax + margin) return true;
  double top, bottom;
  p.edges_at(std::clamp(p.point.x, p.xmin, p.xmax), top, bottom);
  return p.point.y >= top + margin;
}

}  // namespace

HullBox framing_hull(const Ship& s) {
  const double r = s.cls->collision_radius;
  return {glm::dvec3(-0.95 * r, -0.3 * r, -1.15 * r), glm::dvec3(0.95 * r, 0.45 * r, 1.05 * r)};
}

double rise_to_clear(const glm::dvec3& eye, const glm::dquat& view, const glm::dvec3& ship_pos,
                     const glm::dquat& ship_orientation, const HullBox& box, const glm::dvec3& point, double max_m,
                     const FramingRules& rules) {
  const glm::dquat inv = glm::conjugate(view);
  const glm::dvec3 up = view * glm::dvec3(0, 1, 0);
  const double margin = std::tan(rules.margin_deg * kDegToRad), band = std::tan(rules.ease_deg * kDegToRad);
  const Picture at0 = picture(eye, inv, ship_pos, ship_orientation, box, point);
  if (!at0.ok || clear_above(at0, margin)) return 0.0;
  // Only what lies beyond the ship can be behind it: eased in over the box's half-size.
  const double beyond = glm::length(point - eye) - glm::length(ship_pos - eye);
  const double w_far = ease(beyond / std::max(0.5 * glm::length(box.hi - box.lo), 1e-6));
  // Eased in from the widened sides and from the widened bottom edge inwards.
  const double x = at0.point.x;
  const double w_side = ease(std::min(x - (at0.xmin - margin), (at0.xmax + margin) - x) / band);
  double top, bottom;
  at0.edges_at(std::clamp(x, at0.xmin, at0.xmax), top, bottom);
  const double w_bottom = ease((at0.point.y - (bottom - margin)) / band);
  const double w = w_far * w_side * w_bottom;
  if (w <= 0.0) return 0.0;
  auto clear_at = [&](double r) {
    return clear_above(picture(eye + up * r, inv, ship_pos, ship_orientation, box, point), margin);
  };
  double lo = 0.0, hi = max_m;
  if (!clear_at(hi)) return w * max_m;
  for (int i = 0; i < 18; ++i) {
    const double mid = 0.5 * (lo + hi);
    (clear_at(mid) ? hi : lo) = mid;
  }
  return w * hi;
}

Framing chase_framing(const World& w, const glm::dvec3& eye, const glm::dquat& view, double alpha,
                      const FramingRules& rules) {
  Framing f;
  const ShipId focus = w.focus_ship();
  if (!focus || !w.ship(focus).alive) return f;
  const Ship& me = w.ship(focus);
  const glm::dvec3 pos = lerp_pos(me.prev_position, me.position, alpha);
  const glm::dquat q = glm::normalize(glm::slerp(me.prev_orientation, me.orientation, alpha));
  const glm::dvec3 nose = forward_of(q);
  const HullBox box = framing_hull(me);
  const double max_m = rules.max_rise_per_radius * me.cls->collision_radius;
  const double now_s = (double(w.tick) - 1.0 + alpha) * w.dt;
  const double near_cos = std::cos(rules.near_nose_deg * kDegToRad), far_cos = std::cos(rules.far_nose_deg * kDegToRad);
  for (const Ship& h : w.ships) {
    if (h.id == me.id || (!w.hostile(me, h) && h.id != me.target)) continue;
    double fade = 1.0;
    if (!h.alive) {
      if (h.death_tick < 0) continue;  // not arrived yet
      fade = 1.0 - (now_s - double(h.death_tick) * w.dt) / rules.fade_s;
      if (fade <= 0.0) continue;
    }
    const glm::dvec3 at = h.alive ? lerp_pos(h.prev_position, h.position, alpha) : h.position;
    const glm::dvec3 to = at - pos;
    const double len = glm::length(to);
    if (len < 1e-9) continue;
    const double w_nose = ease((glm::dot(to, nose) / len - far_cos) / (near_cos - far_cos)) * std::min(fade, 1.0);
    if (w_nose <= 0.0 || w_nose * max_m <= f.rise_m) continue;
    f.rise_m = std::max(f.rise_m, w_nose * rise_to_clear(eye, view, pos, q, box, at, max_m, rules));
  }
  if (f.rise_m <= 0.0) return f;
  // The hull drops below the eye's line as the eye rises; the view follows part of that drop.
  const glm::dvec3 c = glm::conjugate(view) * (pos - eye);
  const double before = std::atan2(-c.y, -c.z), after = std::atan2(-(c.y - f.rise_m), -c.z);
  f.tilt_rad = rules.tilt_per_rise * (after - before);
  return f;
}

void lift_chase_view(const World& w, double alpha, glm::dvec3& eye, glm::dquat& view) {
  const Framing f = chase_framing(w, eye, view, alpha);
  eye += view * glm::dvec3(0, f.rise_m, 0);
  view = glm::normalize(view * glm::angleAxis(-f.tilt_rad, glm::dvec3(1, 0, 0)));
}

}  // namespace arc
