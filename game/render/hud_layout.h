// game/render/hud_layout.h — the HUD of one frame, laid out in pixels as plain data (no GL).
//
// layout_hud() fills a HudLayer (quads, lines and texts, origin top-left) from the World and
// the frame's camera: the objective and gallery labels; for the ship the camera follows, the
// crosshair, own shield / hull / energy bars, weapon and kills, the target's brackets or an
// off-screen arrow, the lead indicator, the target's bars and the radar; victory or defeat; the
// FPS counter and the pause menu. build_render_view() calls it last, with the frame's camera.
//
// HudState is what the app knows and the World does not: whether the HUD and the FPS counter
// are on, the measured frame rate, and the pause menu's items and selection.
#pragma once
#include <string>
#include <vector>

#include "gfx/render_view.h"

namespace arc {

class World;

struct HudState {
  bool show_hud = true;     // flight HUD, objective and labels (benchmark frames turn it off)
  bool show_fps = false;    // FPS counter (F3)
  double fps = 0;           // shown when show_fps
  int pause_selection = 0;  // highlighted pause-menu item while the game is paused
  std::vector<std::string> pause_items{"Resume", "Restart", "Difficulty: normal", "Quit"};
};

// Replaces `out` with the HUD for `camera` (interpolated like the meshes, by `alpha` in [0, 1])
// in a width × height frame.
void layout_hud(const World& world, const CameraView& camera, const HudState& state, double alpha, int width,
                int height, HudLayer& out);

}  // namespace arc
