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

// HUD sizes follow the window height: 1 at 720 pixels. Text never shrinks below the font's
// own size, where its one-pixel strokes would blur away.
double height_scale(int height) { return std::max(height / 720.0, 0.5); }
double text_scale(double at_720, int height) { return std::max(at_720 * height_scale(height), 1.0); }
constexpr double kGlyphLineHeight = 13.0; // pixels per line at text scale 1 (the font's size)

void centred_text(HudLayer& h, double cx, double y, double scale, const glm::vec4& c, const std::string& s) {
  text(h, cx - s.size() * kGlyphAdvance * scale * 0.5, y, scale, c, s);
}

// Victory or defeat stays on screen; with a menu open (the pause screen, the results) it is
// the menu's title.
void hud_outcome(const World& w, int width, int height, HudLayer& h) {
  if (w.outcome == Outcome::Undecided) return;
  const double k = height_scale(height);
  const glm::vec4 c = w.outcome == Outcome::Defeat ? kHudRed : kHudGreen;
  centred_text(h, width * 0.5, height * 0.3, text_scale(3.0, height), c, outcome_text(w));
  if (w.paused || !w.player) return;
  const std::string hint = "Esc: menu (retry, difficulty, quit)";
  centred_text(h, width * 0.5, height * 0.3 + 48 * k, text_scale(1.2, height), kHudWhite, hint);
}

// Text wrapped within the screen's margins on a dark band centred across it, `top` down.
void text_band(HudLayer& h, const std::string& s, double top, int width, int height, const glm::vec4& back,
               const glm::vec4& colour) {
  const double k = height_scale(height), scale = text_scale(1.2, height), margin = 24 * k, pad = 8 * k;
  const double line_height = 14 * scale, advance = kGlyphAdvance * scale;
  const size_t chars = size_t(std::max(8.0, (width - 2 * margin - 2 * pad) / advance));
  const std::vector<std::string> lines = wrap_text(s, chars, 6);
  size_t longest = 0;
  for (const std::string& l : lines) longest = std::max(longest, l.size());
  const double band_width = longest * advance + 2 * pad, left = (width - band_width) * 0.5;
  quad(h, left, top, band_width, lines.size() * line_height + 2 * pad, back);
  for (size_t i = 0; i < lines.size(); ++i) text(h, left + pad, top + pad + i * line_height, scale, colour, lines[i]);
}

// The notice at the top and the reload error below the target panel, both within the screen
// and clear of the bars at the bottom.
void hud_messages(const HudState& state, int width, int height, HudLayer& h) {
  const double k = height_scale(height);
  if (!state.notice.empty())
    text_band(h, state.notice, 40 * k, width, height, {0.05f, 0.1f, 0.2f, 0.8f}, {0.85f, 0.95f, 1.0f, 1.0f});
  if (!state.error_banner.empty())
    text_band(h, state.error_banner, 120 * k, width, height, {0.35f, 0.02f, 0.02f, 0.85f}, {1.0f, 0.85f, 0.8f, 1.0f});
}

// Joystick mode: the dead zone, the full-rate ring and the cursor, around the screen centre.
void hud_reticle(const HudReticle& r, int width, int height, HudLayer& h) {
  if (!r.shown) return;
  const double cx = width * 0.5, cy = height * 0.5;
  const glm::vec4 ring{0.45f, 1.0f, 0.6f, 0.25f};
  auto circle = [&](double radius) {
    constexpr int kSegments = 48;
    for (int i = 0; i < kSegments; ++i) {
      const double a0 = 6.283185307179586 * i / kSegments, a1 = 6.283185307179586 * (i + 1) / kSegments;
      line(h, cx + radius * std::cos(a0), cy + radius * std::sin(a0), cx + radius * std::cos(a1),
           cy + radius * std::sin(a1), ring, 1.0f);
    }
  };
  circle(r.radius * height);
  if (r.deadzone > 0) circle(r.deadzone * height);
  const double x = cx + r.x * height, y = cy + r.y * height, d = 8 * height_scale(height);
  line(h, cx, cy, x, y, {0.45f, 1.0f, 0.6f, 0.35f}, 1.0f);
  line(h, x - d, y, x + d, y, kHudGreen);
  line(h, x, y - d, x, y + d, kHudGreen);
}

// The set throttle as a bar at `x`, from `top` to `bottom` beside the own ship's bars, a tick
// at the speed it has reached, and the speed in m/s.
void hud_throttle_and_speed(const Ship& me, double x, double top, double bottom, int height, HudLayer& h) {
  const double k = height_scale(height), bar_w = 12 * k, bar_h = bottom - top;
  const double set = axis_value(me.controls.throttle);
  const double speed = std::sqrt(glm::dot(me.velocity, me.velocity));
  const glm::vec4 fill = set < 0 ? kHudRed : me.afterburner_on ? kHudWhite : kHudYellow;
  quad(h, x, top, bar_w, bar_h, kHudBack);
  const glm::vec4 frame{0.45f, 1.0f, 0.6f, 0.35f};
  line(h, x, top, x + bar_w, top, frame, 1.0f);
  line(h, x, top + bar_h, x + bar_w, top + bar_h, frame, 1.0f);
  line(h, x, top, x, top + bar_h, frame, 1.0f);
  line(h, x + bar_w, top, x + bar_w, top + bar_h, frame, 1.0f);
  const double filled = (bar_h - 2) * std::clamp(std::fabs(set), 0.0, 1.0);
  quad(h, x + 1, top + bar_h - 1 - filled, bar_w - 2, filled, fill);
  const double reached = std::clamp(speed / std::max(me.cls->max_speed, 1e-9), 0.0, 1.0);
  const double tick_y = top + bar_h - 1 - (bar_h - 2) * reached;
  line(h, x - 4 * k, tick_y, x + bar_w + 4 * k, tick_y, kHudWhite, float(2 * k));
  const double label_scale = text_scale(1.0, height), speed_scale = text_scale(1.4, height);
  text(h, x, top - 16 * label_scale, label_scale, kHudYellow, "THR");
  text(h, x + bar_w + 8 * k, top, speed_scale, kHudWhite, fmt("%.0f m/s", speed));
  std::string setting = fmt("%.0f%%", set * 100.0);
  if (set < 0) setting = "R " + fmt("%.0f%%", -set * 100.0);
  if (me.afterburner_on) setting += " AB";
  text(h, x + bar_w + 8 * k, top + 16 * speed_scale, text_scale(1.2, height), fill, setting);
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
  if (!me.target || !w.ship(me.target).alive) return;
  const Ship& t = w.ship(me.target);
  const glm::dvec3 tp = lerp_pos(t.prev_position, t.position, alpha);
  const glm::vec4 col = w.hostile(me, t) ? kHudRed : kHudBlue;
  glm::dvec2 px;
  double depth = 0;
  const bool in_front = pr.project(tp, px, &depth);
  const bool on_screen = in_front && px.x >= 0 && px.x <= width && px.y >= 0 && px.y <= height;
  const double dist = std::sqrt(glm::dot(t.position - me.position, t.position - me.position));
  // Paused, the pause menu stands in the middle of the screen: only the target's panel stays.
  const bool cues = !w.paused;
  if (cues && on_screen) {
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
  } else if (cues) {
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
  // Crosshair where the guns converge ahead of the nose; not while paused, where the pause
  // menu stands in the middle of the screen.
  const glm::dvec3 pos = lerp_pos(me.prev_position, me.position, alpha);
  const glm::dquat q = glm::slerp(me.prev_orientation, me.orientation, alpha);
  glm::dvec2 c(width * 0.5, height * 0.5);
  pr.project(pos + forward_of(q) * me.cls->beam.range * 0.5, c);
  if (!w.paused) {
    line(h, c.x - 14, c.y, c.x - 5, c.y, kHudGreen);
    line(h, c.x + 5, c.y, c.x + 14, c.y, kHudGreen);
    line(h, c.x, c.y - 14, c.x, c.y - 5, kHudGreen);
    line(h, c.x, c.y + 5, c.x, c.y + 14, kHudGreen);
  }
  const double x = 24, y = height - 110;
  bar(h, x, y, 220, 12, me.cls->shield > 0 ? me.shield / me.cls->shield : 0.0, kHudBlue, "SHIELD");
  bar(h, x, y + 34, 220, 12, me.hull / me.cls->hull, me.hull < 0.3 * me.cls->hull ? kHudRed : kHudGreen, "HULL");
  bar(h, x, y + 68, 220, 12, me.cls->energy > 0 ? me.energy / me.cls->energy : 0.0, kHudYellow, "ENERGY");
  hud_throttle_and_speed(me, x + 220 + 14 * height_scale(height), y, y + 68 + 12, height, h);
  const char* weapon = me.secondary == SecondaryWeapon::Plasma ? "PLASMA" : "MISSILES";
  text(h, width - 260, height - 60, 1.2, kHudWhite, std::string("beam + ") + weapon);
  text(h, width - 260, height - 36, 1.2, kHudWhite, "kills " + std::to_string(me.kills));
}

// Labels centred on (the top centre at) their world point.
void labels(const World& w, const Projector& pr, int width, int height, HudLayer& h) {
  auto put = [&](const glm::dvec3& p, const std::string& label) {
    glm::dvec2 px;
    if (label.empty() || !pr.project(p, px)) return;
    if (px.x < -100 || px.x > width + 100 || px.y < -20 || px.y > height + 20) return;
    centred_text(h, px.x, px.y, 1.0, kHudWhite, label);
  };
  for (const Prop& p : w.props) put(p.position + glm::dvec3(0, p.radius + 6.0 * p.scale, 0), p.label);
  for (const EffectSpawnDef& e : w.level.effects)
    put(e.has_label_at ? e.label_at : e.position + glm::dvec3(0, 12.0 * e.scale, 0), e.label);
  // With a fixed camera nobody is "me", so ships get their labels (their names unless the level
  // says otherwise), below them so they do not collide with labels of effects placed on them.
  if (w.camera_mode != CameraMode::Fixed) return;
  for (size_t i = 0; i < w.ships.size() && i < w.level.ships.size(); ++i) {
    const Ship& s = w.ships[i];
    const ShipSpawnDef& def = w.level.ships[i];
    if (s.alive) put(s.position - glm::dvec3(0, s.cls->shield_radius + 6.0, 0), def.has_label ? def.label : s.name);
  }
}

}  // namespace

std::string outcome_text(const World& w) {
  return w.outcome == Outcome::Victory  ? "VICTORY"
         : w.outcome == Outcome::Defeat ? "DEFEAT"
                                        : "TEAM " + w.team_name(w.winner) + " WINS";
}

void layout_hud(const World& w, const CameraView& cam, const HudState& state, double alpha, int width, int height,
                HudLayer& h) {
  alpha = std::clamp(alpha, 0.0, 1.0);
  h = HudLayer{};
  // Laid out on a canvas kHudCanvasHeight units high, then scaled to the window.
  const double scale = hud_canvas_scale(std::max(height, 1));
  width = std::max(1, int(std::lround(std::max(width, 1) / scale)));
  height = std::max(1, int(std::lround(std::max(height, 1) / scale)));
  if (state.show_fps) {
    text(h, width - 120, 12, 1.0, kHudWhite, fmt("%.0f fps", state.fps));
    if (!state.frame_stats.empty()) text(h, width / 2 - 300, 4, 0.8, kHudWhite, state.frame_stats);
  }
  if (state.show_hud) {
    const Projector pr = Projector::of(cam, width, height);
    text(h, 24, 16, 1.2, kHudWhite, w.level.objective);
    labels(w, pr, width, height, h);
    const ShipId focus = w.focus_ship();
    const bool flying = focus && w.ship(focus).alive && w.camera_mode != CameraMode::Fixed;
    layout_kill_feed(w, flying ? &w.ship(focus) : nullptr, state.rules, 24, 44, h);
    if (flying) {
      const Ship& me = w.ship(focus);
      if (!w.paused) layout_combat_cues(w, me, pr, state.rules, alpha, width, height, h);
      hud_own(w, me, pr, width, height, alpha, h);
      hud_target(w, me, pr, width, height, alpha, h);
      layout_radar(w, me, state.rules, width, height, h);
    }
  }
  hud_reticle(state.reticle, width, height, h);
  if (state.show_outcome) hud_outcome(w, width, height, h);
  hud_messages(state, width, height, h);
  scale_hud(h, scale);
}

HudBox text_box(const HudText& t) {
  size_t longest = 0, lines = 1, run = 0;
  for (char c : t.text) {
    run = c == '\n' ? 0 : run + 1;
    lines += c == '\n' ? 1 : 0;
    longest = std::max(longest, run);
  }
  return {t.x, t.y, t.x + longest * kGlyphAdvance * t.scale, t.y + lines * kGlyphLineHeight * t.scale};
}

std::vector<std::string> wrap_text(const std::string& original, size_t max_chars, size_t max_lines) {
  max_chars = std::max<size_t>(max_chars, 4);
  std::string text = original;  // line breaks and tabs of the message become spaces
  std::replace_if(text.begin(), text.end(), [](char c) { return c == '\n' || c == '\t' || c == '\r'; }, ' ');
  std::vector<std::string> lines;
  std::string current;
  size_t i = 0;
  while (lines.size() < max_lines) {
    while (i < text.size() && text[i] == ' ') ++i;
    if (i >= text.size()) break;
    const size_t end = std::min(text.find(' ', i), text.size());
    const std::string word = text.substr(i, end - i);
    const size_t need = current.empty() ? word.size() : current.size() + 1 + word.size();
    if (need <= max_chars) {
      current += (current.empty() ? "" : " ") + word;
      i += word.size();
    } else if (!current.empty()) {
      lines.push_back(std::move(current));
      current.clear();
    } else {
      lines.push_back(word.substr(0, max_chars));  // a word longer than a line is cut across lines
      i += max_chars;
    }
  }
  const bool cut = i < text.size();
  if (!current.empty() && lines.size() < max_lines) lines.push_back(std::move(current));
  if (cut && !lines.empty()) {
    std::string& last = lines.back();
    last = last.substr(0, std::min(last.size(), max_chars - 3)) + "...";
  }
  return lines;
}

}  // namespace arc
