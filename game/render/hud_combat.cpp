// Combat cues of the HUD: hit markers, damage direction, missile warning, kill feed.
#include "game/render/hud_combat.h"

#include <algorithm>
#include <cmath>
#include <vector>
#include <glm/geometric.hpp>

#include "game/render/hud_draw.h"
#include "game/sim/world.h"

namespace arc {
namespace {

const glm::vec4 kDamageRed{1.0f, 0.22f, 0.12f, 0.9f};
const glm::vec4 kEdgeGlow{1.0f, 0.25f, 0.1f, 0.04f};

double seconds_since(const World& w, int64_t tick) { return double(w.tick - tick) * w.dt; }

glm::dvec3 drawn_position(const Ship& s, double alpha) { return lerp_pos(s.prev_position, s.position, alpha); }

// The screen direction from the centre toward a world point (in front or behind), or false
// when it lies straight ahead or straight behind.
bool screen_direction(const Projector& pr, const glm::dvec3& world, glm::dvec2& dir) {
  const glm::dvec3 v = pr.to_view(world);
  const glm::dvec2 d(v.x, -v.y);
  const double len = glm::length(d);
  if (len < 1e-6 * std::max(1.0, std::fabs(v.z))) return false;
  dir = d / len;
  return true;
}

void centred_text(HudLayer& h, double cx, double y, double scale, const glm::vec4& c, const std::string& s) {
  text(h, cx - 0.5 * kGlyphAdvance * scale * double(s.size()), y, scale, c, s);
}

void hit_marker(HudLayer& h, glm::dvec2 c, bool kill) {
  const double r0 = kill ? 12.0 : 9.0, r1 = kill ? 26.0 : 17.0;
  const glm::vec4 col = kill ? kHudRed : kHudWhite;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      line(h, c.x + sx * r0 * 0.7071, c.y + sy * r0 * 0.7071, c.x + sx * r1 * 0.7071, c.y + sy * r1 * 0.7071, col,
           kill ? 3.0f : 2.0f);
}

void hit_markers(const World& w, const Ship& me, const HudRules& rules, glm::dvec2 crosshair, HudLayer& h) {
  bool hit = false, kill = false;
  for (const Ship& s : w.ships) {
    if (s.id == me.id || s.last_attacker != me.id || !w.hostile(me, s)) continue;
    hit = hit || seconds_since(w, s.last_hit_tick) < rules.hit_marker_seconds;
    kill = kill || (!s.alive && s.death_tick >= 0 && seconds_since(w, s.death_tick) < 3.0 * rules.hit_marker_seconds);
  }
  if (hit || kill) hit_marker(h, crosshair, kill);
}

// An arc of the ring around the screen centre toward `dir`, with a chevron pointing out.
void ring_wedge(HudLayer& h, glm::dvec2 c, double radius, glm::dvec2 dir, const glm::vec4& col) {
  const double a = std::atan2(dir.y, dir.x), half = 0.3;
  const int segments = 6;
  glm::dvec2 prev = c + radius * glm::dvec2(std::cos(a - half), std::sin(a - half));
  for (int i = 1; i <= segments; ++i) {
    const double t = a - half + 2.0 * half * i / segments;
    const glm::dvec2 p = c + radius * glm::dvec2(std::cos(t), std::sin(t));
    line(h, prev.x, prev.y, p.x, p.y, col, 5.0f);
    prev = p;
  }
  const glm::dvec2 side(-dir.y, dir.x), base = c + (radius + 6.0) * dir, tip = c + (radius + 18.0) * dir;
  line(h, base.x + side.x * 10.0, base.y + side.y * 10.0, tip.x, tip.y, col, 3.0f);
  line(h, base.x - side.x * 10.0, base.y - side.y * 10.0, tip.x, tip.y, col, 3.0f);
}

// A red glow on the screen edge where `dir` from the centre leaves the screen, brightest at the
// edge: stacked translucent bands, each shorter and deeper than the one before.
void edge_glow(HudLayer& h, glm::dvec2 c, glm::dvec2 dir, double canvas_w, double canvas_h, double strength) {
  const double tx = dir.x > 0 ? (canvas_w - c.x) / dir.x : dir.x < 0 ? -c.x / dir.x : 1e30;
  const double ty = dir.y > 0 ? (canvas_h - c.y) / dir.y : dir.y < 0 ? -c.y / dir.y : 1e30;
  const glm::dvec2 at = c + dir * std::min(tx, ty);
  const bool side_edge = tx < ty;
  const glm::vec4 col = faded(kEdgeGlow, strength);
  const int bands = 16;
  for (int i = 0; i < bands; ++i) {
    const double depth = 3.0 * (i + 1), span = (side_edge ? canvas_h : canvas_w) * (0.42 - 0.02 * i);
    if (side_edge) {
      const double y = std::clamp(at.y - span * 0.5, 0.0, canvas_h - span);
      quad(h, dir.x > 0 ? canvas_w - depth : 0.0, y, depth, span, col);
    } else {
      const double x = std::clamp(at.x - span * 0.5, 0.0, canvas_w - span);
      quad(h, x, dir.y > 0 ? canvas_h - depth : 0.0, span, depth, col);
    }
  }
}

void damage_directions(const ThreatCues& t, glm::dvec2 c, double canvas_w, double canvas_h, HudLayer& h) {
  for (const ThreatCue& a : t.attackers) {
    // An attacker in view has its own marks; the ring points to the ones out of view.
    if (!a.in_view) ring_wedge(h, c, 0.17 * canvas_h, a.dir, faded(kDamageRed, a.strength));
    edge_glow(h, c, a.dir, canvas_w, canvas_h, a.strength);
  }
}

void missile_warning(const World& w, const ThreatCues& t, glm::dvec2 c, double canvas_h, HudLayer& h) {
  for (const glm::dvec2& dir : t.missiles) {
    const double r = 0.17 * canvas_h + 22.0;
    const glm::dvec2 at = c + dir * r, side(-dir.y, dir.x);
    line(h, at.x + side.x * 8.0 - dir.x * 8.0, at.y + side.y * 8.0 - dir.y * 8.0, at.x, at.y, kHudYellow, 3.0f);
    line(h, at.x - side.x * 8.0 - dir.x * 8.0, at.y - side.y * 8.0 - dir.y * 8.0, at.x, at.y, kHudYellow, 3.0f);
  }
  if (t.missile_m < 0) return;
  const bool lit = int64_t(double(w.tick) * w.dt * 6.0) % 2 == 0;  // three blinks a second
  centred_text(h, c.x, c.y - 0.25 * canvas_h, 1.6, lit ? kHudYellow : faded(kHudYellow, 0.35),
               "MISSILE " + fmt("%.0f m", t.missile_m));
}

}  // namespace

ThreatCues threat_cues(const World& w, const Ship& me, const Projector& pr, const HudRules& rules, double alpha,
                       double canvas_w, double canvas_h) {
  ThreatCues t;
  std::vector<double> strength(w.ships.size(), 0.0);  // per attacking ship
  const double since_hit = seconds_since(w, me.last_hit_tick);
  if (me.last_attacker && me.last_attacker != me.id && since_hit < rules.damage_seconds)
    strength[me.last_attacker.index()] = 1.0 - since_hit / rules.damage_seconds;
  for (const Ship& s : w.ships)
    if (s.alive && s.beam_firing && s.beam_target == me.id && w.hostile(me, s)) strength[s.id.index()] = 1.0;
  for (const Ship& s : w.ships) {
    ThreatCue a;
    a.strength = strength[s.id.index()];
    const glm::dvec3 at = drawn_position(s, alpha);
    if (a.strength <= 0.0 || !screen_direction(pr, at, a.dir)) continue;
    glm::dvec2 px;
    a.in_view = pr.project(at, px) && px.x >= 0 && px.x <= canvas_w && px.y >= 0 && px.y <= canvas_h;
    t.attackers.push_back(a);
  }
  for (const Projectile& p : w.projectiles) {
    // A missile chasing a flare no longer threatens.
    if (p.target != me.id || p.kind != SecondaryWeapon::Missile || p.decoy != 0) continue;
    const double d = glm::length(p.position - me.position);
    t.missile_m = t.missile_m < 0 ? d : std::min(t.missile_m, d);
    glm::dvec2 dir;
    if (screen_direction(pr, p.position, dir)) t.missiles.push_back(dir);
  }
  return t;
}

void layout_range_cue(HudLayer& h, glm::dvec2 c, double r, bool in_range, const glm::vec4& col) {
  // Above the brackets: the crosshair sits on the target while aiming, its arms reach 14 below.
  const double y = c.y - std::max(r, 18.0) - 20.0;
  if (!in_range) return;
  const std::string label = "IN RANGE";
  const double w = kGlyphAdvance * double(label.size()) + 8.0;
  quad(h, c.x - 0.5 * w, y - 2.0, w, 17.0, faded(col, 0.3));
  centred_text(h, c.x, y, 1.0, kHudWhite, label);
}

void layout_combat_cues(const World& w, const Ship& me, const Projector& pr, const HudRules& rules, double alpha,
                        double canvas_w, double canvas_h, HudLayer& h) {
  glm::dvec2 crosshair(pr.cx, pr.cy);
  pr.project(crosshair_point(w, me, alpha), crosshair);
  const ThreatCues threats = threat_cues(w, me, pr, rules, alpha, canvas_w, canvas_h);
  const glm::dvec2 centre(pr.cx, pr.cy);
  damage_directions(threats, centre, canvas_w, canvas_h, h);
  missile_warning(w, threats, centre, canvas_h, h);
  hit_markers(w, me, rules, crosshair, h);
}

void layout_kill_feed(const World& w, const Ship* me, const HudRules& rules, double x, double y, HudLayer& h,
                      const std::map<uint32_t, std::string>* names, double right) {
  auto name = [&](const Ship& s) -> const std::string& {
    if (names)
      if (auto it = names->find(s.id.index()); it != names->end() && !it->second.empty()) return it->second;
    return s.name;
  };
  // The kills and the messages (wing replies, reinforcements), newest first, one list.
  struct Line {
    int64_t tick;
    size_t order;
    std::string text;
    glm::vec4 colour;
  };
  std::vector<Line> lines;
  for (const Ship& s : w.ships) {
    if (s.alive || s.death_tick < 0 || seconds_since(w, s.death_tick) >= rules.kill_feed_seconds) continue;
    const ShipId killer = s.last_attacker;
    std::string t = killer && killer != s.id ? name(w.ship(killer)) + " destroyed " + name(s) : name(s) + " destroyed";
    const glm::vec4 col = !me ? kHudWhite : w.hostile(*me, s) ? kHudGreen : kHudRed;
    lines.push_back({s.death_tick, s.id.index(), std::move(t), col});
  }
  for (size_t i = 0; i < w.messages.size(); ++i) {
    const SimMessage& m = w.messages[i];
    if (seconds_since(w, m.tick) >= rules.kill_feed_seconds) continue;
    const glm::vec4 col = m.kind == MessageKind::Hostile ? kHudYellow : m.kind == MessageKind::Radio ? kHudWhite : kHudBlue;
    lines.push_back({m.tick, w.ships.size() + i, m.text, col});
  }
  std::sort(lines.begin(), lines.end(), [](const Line& a, const Line& b) {
    return a.tick != b.tick ? a.tick > b.tick : a.order < b.order;
  });
  if (lines.size() > size_t(std::max(rules.kill_feed_lines, 0))) lines.resize(size_t(std::max(rules.kill_feed_lines, 0)));
  for (const Line& l : lines) {
    const double left = rules.kill_feed_seconds - seconds_since(w, l.tick);
    const size_t room = right > x ? size_t(std::max(4.0, (right - x) / kGlyphAdvance)) : l.text.size();
    const std::string shown = l.text.size() <= room ? l.text : l.text.substr(0, room - 2) + "..";
    text(h, x, y, 1.0, faded(l.colour, std::min(1.0, left)), shown);
    y += 18.0;
  }
}

}  // namespace arc
