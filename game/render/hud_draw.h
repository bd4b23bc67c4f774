// game/render/hud_draw.h — the HUD's colours and drawing primitives, shared by the HUD files
// (hud_layout.cpp, hud_combat.cpp, hud_radar.cpp); no GL.
//
// Everything is laid out on a canvas 720 units high (hud_canvas_scale()): layout_hud() scales
// the finished layer to the window, so every size follows the window height.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "gfx/render_view.h"

namespace arc {

inline const glm::vec4 kHudGreen{0.45f, 1.0f, 0.6f, 0.9f};
inline const glm::vec4 kHudRed{1.0f, 0.35f, 0.3f, 0.95f};
inline const glm::vec4 kHudBlue{0.4f, 0.7f, 1.0f, 0.9f};
inline const glm::vec4 kHudYellow{1.0f, 0.85f, 0.3f, 0.9f};
inline const glm::vec4 kHudWhite{1.0f, 1.0f, 1.0f, 0.95f};
inline const glm::vec4 kHudBack{0.0f, 0.0f, 0.0f, 0.45f};

inline constexpr double kGlyphAdvance = 7.0;  // canvas units per character at text scale 1 (gfx/hud_font: ProggyClean)
inline constexpr double kHudCanvasHeight = 720.0;  // HUD sizes are written for this window height
inline constexpr double kHudSmallestScale = 1.0;  // smaller windows keep 720p sizes: the bitmap font
                                                  // (nearest-filtered) loses rows below scale 1

// Window pixels per canvas unit.
inline double hud_canvas_scale(int window_height) {
  return std::max(kHudSmallestScale, double(window_height) / kHudCanvasHeight);
}

// HUD sizes follow the canvas height: 1 at 720 units, never below 0.5. Text never shrinks
// below the font's own size, where its one-pixel strokes would blur away.
inline double hud_height_scale(int height) { return std::max(height / 720.0, 0.5); }
inline double hud_text_scale(double at_720, int height) { return std::max(at_720 * hud_height_scale(height), 1.0); }
// The weapon lines at the bottom right: their row spacing, and the top of the first line.
inline double hud_weapon_row(int height) {
  return std::max(24 * hud_height_scale(height), 14 * hud_text_scale(1.2, height));
}
inline double hud_weapon_top(int height) { return height - 36 * hud_height_scale(height) - hud_weapon_row(height); }
// The left edge of the bottom right's column (the weapon lines and the radar above them).
inline double hud_right_column(int width, int height) { return width - 260 * hud_height_scale(height); }

// Multiplies every position, size, line width and text scale of the layer by `s`.
inline void scale_hud(HudLayer& h, double s) {
  const float k = float(s);
  for (HudQuad& q : h.quads) q.x *= k, q.y *= k, q.w *= k, q.h *= k;
  for (HudLine& l : h.lines) l.x0 *= k, l.y0 *= k, l.x1 *= k, l.y1 *= k, l.width *= k;
  for (HudText& t : h.texts) t.x *= k, t.y *= k, t.scale *= k;
}

inline void line(HudLayer& h, double x0, double y0, double x1, double y1, const glm::vec4& c, float width = 2.0f) {
  h.lines.push_back({float(x0), float(y0), float(x1), float(y1), width, c});
}
inline void quad(HudLayer& h, double x, double y, double w, double hh, const glm::vec4& c) {
  h.quads.push_back({float(x), float(y), float(w), float(hh), c});
}
inline void text(HudLayer& h, double x, double y, double scale, const glm::vec4& c, std::string s) {
  h.texts.push_back({float(x), float(y), float(scale), c, std::move(s)});
}

inline void bar(HudLayer& h, double x, double y, double w, double hh, double frac, const glm::vec4& c,
                const char* label) {
  frac = std::clamp(frac, 0.0, 1.0);
  quad(h, x, y, w, hh, kHudBack);
  quad(h, x + 1, y + 1, (w - 2) * frac, hh - 2, c);
  text(h, x, y - 16, 1.0, c, label);
}

inline void brackets(HudLayer& h, glm::dvec2 c, double r, const glm::vec4& col, float width = 2.0f) {
  r = std::max(r, 14.0);
  const double a = r * 0.4;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1}) {
      double x = c.x + sx * r, y = c.y + sy * r;
      line(h, x, y, x - sx * a, y, col, width);
      line(h, x, y, x, y - sy * a, col, width);
    }
}

inline std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// A colour with its alpha scaled, for fading cues.
inline glm::vec4 faded(glm::vec4 c, double k) {
  c.a *= float(std::clamp(k, 0.0, 1.0));
  return c;
}

}  // namespace arc
