// HUD layout: every HUD element in pixels, from the World, the frame's camera and HudState.
#include "game/render/hud_layout.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "game/render/hud_aim.h"
#include "game/render/hud_combat.h"
#include "game/render/hud_comms.h"
#include "game/render/hud_draw.h"
#include "game/render/hud_radar.h"
#include "game/render/hud_objectives.h"
#include "game/render/hud_training.h"
#include "game/render/screen_projection.h"
#include "game/sim/world.h"

namespace arc {
namespace {

double height_scale(int height) { return hud_height_scale(height); }
double text_scale(double at_720, int height) { return hud_text_scale(at_720, height); }
constexpr double kGlyphLineHeight = 13.0; // pixels per line at text scale 1 (the font's size)
constexpr double kLeftMargin = 24.0;      // canvas units from the left edge to the panels there
constexpr double kSideMargin = 12.0;      // at 720p, the least gap to the right edge and between panels
constexpr double kBarLabelRise = 16.0;    // bar() puts its label this far above the bar, at text scale 1
constexpr double kKillFeedRow = 18.0;     // layout_kill_feed()'s line spacing
constexpr size_t kObjectiveLines = 2;
constexpr size_t kTargetPanelChars = 25;  // the target's name, class and distance fit this many

// The target panel's width at the top right, reserved whether a target is shown or not so the
// objective does not reflow when one is picked.
double target_panel_width(int height) {
  const double k = height_scale(height);
  return std::max(230 * k, kTargetPanelChars * kGlyphAdvance * text_scale(1.2, height) + kSideMargin * k);
}

// The target panel's rows: its name, then the shield bar and the hull bar, each with its label.
struct TargetPanelRows {
  double name_y, shield_y, hull_y, bar_h;
};
TargetPanelRows target_panel_rows(int height) {
  const double k = height_scale(height), s = text_scale(1.2, height), bar_h = 10 * k, name_y = 30 * k;
  const double shield_y = name_y + std::max(40 * k, kGlyphLineHeight * s + kBarLabelRise + 2);
  return {name_y, shield_y, shield_y + std::max(30 * k, bar_h + kBarLabelRise + 2), bar_h};
}
double target_panel_bottom(int height) {
  const TargetPanelRows r = target_panel_rows(height);
  return r.hull_y + r.bar_h;
}

// The own bars' row spacing and the first bar's top, at the bottom left.
double own_bar_row(int height) {
  const double k = height_scale(height);
  return std::max(34 * k, kBarLabelRise + 12 * k + 4);
}
double own_bars_top(int height) {
  const double k = height_scale(height);
  return height - 30 * k - 2 * own_bar_row(height) - 12 * k;
}

double weapon_row(int height) { return hud_weapon_row(height); }

// The right end of the own bars with the throttle and its widest speed ("1000 m/s").
double own_panel_right(int height) {
  const double k = height_scale(height);
  return kLeftMargin + 220 * k + 14 * k + 12 * k + 8 * k + 8 * kGlyphAdvance * text_scale(1.4, height);
}

// Where the off-screen arrow may stand: inside the screen edges, under the top panels (the
// target panel and the longest kill feed) and above the bottom ones (bars, radar, weapon).
HudRect arrow_area(double feed_y, int kill_feed_lines, int width, int height) {
  const double k = height_scale(height), margin = 30 * k;
  const double top = std::max(target_panel_bottom(height), feed_y + kKillFeedRow * std::max(kill_feed_lines, 0));
  const double bars_top = own_bars_top(height) - kBarLabelRise * text_scale(1.0, height);
  const double bottom = std::min({bars_top, radar_rect(width, height).y, height - 36 * k - weapon_row(height)});
  return {margin, top + margin, std::max(1.0, width - 2 * margin), std::max(1.0, bottom - top - 2 * margin)};
}

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

// Text wrapped within the screen's margins on a dark band centred across it, `y` down from
// its top, or up from its bottom when `from_bottom`.
void text_band(HudLayer& h, const std::string& s, double y, bool from_bottom, int width, int height,
               const glm::vec4& back, const glm::vec4& colour, double max_band_width = 0) {
  const double k = height_scale(height), scale = text_scale(1.2, height), margin = 24 * k, pad = 8 * k;
  const double line_height = 14 * scale, advance = kGlyphAdvance * scale;
  double room = width - 2 * margin;
  if (max_band_width > 0) room = std::min(room, max_band_width);
  const size_t chars = size_t(std::max(8.0, (room - 2 * pad) / advance));
  const std::vector<std::string> lines = wrap_text(s, chars, 6);
  size_t longest = 0;
  for (const std::string& l : lines) longest = std::max(longest, l.size());
  const double band_width = longest * advance + 2 * pad, left = (width - band_width) * 0.5;
  const double band_height = lines.size() * line_height + 2 * pad, top = from_bottom ? y - band_height : y;
  quad(h, left, top, band_width, band_height, back);
  for (size_t i = 0; i < lines.size(); ++i) text(h, left + pad, top + pad + i * line_height, scale, colour, lines[i]);
}

// The notice at the bottom centre, growing upward between the own bars and the right column:
// the top of the screen belongs to the objective, the kill feed and the target panel, and the
// middle to the fight (the chase view's own ship sits just above the notice).
void hud_notice(const HudState& state, int width, int height, HudLayer& h) {
  if (state.notice.empty()) return;
  const double k = height_scale(height), gap = kSideMargin * k;
  const double half = std::min(width * 0.5 - own_panel_right(height), hud_right_column(width, height) - width * 0.5);
  text_band(h, state.notice, height - gap, true, width, height, {0.05f, 0.1f, 0.2f, 0.8f},
            {0.85f, 0.95f, 1.0f, 1.0f}, std::max(2 * (half - gap), 16 * kGlyphAdvance));
}

// The radio line being spoken, centred over the notice's place above the radar.
void hud_subtitle(const HudState& state, int width, int height, HudLayer& h) {
  if (state.subtitle.empty()) return;
  const double bottom = radar_rect(width, height).y - 64 * height_scale(height);
  text_band(h, state.subtitle, bottom, true, width, height, {0.0f, 0.0f, 0.0f, 0.6f}, {1.0f, 0.95f, 0.7f, 1.0f});
}

// The reload error under the top panels: the target panel, the longest kill feed and the F3
// figures (`figures_bottom`, 0 without them).
void hud_error_banner(const HudState& state, double feed_y, int kill_feed_lines, double figures_bottom, int width,
                      int height, HudLayer& h) {
  if (state.error_banner.empty()) return;
  const double k = height_scale(height);
  const double feed_bottom = feed_y + kKillFeedRow * std::max(kill_feed_lines, 0);
  const double top = std::max({target_panel_bottom(height), feed_bottom, figures_bottom}) + 8 * k;
  text_band(h, state.error_banner, top, false, width, height, {0.35f, 0.02f, 0.02f, 0.85f}, {1.0f, 0.85f, 0.8f, 1.0f});
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

// The target's name, class, distance and bars at the top right.
void hud_target_panel(const World& w, const Ship& me, int width, int height, HudLayer& h) {
  if (!me.target || !w.ship(me.target).alive) return;
  const Ship& t = w.ship(me.target);
  const glm::vec4 col = w.hostile(me, t) ? kHudRed : kHudBlue;
  const double k = height_scale(height), s = text_scale(1.2, height), x = width - target_panel_width(height);
  const size_t room = size_t(std::max(1.0, (target_panel_width(height) - kSideMargin * k) / (kGlyphAdvance * s)));
  const std::string dist = " " + fmt("%.0f m", glm::length(t.position - me.position));
  std::string name = t.name + " (" + t.cls->name + ")";
  if (name.size() + dist.size() > room) name = t.name;
  if (name.size() + dist.size() > room) name = name.substr(0, room > dist.size() ? room - dist.size() : 0);
  const TargetPanelRows rows = target_panel_rows(height);
  text(h, x, rows.name_y, s, col, name + dist);
  bar(h, x, rows.shield_y, 200 * k, rows.bar_h, t.cls->shield > 0 ? t.shield / t.cls->shield : 0.0, kHudBlue, "shield");
  bar(h, x, rows.hull_y, 200 * k, rows.bar_h, t.hull / t.cls->hull, kHudRed, "hull");
}

// The objective at the top left, wrapped to leave room for the target panel while flying;
// returns the top of the kill feed under it.
// The frame figures (F3): the frame rate, then the renderer's particle figures, wrapped to the
// target panel's column and right-aligned in it under the panel, where the objective, the
// training prompt, the radar and the own ship never reach (the kill feed stops short of it);
// returns their bottom.
double hud_frame_stats(const HudState& state, int width, int height, HudLayer& h) {
  const double k = height_scale(height), s = 0.8, row = kGlyphLineHeight * s + 2;
  const double right = width - kSideMargin * k, room = target_panel_width(height) - kSideMargin * k;
  const size_t chars = size_t(std::max(8.0, room / (kGlyphAdvance * s)));
  std::vector<std::string> lines{fmt("%.0f fps", state.fps)};
  for (size_t at = 0; !state.frame_stats.empty() && at != std::string::npos;) {
    const size_t bar = state.frame_stats.find(" | ", at);
    for (const std::string& l : wrap_text(state.frame_stats.substr(at, bar == std::string::npos ? bar : bar - at), chars, 3))
      lines.push_back(l);
    at = bar == std::string::npos ? bar : bar + 3;
  }
  double y = target_panel_bottom(height) + 8 * k;
  for (const std::string& l : lines) {
    text(h, std::max(4.0, right - double(l.size()) * kGlyphAdvance * s), y, s, kHudWhite, l);
    y += row;
  }
  return y;
}

double hud_objective(const std::string& objective, bool flying, int width, int height, HudLayer& h) {
  const double k = height_scale(height), s = 1.2, x = kLeftMargin, y = 16;
  const double room = width - (flying ? target_panel_width(height) : 0.0) - kSideMargin * k - x;
  const std::vector<std::string> lines =
      wrap_text(objective, size_t(std::max(8.0, room / (kGlyphAdvance * s))), kObjectiveLines);
  for (size_t i = 0; i < lines.size(); ++i) text(h, x, y + 14 * s * double(i), s, kHudWhite, lines[i]);
  return std::max(44 * k, y + 14 * s * double(std::max<size_t>(lines.size(), 1)) + 4);
}

// The own ship's shield, hull and energy bars with the throttle at the bottom left.
// Rows keep room for each bar's label (16 above it, at text scale 1) in small windows.
void hud_own(const Ship& me, int height, HudLayer& h) {
  const double k = height_scale(height), x = kLeftMargin, bar_w = 220 * k, bar_h = 12 * k;
  const double row = own_bar_row(height), y = own_bars_top(height);
  bar(h, x, y, bar_w, bar_h, me.cls->shield > 0 ? me.shield / me.cls->shield : 0.0, kHudBlue, "SHIELD");
  bar(h, x, y + row, bar_w, bar_h, me.hull / me.cls->hull, me.hull < 0.3 * me.cls->hull ? kHudRed : kHudGreen, "HULL");
  bar(h, x, y + 2 * row, bar_w, bar_h, me.cls->energy > 0 ? me.energy / me.cls->energy : 0.0, kHudYellow, "ENERGY");
  hud_throttle_and_speed(me, x + bar_w + 14 * k, y, y + 2 * row + bar_h, height, h);
}

// The selected weapons, the flares left and the kills at the bottom right.
void hud_weapon(const Ship& me, int width, int height, HudLayer& h) {
  const double k = height_scale(height), s = text_scale(1.2, height), row = weapon_row(height);
  const std::string weapon = std::string(me.cls->primary_plasma ? "plasma + " : "beam + ") +
                             (me.secondary == SecondaryWeapon::Plasma    ? "PLASMA"
                              : me.secondary == SecondaryWeapon::Torpedo ? "TORPEDO"
                                                                          : "MISSILES");
  const std::string kills = (me.cls->countermeasures.count > 0 ? "flares " + std::to_string(me.seeker.flares) + "  " : "") +
                            "kills " + std::to_string(me.kills);
  const double wide = double(std::max(weapon.size(), kills.size())) * kGlyphAdvance * s;
  const double x = std::min(hud_right_column(width, height), width - kSideMargin * k - wide), y = height - 36 * k;
  text(h, x, y - row, s, kHudWhite, weapon);
  text(h, x, y, s, kHudWhite, kills);
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

// Where each panel's drawing starts and ends in the layer, for its box.
struct PanelMark {
  const char* name;
  size_t quads[2], lines[2], texts[2];
};

class PanelMarks {
 public:
  PanelMarks(HudLayer& h, bool on) : h_(h), on_(on) {}
  template <class Draw>
  void panel(const char* name, Draw&& draw) {
    PanelMark m{name, {h_.quads.size(), 0}, {h_.lines.size(), 0}, {h_.texts.size(), 0}};
    draw();
    m.quads[1] = h_.quads.size(), m.lines[1] = h_.lines.size(), m.texts[1] = h_.texts.size();
    if (on_) marks_.push_back(m);
  }
  // The boxes of the marked panels that drew anything, from the finished (scaled) layer.
  void boxes(std::vector<HudPanelBox>& out) const {
    out.clear();
    for (const PanelMark& m : marks_) {
      HudBox b{1e30, 1e30, -1e30, -1e30};
      auto add = [&b](double x0, double y0, double x1, double y1) {
        b = {std::min(b.x0, x0), std::min(b.y0, y0), std::max(b.x1, x1), std::max(b.y1, y1)};
      };
      for (size_t i = m.quads[0]; i < m.quads[1]; ++i) {
        const HudQuad& q = h_.quads[i];
        add(q.x, q.y, q.x + q.w, q.y + q.h);
      }
      for (size_t i = m.lines[0]; i < m.lines[1]; ++i) {
        const HudLine& l = h_.lines[i];
        const double r = l.width * 0.5;
        add(std::min(l.x0, l.x1) - r, std::min(l.y0, l.y1) - r, std::max(l.x0, l.x1) + r, std::max(l.y0, l.y1) + r);
      }
      for (size_t i = m.texts[0]; i < m.texts[1]; ++i) {
        const HudBox t = text_box(h_.texts[i]);
        add(t.x0, t.y0, t.x1, t.y1);
      }
      if (b.x1 >= b.x0) out.push_back({m.name, b});
    }
  }

 private:
  HudLayer& h_;
  bool on_;
  std::vector<PanelMark> marks_;
};

}  // namespace

std::string outcome_text(const World& w) {
  return w.outcome == Outcome::Victory  ? "VICTORY"
         : w.outcome == Outcome::Defeat ? "DEFEAT"
                                        : "TEAM " + w.team_name(w.winner) + " WINS";
}

void layout_hud(const World& w, const CameraView& cam, const HudState& state, double alpha, int width, int height,
                HudLayer& h, std::vector<HudPanelBox>* panels) {
  alpha = std::clamp(alpha, 0.0, 1.0);
  h = HudLayer{};
  PanelMarks marks(h, panels != nullptr);
  // Laid out on a canvas kHudCanvasHeight units high, then scaled to the window.
  const double scale = hud_canvas_scale(std::max(height, 1));
  width = std::max(1, int(std::lround(std::max(width, 1) / scale)));
  height = std::max(1, int(std::lround(std::max(height, 1) / scale)));
  double feed_y = 44 * height_scale(height);  // the kill feed's top, under the objective
  double figures_bottom = 0;  // the F3 frame figures' bottom, for the error banner under them
  if (state.show_fps && !state.net.scoreboard) {  // the held scoreboard stands in for the F3 figures
    marks.panel("frame stats", [&] { figures_bottom = hud_frame_stats(state, width, height, h); });
    if (state.net.on) marks.panel("net stats", [&] { hud_net_stats(state.net, width, height, h); });
  }
  if (state.show_hud) {
    const Projector pr = Projector::of(cam, width, height);
    const ShipId focus = w.focus_ship();
    const bool flying = focus && w.ship(focus).alive && w.camera_mode != CameraMode::Fixed;
    if (training_prompt_shown(w)) {
      // The training step's prompt takes the objective's place, in the room the target panel leaves.
      const double x1 = flying ? width - target_panel_width(height) - kSideMargin * height_scale(height) : width - kLeftMargin;
      marks.panel("training", [&] {
        feed_y = std::max(feed_y, hud_training_prompt(w, state.key_names, kLeftMargin, x1, 12, width, h) + 6);
      });
    } else {
      marks.panel("objective", [&] { feed_y = hud_objective(w.level.objective, flying, width, height, h); });
      if (w.mission) marks.panel("objectives", [&] { feed_y = hud_objectives(w, kLeftMargin, feed_y, h); });
    }
    labels(w, pr, width, height, h);
    if (state.net.on) hud_net_names(w, state.net, pr, width, height, h);
    // The held scoreboard stands in for the panels while it is up.
    if (state.net.scoreboard) marks.panel("scoreboard", [&] { hud_scoreboard(w, state.net, width, height, h); });
    if (!state.net.scoreboard)
      marks.panel("kill feed", [&] {
        const double right = figures_bottom > 0 ? width - target_panel_width(height) - kSideMargin * height_scale(height) : 0;
        layout_kill_feed(w, flying ? &w.ship(focus) : nullptr, state.rules, kLeftMargin, feed_y, h, &state.net.names, right);
      });
    if (flying && !state.net.scoreboard) {
      const Ship& me = w.ship(focus);
      if (!w.paused) layout_combat_cues(w, me, pr, state.rules, alpha, width, height, h);
      const HudRect arrows = arrow_area(feed_y, state.rules.kill_feed_lines, width, height);
      layout_aim_cues(w, me, pr, alpha, width, height, arrows, h);
      marks.panel("own bars", [&] { hud_own(me, height, h); });
      marks.panel("weapon", [&] { hud_weapon(me, width, height, h); });
      marks.panel("target panel", [&] { hud_target_panel(w, me, width, height, h); });
      marks.panel("radar", [&] { layout_radar(w, me, state.rules, width, height, h); });
      if (state.comms_open) marks.panel("comms", [&] { hud_comms_menu(w, width, height, h); });
    }
  }
  hud_reticle(state.reticle, width, height, h);
  if (state.show_outcome) hud_outcome(w, width, height, h);
  marks.panel("notice", [&] { hud_notice(state, width, height, h); });
  if (state.show_hud) hud_subtitle(state, width, height, h);
  if (!state.net.scoreboard)  // back when the scoreboard's key is let go
    marks.panel("error banner",
                [&] { hud_error_banner(state, feed_y, state.rules.kill_feed_lines, figures_bottom, width, height, h); });
  scale_hud(h, scale);
  if (panels) marks.boxes(*panels);
}

HudPicture hud_picture(const World& w, const CameraView& cam, const HudState& state, double alpha, int width,
                       int height) {
  HudPicture pic;
  alpha = std::clamp(alpha, 0.0, 1.0);
  pic.scale = hud_canvas_scale(std::max(height, 1));
  width = std::max(1, int(std::lround(std::max(width, 1) / pic.scale)));
  height = std::max(1, int(std::lround(std::max(height, 1) / pic.scale)));
  const ShipId focus = w.focus_ship();
  pic.flying = state.show_hud && !w.paused && focus && w.ship(focus).alive && w.camera_mode != CameraMode::Fixed;
  if (!pic.flying) return pic;
  const Ship& me = w.ship(focus);
  HudLayer scratch;  // the objective's height decides where the off-screen arrow may stand
  const double feed_y = hud_objective(w.level.objective, true, width, height, scratch);
  const HudRect arrows = arrow_area(feed_y, state.rules.kill_feed_lines, width, height);
  pic.aim = aim_cues(w, me, Projector::of(cam, width, height), alpha, width, height, arrows);
  pic.radar = radar_rect(width, height);
  pic.radar_blips = radar_blips(w, me, state.rules, width, height);
  pic.threats = threat_cues(w, me, Projector::of(cam, width, height), state.rules, alpha, width, height);
  // To window pixels, as scale_hud() scales the drawn layer.
  const double k = pic.scale;
  pic.aim.crosshair *= k;
  TargetCues& t = pic.aim.target;
  t.centre *= k, t.half_size *= k, t.lead *= k, t.arrow_tip *= k;
  pic.aim.nav.at *= k, pic.aim.nav.arrow_tip *= k;
  pic.radar = {pic.radar.x * k, pic.radar.y * k, pic.radar.w * k, pic.radar.h * k};
  for (RadarBlip& b : pic.radar_blips) b.at *= k, b.size *= k, b.rise *= k;
  return pic;
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
