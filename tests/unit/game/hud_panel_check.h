// tests/unit/game/hud_panel_check.h — the HUD layout's panels checked at every window size from 640x360 to 3840x2160.
//
// check_hud_panels(w, state, want) lays out the HUD of `w` with `state` at each size of
// kHudSizes, as build_render_view() frames it, and expects every panel named in `want` to be
// drawn, the radar at least 15 % of the height, and no panel to overlap another or leave the
// screen. Shared by the HUD layout and net HUD tests.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "game/render/hud_layout.h"
#include "game/render/render_view_builder.h"
#include "game/sim/world.h"

namespace arc::test {

// The smallest and largest windows, the common 16:9 ones between and a 16:10 one.
inline const std::vector<std::pair<int, int>> kHudSizes = {{640, 360},   {960, 540},   {1280, 720},  {1280, 800},
                                                           {1920, 1080}, {2560, 1440}, {3840, 2160}};

inline std::string box_text(const HudPanelBox& p) {
  return p.name + " [" + std::to_string(int(p.box.x0)) + "," + std::to_string(int(p.box.y0)) + " - " +
         std::to_string(int(p.box.x1)) + "," + std::to_string(int(p.box.y1)) + "]";
}

// The panels layout_hud() draws for `w` at width × height, framed as the game frames it.
inline std::vector<HudPanelBox> hud_panels(const World& w, const HudState& state, int width, int height,
                                           RenderView* view = nullptr) {
  RenderView v;
  build_render_view(w, {}, 1.0, CameraSettings{}, state, width, height, v);
  std::vector<HudPanelBox> panels;
  layout_hud(w, v.camera, state, 1.0, width, height, v.hud, &panels);
  if (view) *view = std::move(v);
  return panels;
}

inline void check_hud_panels(const World& w, const HudState& state, const std::vector<std::string>& want) {
  for (auto [width, height] : kHudSizes) {
    const std::vector<HudPanelBox> panels = hud_panels(w, state, width, height);
    const std::string at = " at " + std::to_string(width) + "x" + std::to_string(height);
    for (const std::string& name : want) {
      EXPECT_TRUE(std::any_of(panels.begin(), panels.end(), [&](const HudPanelBox& p) { return p.name == name; }))
          << name << at;
    }
    for (const HudPanelBox& p : panels) {
      if (p.name == "radar") {
        EXPECT_GE(p.box.y1 - p.box.y0, 0.15 * height) << "radar" << at;
      }
    }
    for (size_t i = 0; i < panels.size(); ++i) {
      const HudBox& a = panels[i].box;
      EXPECT_TRUE(a.x0 >= 0 && a.y0 >= 0 && a.x1 <= width && a.y1 <= height) << box_text(panels[i]) << " leaves the screen" << at;
      for (size_t j = i + 1; j < panels.size(); ++j) {
        const HudBox& b = panels[j].box;
        EXPECT_FALSE(a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1)
            << box_text(panels[i]) << " overlaps " << box_text(panels[j]) << at;
      }
    }
  }
}

}  // namespace arc::test
