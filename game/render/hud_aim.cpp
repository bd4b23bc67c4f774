// The aim cues: the crosshair's beam ring, the target's brackets, missile cue, plasma lead and
// the off-screen arrow.
#include "game/render/hud_aim.h"

#include <algorithm>
#include <cmath>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "game/render/hud_combat.h"
#include "game/render/hud_draw.h"
#include "game/sim/beams.h"
#include "game/sim/capital.h"
#include "game/sim/geometry.h"
#include "game/sim/seekers.h"
#include "game/sim/world.h"

namespace arc {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kBeamRingRadius = 20.0;
constexpr int kLockSegments = 32;

void centred_text(HudLayer& h, double cx, double y, double scale, const glm::vec4& c, const std::string& s) {
  text(h, cx - 0.5 * kGlyphAdvance * scale * double(s.size()), y, scale, c, s);
}

// A circle of `segments` strokes; `every` > 1 draws only every such stroke (a broken circle).
void circle(HudLayer& h, glm::dvec2 c, double r, const glm::vec4& col, float width, int segments, int every = 1) {
  for (int i = 0; i < segments; i += every) {
    const double a0 = kTwoPi * i / segments, a1 = kTwoPi * (i + 1) / segments;
    line(h, c.x + r * std::cos(a0), c.y + r * std::sin(a0), c.x + r * std::cos(a1), c.y + r * std::sin(a1), col, width);
  }
}

// The lock's progress: the first `frac` of a ring, clockwise from the top.
void lock_arc(HudLayer& h, glm::dvec2 c, double r, double frac) {
  const int n = static_cast<int>(std::floor(std::clamp(frac, 0.0, 1.0) * kLockSegments + 1e-9));
  for (int i = 0; i < n; ++i) {
    const double a0 = kTwoPi * i / kLockSegments - 0.25 * kTwoPi, a1 = kTwoPi * (i + 1) / kLockSegments - 0.25 * kTwoPi;
    line(h, c.x + r * std::cos(a0), c.y + r * std::sin(a0), c.x + r * std::cos(a1), c.y + r * std::sin(a1), kHudRed,
         3.0f);
  }
}

void crosshair(glm::dvec2 c, bool beam_ring_lit, HudLayer& h) {
  line(h, c.x - 14, c.y, c.x - 5, c.y, kHudGreen);
  line(h, c.x + 5, c.y, c.x + 14, c.y, kHudGreen);
  line(h, c.x, c.y - 14, c.x, c.y - 5, kHudGreen);
  line(h, c.x, c.y + 5, c.x, c.y + 14, kHudGreen);
  if (beam_ring_lit) {
    circle(h, c, kBeamRingRadius, kHudGreen, 2.5f, 32);
    // On the left: the target's own labels stand right of and under it.
    text(h, c.x - kBeamRingRadius - 12.0 - 4 * kGlyphAdvance, c.y - 6.0, 1.0, kHudGreen, "BEAM");
  } else {
    circle(h, c, kBeamRingRadius, faded(kHudGreen, 0.3), 1.0f, 32);
  }
}

// The missile cue around the target at `px` (brackets' half-size r): a circle, whole when a
// missile launched now reaches the target, broken otherwise, labelled "MSL"; over it the lock
// ring, filling clockwise from the top as the lock builds; once locked, a bold double ring
// labelled "LOCK".
void missile_cue(HudLayer& h, glm::dvec2 px, double r, bool ready, double lock) {
  const double radius = r + 10.0;
  if (lock >= 1.0) {
    circle(h, px, radius, kHudRed, 3.0f, kLockSegments);
    circle(h, px, radius + 5.0, kHudRed, 1.5f, kLockSegments);
    text(h, px.x + radius + 8.0, px.y - 6.0, 1.0, kHudRed, "LOCK");
    return;
  }
  const glm::vec4 col = ready ? kHudYellow : faded(kHudYellow, 0.55);
  circle(h, px, radius, col, ready ? 1.5f : 1.0f, kLockSegments, ready ? 1 : 2);
  lock_arc(h, px, radius + 4.0, lock);
  text(h, px.x + radius + 8.0, px.y - 6.0, 1.0, col, "MSL");
}

// Where plasma bolts fired now meet the target (drawn at `drawn`): false when behind the eye.
bool plasma_lead_point(const Ship& me, const Ship& t, const glm::dvec3& drawn, const Projector& pr, glm::dvec2& lp) {
  const double speed = me.cls->plasma.speed;
  const glm::dvec3 rel = t.position - me.position, rv = t.velocity - me.velocity;
  double time = std::sqrt(glm::dot(rel, rel)) / speed;
  for (int i = 0; i < 2; ++i) time = std::sqrt(glm::dot(rel + rv * time, rel + rv * time)) / speed;
  return pr.project(drawn + rv * time, lp);
}

// The plasma lead: the diamond and its label.
void plasma_lead(HudLayer& h, glm::dvec2 lp) {
  const double d = 7;
  line(h, lp.x - d, lp.y, lp.x, lp.y - d, kHudYellow);
  line(h, lp.x, lp.y - d, lp.x + d, lp.y, kHudYellow);
  line(h, lp.x + d, lp.y, lp.x, lp.y + d, kHudYellow);
  line(h, lp.x, lp.y + d, lp.x - d, lp.y, kHudYellow);
  text(h, lp.x + d + 3.0, lp.y - 6.0, 1.0, kHudYellow, "PLS");
}

// Below the brackets: the distance and the target's shield and hull as two thin bars.
void bracket_readout(HudLayer& h, const Ship& t, glm::dvec2 px, double r, double dist, const glm::vec4& col) {
  const double top = px.y + std::max(r, 14.0) + 6.0, bar_w = std::clamp(2.0 * r, 28.0, 60.0);
  const double x = px.x - bar_w * 0.5;
  const double shield = t.cls->shield > 0 ? std::clamp(t.shield / t.cls->shield, 0.0, 1.0) : 0.0;
  const double hull = std::clamp(t.hull / t.cls->hull, 0.0, 1.0);
  quad(h, x, top, bar_w, 3.0, kHudBack);
  quad(h, x, top, bar_w * shield, 3.0, kHudBlue);
  quad(h, x, top + 4.0, bar_w, 3.0, kHudBack);
  quad(h, x, top + 4.0, bar_w * hull, 3.0, col);
  centred_text(h, px.x, top + 10.0, 1.0, faded(kHudWhite, 0.8), fmt("%.0f m", dist));
}

// Where the off-screen arrow toward `dir` (from the screen centre) points from: where that ray
// leaves `area`, the part of the screen between the HUD's panels.
glm::dvec2 offscreen_arrow_tip(glm::dvec2 dir, double canvas_w, double canvas_h, const HudRect& area) {
  const glm::dvec2 c(std::clamp(canvas_w * 0.5, area.x, area.x + area.w),
                     std::clamp(canvas_h * 0.5, area.y, area.y + area.h));
  double t = 1e30;
  if (dir.x > 1e-9) t = std::min(t, (area.x + area.w - c.x) / dir.x);
  if (dir.x < -1e-9) t = std::min(t, (area.x - c.x) / dir.x);
  if (dir.y > 1e-9) t = std::min(t, (area.y + area.h - c.y) / dir.y);
  if (dir.y < -1e-9) t = std::min(t, (area.y - c.y) / dir.y);
  return c + dir * std::max(t, 0.0);
}

// The screen direction from the centre toward `at`, a point out of view.
glm::dvec2 offscreen_direction(const Projector& pr, const glm::dvec3& at) {
  const glm::dvec3 v = pr.to_view(at);
  const glm::dvec2 dir(v.x, -v.y);
  const double len = std::sqrt(dir.x * dir.x + dir.y * dir.y);
  return len > 1e-9 ? dir / len : glm::dvec2(0, 1);
}

// Where the world point `p` shows: true with `at` on the canvas, or false with the edge
// arrow's direction and tip toward it; `depth` is its view depth either way.
bool place_on_screen(const Projector& pr, const glm::dvec3& p, double canvas_w, double canvas_h, const HudRect& arrow_area,
                     glm::dvec2& at, glm::dvec2& arrow_dir, glm::dvec2& arrow_tip, double& depth) {
  const bool in_front = pr.project(p, at, &depth);
  if (in_front && at.x >= 0 && at.x <= canvas_w && at.y >= 0 && at.y <= canvas_h) return true;
  arrow_dir = offscreen_direction(pr, p);
  arrow_tip = offscreen_arrow_tip(arrow_dir, canvas_w, canvas_h, arrow_area);
  return false;
}

void offscreen_arrow(HudLayer& h, glm::dvec2 dir, glm::dvec2 tip, double dist, const HudRect& area,
                     const glm::vec4& col) {
  const glm::dvec2 side(-dir.y, dir.x);
  const glm::dvec2 b0 = tip - dir * 18.0 + side * 10.0, b1 = tip - dir * 18.0 - side * 10.0;
  line(h, tip.x, tip.y, b0.x, b0.y, col, 3.0f);
  line(h, tip.x, tip.y, b1.x, b1.y, col, 3.0f);
  line(h, b0.x, b0.y, b1.x, b1.y, col, 3.0f);
  // The distance just inside the arrow's base, kept within the area.
  const std::string label = fmt("%.0f m", dist);
  const double half_w = 0.5 * kGlyphAdvance * double(label.size());
  const glm::dvec2 at_text = tip - dir * (26.0 + std::fabs(dir.x) * half_w + std::fabs(dir.y) * 9.0);
  const double cx = std::clamp(at_text.x, area.x + half_w, std::max(area.x + half_w, area.x + area.w - half_w));
  const double y = std::clamp(at_text.y - 6.0, area.y, std::max(area.y, area.y + area.h - 13.0));
  centred_text(h, cx, y, 1.0, col, label);
}

}  // namespace

bool beam_would_hit(const World& w, const Ship& me) {
  if (!me.alive) return false;
  const glm::dvec3 aim = forward_of(me.orientation);
  for (const glm::dvec3& mount : me.cls->beam.mounts) {
    const glm::dvec3 origin = me.position + me.orientation * mount;
    const BeamHit hit = trace_beam(w, me.id, {origin, origin + aim * me.cls->beam.range});
    if (hit.ship && w.hostile(me, w.ship(hit.ship))) return true;
  }
  return false;
}

bool missile_ready(const Ship& me, const Ship& t) {
  const ProjectileWeaponDef& m = me.cls->missile;
  if (!m.present) return false;
  const glm::dvec3 rel = t.position - me.position;
  const double dist = glm::length(rel);
  if (dist > m.speed * m.lifetime) return false;
  if (dist < 1e-9) return true;
  const double off_nose = std::acos(std::clamp(glm::dot(rel / dist, forward_of(me.orientation)), -1.0, 1.0));
  return off_nose <= std::min(m.turn_rate * kMissileConeSeconds, 180.0) * kDeg;
}

namespace {

// The player's route order's next waypoint, where the HUD shows it.
NavCue nav_cue(const World& w, const Ship& me, const Projector& pr, double canvas_w, double canvas_h,
               const HudRect& arrow_area) {
  NavCue n;
  if (!w.mission || me.id != w.player || me.id.index() >= w.mission->orders.size()) return n;
  const ShipOrder& o = w.mission->orders[me.id.index()];
  if (o.kind != OrderKind::Route || o.next < 0 || size_t(o.next) >= o.waypoints.size()) return n;
  const glm::dvec3 at = o.waypoints[size_t(o.next)];
  n.shown = true;
  n.distance = glm::length(at - me.position);
  double depth = 0;
  n.on_screen = place_on_screen(pr, at, canvas_w, canvas_h, arrow_area, n.at, n.arrow_dir, n.arrow_tip, depth);
  return n;
}

void nav_marker(HudLayer& h, const NavCue& n, const HudRect& arrow_area) {
  if (!n.shown) return;
  if (!n.on_screen) {
    offscreen_arrow(h, n.arrow_dir, n.arrow_tip, n.distance, arrow_area, kHudGreen);
    return;
  }
  const double d = 10;
  const glm::dvec2 p = n.at;
  line(h, p.x - d, p.y, p.x, p.y - d, kHudGreen, 2.0f);
  line(h, p.x, p.y - d, p.x + d, p.y, kHudGreen, 2.0f);
  line(h, p.x + d, p.y, p.x, p.y + d, kHudGreen, 2.0f);
  line(h, p.x, p.y + d, p.x - d, p.y, kHudGreen, 2.0f);
  centred_text(h, p.x, p.y - d - 15.0, 1.0, kHudGreen, "NAV");
  centred_text(h, p.x, p.y + d + 4.0, 1.0, kHudGreen, fmt("%.0f m", n.distance));
}

}  // namespace

AimCues aim_cues(const World& w, const Ship& me, const Projector& pr, double alpha, double canvas_w, double canvas_h,
                 const HudRect& arrow_area) {
  AimCues cues;
  cues.crosshair = {canvas_w * 0.5, canvas_h * 0.5};
  pr.project(crosshair_point(w, me, alpha), cues.crosshair);
  cues.beam_ring_lit = beam_would_hit(w, me);
  cues.nav = nav_cue(w, me, pr, canvas_w, canvas_h, arrow_area);
  if (!me.target || !w.ship(me.target).alive) return cues;
  const Ship& t = w.ship(me.target);
  TargetCues& c = cues.target;
  c.selected = true;
  c.hostile = w.hostile(me, t);
  c.distance = glm::length(t.position - me.position);
  const glm::dvec3 tp = lerp_pos(t.prev_position, t.position, alpha);
  double depth = 0;
  c.on_screen = place_on_screen(pr, tp, canvas_w, canvas_h, arrow_area, c.centre, c.arrow_dir, c.arrow_tip, depth);
  if (!c.on_screen) return cues;
  c.half_size = std::max(t.cls->shield_radius * pr.focal / depth, 14.0);
  c.in_range = c.distance <= me.cls->beam.range;
  if (!c.hostile) return cues;
  if (me.secondary == SecondaryWeapon::Plasma && me.cls->plasma.present) {
    c.plasma_lead = plasma_lead_point(me, t, tp, pr, c.lead);
  } else if (me.secondary == SecondaryWeapon::Missile && me.cls->missile.present) {
    c.missile_cue = true;
    c.missile_ready = missile_ready(me, t);
    c.lock = lock_progress(w, me);
  }
  return cues;
}

void subsystem_cue(const World& w, const Ship& me, const Projector& pr, double alpha, HudLayer& h);

void layout_aim_cues(const World& w, const Ship& me, const Projector& pr, double alpha, double canvas_w,
                     double canvas_h, const HudRect& arrow_area, HudLayer& h) {
  if (w.paused) return;  // the pause menu stands in the middle of the screen
  const AimCues cues = aim_cues(w, me, pr, alpha, canvas_w, canvas_h, arrow_area);
  crosshair(cues.crosshair, cues.beam_ring_lit, h);
  nav_marker(h, cues.nav, arrow_area);
  const TargetCues& c = cues.target;
  if (!c.selected) return;
  const glm::vec4 col = c.hostile ? kHudRed : kHudBlue;
  if (!c.on_screen) {
    offscreen_arrow(h, c.arrow_dir, c.arrow_tip, c.distance, arrow_area, col);
    return;
  }
  brackets(h, c.centre, c.half_size, col, c.in_range ? 3.0f : 2.0f);
  layout_range_cue(h, c.centre, c.half_size, c.in_range, col);
  bracket_readout(h, w.ship(me.target), c.centre, c.half_size, c.distance, col);
  if (c.plasma_lead) plasma_lead(h, c.lead);
  if (c.missile_cue) missile_cue(h, c.centre, c.half_size, c.missile_ready, c.lock);
  subsystem_cue(w, me, pr, alpha, h);
}

// The subsystem the player aims at on a capital ship: its own small yellow brackets, its name
// and what is left of its hull above them.
void subsystem_cue(const World& w, const Ship& me, const Projector& pr, double alpha, HudLayer& h) {
  const int part = target_part(w, me);
  if (part < 0) return;
  const Ship& t = w.ship(me.target);
  const glm::dvec3 local = glm::inverse(t.orientation) * (part_position(t, size_t(part)) - t.position);
  const glm::dquat q = glm::normalize(glm::slerp(t.prev_orientation, t.orientation, alpha));
  const glm::dvec3 at = lerp_pos(t.prev_position, t.position, alpha) + q * local;
  glm::dvec2 px;
  double depth = 0;
  if (!pr.project(at, px, &depth) || depth <= 0) return;
  const double r = std::max(part_radius(*t.cls, size_t(part)) * pr.focal / depth, 8.0);
  brackets(h, px, r, kHudYellow, 2.0f);
  const double full = size_t(part) < t.cls->turrets.size() ? t.cls->turrets[size_t(part)].hull
                                                             : t.cls->subsystems[size_t(part) - t.cls->turrets.size()].hull;
  centred_text(h, px.x, px.y - r - 14.0, 1.0, kHudYellow,
               std::string(part_name(*t.cls, size_t(part))) + fmt(" %.0f%%", 100.0 * std::max(0.0, t.parts[size_t(part)].hull) / full));
}

}  // namespace arc
