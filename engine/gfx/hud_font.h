// gfx/hud_font.h — turns a HudLayer (quads, lines, text in pixels) into one triangle list.
//
// Glyphs come from Dear ImGui's built-in font atlas (ProggyClean, MIT-licensed like Dear
// ImGui itself; libimgui-dev), used only as a bitmap atlas: no ImGui context or windows.
// Quads and lines sample the atlas's white pixel, so the whole HUD is one draw.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "gfx/render_view.h"

namespace arc {

struct HudVertex {
  float x, y;        // pixels, origin top-left
  float u, v;        // atlas coordinates
  float r, g, b, a;  // straight (not premultiplied) colour
};

class HudFont {
 public:
  HudFont();
  ~HudFont();
  int width() const;
  int height() const;
  const uint8_t* pixels() const;  // RGBA8 atlas, rows top to bottom
  float line_height() const;      // pixels at scale 1
  void build(const HudLayer& hud, std::vector<HudVertex>& out) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace arc
