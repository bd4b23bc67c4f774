// HUD layout: every HUD element in pixels, from the World, the frame's camera and HudState.
#include "game/render/hud_layout.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "game/render/hud_combat.h"
#include "game/render/hud_draw.h"
#include "game/render/hud_radar.h"
#include "game/render/screen_projection.h"
#include "game/sim/world.h"

namespace arc {
namespace {

// Canvas units an off-screen arrow keeps from the screen edges and from the radar.
constexpr double kArrowMargin = 30.0;

void hud_outcome_and_menu(const World& w, const HudState& state, int width, int height, HudLayer& h) {
  if (w.outcome != Outcome::Undecided && !w.paused) {
    std::string msg = w.outcome == Outcome::Victory  ? "VICTORY"
                      : w.outcome == Outcome::Defeat ? "DEFEAT"
                                                     : "TEAM " + w.winner + " WINS";
    const glm::vec4 c = w.outcome == Outcome::Defeat ? kHudRed : kHudGreen;
    text(h, width * 0.5 - msg.size() * 12.0, height * 0.3, 3.0, c, msg);
    if (w.player >= 0) {
      const std::string hint = "Esc: menu (restart, difficulty, quit)";
      text(h, width * 0.5 - hint.size() * 4.8, height * 0.3 + 48, 1.2, kHudWhite, hint);
    }
  }
  if (!w.paused) return;
  quad(h, 0, 0, width, height, {0.0f, 0.0f, 0.05f, 0.55f});
  text(h, width * 0.5 - 60, height * 0.3, 2.5, kHudWhite, "PAUSED");
  for (size_t i = 0; i < state.pause_items.size(); ++i) {
    const bool sel = int(i) == state.pause_selection;
    const double y = height * 0.4 + 36.0 * i;
    if (sel) quad(h, width * 0.5 - 130, y - 6, 260, 32, {0.3f, 0.6f, 1.0f, 0.35f});
    text(h, width * 0.5 - 110, y, 1.6, sel ? kHudYellow : kHudWhite, state.pause_items[i]);
  }
}

// Where the off-screen arrow toward `dir` (from the centre) points from: on an ellipse inside
// the screen edges, lifted above the radar when it would fall on it.
glm::dvec2 offscreen_arrow_tip(glm::dvec2 dir, int width, int height) {
  const double rx = width * 0.5 - kArrowMargin, ry = height * 0.5 - kArrowMargin;
  glm::dvec2 tip(width * 0.5 + dir.x * rx, height * 0.5 + dir.y * ry);
  const HudRect radar = radar_rect(width, height);
  const double reach = 20.0 + kArrowMargin * 0.5;  // the arrow's size around its tip, and a gap
  if (radar.overlaps(tip.x - reach, tip.y - reach, 2.0 * reach, 2.0 * reach)) tip.y = radar.y - reach;
  return tip;
}

void hud_target(const World& w, const Ship& me, const Projector& pr, int width, int height, double alpha,
                HudLayer& h) {
  if (me.target < 0 || !w.ships[me.target].alive) return;
  const Ship& t = w.ships[me.target];
  const glm::dvec3 tp = lerp_pos(t.prev_position, t.position, alpha);
  const glm::vec4 col = w.hostile(me, t) ? kHudRed : kHudBlue;
  glm::dvec2 px;
  double depth = 0;
  const bool in_front = pr.project(tp, px, &depth);
  const bool on_screen = in_front && px.x >= 0 && px.x <= width && px.y >= 0 && px.y <= height;
  const double dist = std::sqrt(glm::dot(t.position - me.position, t.position - me.position));
  if (on_screen) {
    const double r = t.cls->shield_radius * pr.focal / depth;
    const bool in_range = dist <= me.cls->beam.range;
    brackets(h, px, r, col, in_range ? 3.0f : 2.0f);
    layout_range_cue(h, px, r, in_range, dist, col);
    // Lead indicator: where to aim the current secondary (or the beam, which is instant).
    const bool plasma = me.secondary == SecondaryWeapon::Plasma && me.cls->plasma.present;
    const double speed = plasma ? me.cls->plasma.speed : me.cls->missile.present ? me.cls->missile.speed : 0.0;
    if (speed > 0) {
      glm::dvec3 rel = t.position - me.position, rv = t.velocity - me.velocity;
      double time = std::sqrt(glm::dot(rel, rel)) / speed;
      for (int i = 0; i < 2; ++i) time = std::sqrt(glm::dot(rel + rv * time, rel + rv * time)) / speed;
      glm::dvec2 lp;
      if (pr.project(tp + rv * time, lp)) {
        const double d = 7;
        line(h, lp.x - d, lp.y, lp.x, lp.y - d, kHudYellow);
        line(h, lp.x, lp.y - d, lp.x + d, lp.y, kHudYellow);
        line(h, lp.x + d, lp.y, lp.x, lp.y + d, kHudYellow);
        line(h, lp.x, lp.y + d, lp.x - d, lp.y, kHudYellow);
      }
    }
  } else {
    // Arrow at the screen edge toward the target.
    glm::dvec3 v = pr.to_view(tp);
    glm::dvec2 dir(v.x, -v.y);
    double len = std::sqrt(dir.x * dir.x + dir.y * dir.y);
    dir = len > 1e-9 ? dir / len : glm::dvec2(0, 1);
    const glm::dvec2 tip = offscreen_arrow_tip(dir, width, height);
    glm::dvec2 side(-dir.y, dir.x);
    glm::dvec2 b0 = tip - dir * 18.0 + side * 10.0, b1 = tip - dir * 18.0 - side * 10.0;
    line(h, tip.x, tip.y, b0.x, b0.y, col, 3.0f);
    line(h, tip.x, tip.y, b1.x, b1.y, col, 3.0f);
    line(h, b0.x, b0.y, b1.x, b1.y, col, 3.0f);
  }
  const double x = width - 230, y = 70;
  text(h, x, y - 40, 1.2, col, t.name + " (" + t.cls->name + ") " + fmt("%.0f m", dist));
  bar(h, x, y, 200, 10, t.cls->shield > 0 ? t.shield / t.cls->shield : 0.0, kHudBlue, "shield");
  bar(h, x, y + 30, 200, 10, t.hull / t.cls->hull, kHudRed, "hull");
}

void hud_own(const World& w, const Ship& me, const Projector& pr, int width, int height, double alpha, HudLayer& h) {
  // Crosshair where the guns converge ahead of the nose.
  const glm::dvec3 pos = lerp_pos(me.prev_position, me.position, alpha);
  const glm::dquat q = glm::slerp(me.prev_orientation, me.orientation, alpha);
  glm::dvec2 c(width * 0.5, height * 0.5);
  pr.project(pos + forward_of(q) * me.cls->beam.range * 0.5, c);
  line(h, c.x - 14, c.y, c.x - 5, c.y, kHudGreen);
  line(h, c.x + 5, c.y, c.x + 14, c.y, kHudGreen);
  line(h, c.x, c.y - 14, c.x, c.y - 5, kHudGreen);
  line(h, c.x, c.y + 5, c.x, c.y + 14, kHudGreen);
  const double x = 24, y = height - 110;
  bar(h, x, y, 220, 12, me.cls->shield > 0 ? me.shield / me.cls->shield : 0.0, kHudBlue, "SHIELD");
  bar(h, x, y + 34, 220, 12, me.hull / me.cls->hull, me.hull < 0.3 * me.cls->hull ? kHudRed : kHudGreen, "HULL");
  bar(h, x, y + 68, 220, 12, me.cls->energy > 0 ? me.energy / me.cls->energy : 0.0, kHudYellow, "ENERGY");
  const char* weapon = me.secondary == SecondaryWeapon::Plasma ? "PLASMA" : "MISSILES";
  text(h, width - 260, height - 60, 1.2, kHudWhite, std::string("beam + ") + weapon);
  text(h, width - 260, height - 36, 1.2, kHudWhite, "kills " + std::to_string(me.kills));
}

void labels(const World& w, const Projector& pr, int width, int height, HudLayer& h) {
  auto put = [&](const glm::dvec3& p, const std::string& label) {
    glm::dvec2 px;
    if (label.empty() || !pr.project(p, px)) return;
    if (px.x < -100 || px.x > width + 100 || px.y < -20 || px.y > height + 20) return;
    text(h, px.x - label.size() * 4.0, px.y, 1.0, kHudWhite, label);
  };
  for (const Prop& p : w.props) put(p.position + glm::dvec3(0, p.radius + 6.0 * p.scale, 0), p.label);
  for (const EffectSpawnDef& e : w.level.effects) put(e.position + glm::dvec3(0, 12.0 * e.scale, 0), e.label);
  // With a fixed camera nobody is "me", so ships get their names (the gallery), below them so
  // they do not collide with labels of effects placed on them.
  if (w.camera_mode != CameraMode::Fixed) return;
  for (const Ship& s : w.ships)
    if (s.alive) put(s.position - glm::dvec3(0, s.cls->shield_radius + 6.0, 0), s.name);
}

}  // namespace

void layout_hud(const World& w, const CameraView& cam, const HudState& state, double alpha, int width, int height,
                HudLayer& h) {
  alpha = std::clamp(alpha, 0.0, 1.0);
  h = HudLayer{};
  // Laid out on a canvas kHudCanvasHeight units high, then scaled to the window.
  const double scale = hud_canvas_scale(std::max(height, 1));
  width = std::max(1, int(std::lround(std::max(width, 1) / scale)));
  height = std::max(1, int(std::lround(std::max(height, 1) / scale)));
  if (state.show_fps) text(h, width - 120, 12, 1.0, kHudWhite, fmt("%.0f fps", state.fps));
  if (state.show_hud) {
    const Projector pr = Projector::of(cam, width, height);
    text(h, 24, 16, 1.2, kHudWhite, w.level.objective);
    labels(w, pr, width, height, h);
    const int focus = w.focus_ship();
    const bool flying = focus >= 0 && w.ships[focus].alive && w.camera_mode != CameraMode::Fixed;
    layout_kill_feed(w, flying ? &w.ships[focus] : nullptr, state.rules, 24, 44, h);
    if (flying) {
      const Ship& me = w.ships[focus];
      layout_combat_cues(w, me, pr, state.rules, alpha, width, height, h);
      hud_own(w, me, pr, width, height, alpha, h);
      hud_target(w, me, pr, width, height, alpha, h);
      layout_radar(w, me, state.rules, width, height, h);
    }
  }
  hud_outcome_and_menu(w, state, width, height, h);
  scale_hud(h, scale);
}

}  // namespace arc
