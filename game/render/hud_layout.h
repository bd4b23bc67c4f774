// game/render/hud_layout.h — the HUD of one frame, laid out in pixels as plain data (no GL).
//
// layout_hud() fills a HudLayer (quads, lines and texts, origin top-left) from the World and
// the frame's camera: the objective, the kill feed and gallery labels; for the ship the camera
// follows, the aim cues (hud_aim.h: the crosshair's beam ring, the target's brackets, missile
// cue or plasma lead, the off-screen arrow between the panels), own shield / hull / energy bars,
// weapon and kills, the target's panel, the radar (hud_radar.h) and the combat cues
// (hud_combat.h: hit markers, damage direction, missile warning); the set throttle and the
// speed; victory or defeat; the FPS counter, the mouse-joystick reticle, a notice line above
// the radar and the reload-error banner under the top panels (both wrapped to the screen). The
// pause screen is a menu page (menu_layout.h) over it. build_render_view() calls it last, with
// the frame's camera.
//
// Every size is written for a window 720 pixels high and the finished layer is scaled to the
// window's height (hud_draw.h), so the HUD looks the same at 1280x720 and at 2560x1440. In
// windows less than 720 pixels high the panels shrink with the height (to half at 360) while
// text keeps the bitmap font's own size, where it stays sharp; the panels' rows and widths make
// room for it, so no panel overlaps another at any size from 640x360 up.
//
// HudState is what the app knows and the World does not: whether the HUD and the FPS counter
// are on, the measured frame rate, the reticle, the comms menu, and the notice and error texts.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "game/render/hud_aim.h"
#include "game/render/hud_combat.h"
#include "game/render/hud_net.h"
#include "game/render/hud_radar.h"
#include "game/render/hud_rules.h"
#include "gfx/render_view.h"

namespace arc {

class World;

// The mouse-joystick mode's virtual cursor, in screen heights from the centre (+y down).
struct HudReticle {
  bool shown = false;
  double x = 0, y = 0, radius = 0, deadzone = 0;
};

struct HudState {
  bool show_hud = true;     // flight HUD, objective and labels (benchmark frames turn it off)
  bool show_outcome = true; // victory or defeat, large (off under the results screen)
  bool show_fps = false;    // FPS counter (F3)
  double fps = 0;           // shown when show_fps
  std::string frame_stats;  // shown under it when show_fps: the renderer's particle figures
  HudReticle reticle;
  bool comms_open = false;   // the comms menu (hud_comms.h) is drawn while flying
  std::string notice;        // one line above the radar (e.g. "Recording stopped ...")
  std::string subtitle;      // the radio line being spoken ("Wing: Copy. Engaging your target."), over the notice
  std::string error_banner;  // a failed hot reload, wrapped within the screen below the objective
  HudRules rules;           // tunable numbers (assets/settings/hud.json), also the own-effect view rules
  // Remappable action id → its key's name ("target_nearest" → "R"), for training prompts
  // (hud_training.h); the app fills it from the live bindings.
  std::map<std::string, std::string> key_names;
  NetHud net;  // a network match's names, figures and scoreboard (hud_net.h)
};

// A decided fight's verdict: "VICTORY" or "DEFEAT" for the player, else "TEAM NAME WINS".
std::string outcome_text(const World& w);

// The box a text of the layer covers, in the layer's pixels: every line of the bitmap font
// (gfx/hud_font, ProggyClean) is 13 pixels high and each character 7 wide at scale 1. Tests
// check with it that texts (the gallery's labels) neither overlap nor leave the screen.
struct HudBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
HudBox text_box(const HudText& t);

// A panel of the HUD (own bars, radar, target panel, weapon text, objective, kill feed, notice,
// error banner) and the box of everything it drew, in window pixels: the panels must neither
// overlap nor leave the screen at any window size (tests/unit/game/test_hud_layout.cpp).
struct HudPanelBox {
  std::string name;
  HudBox box;
};

// Replaces `out` with the HUD for `camera` (interpolated like the meshes, by `alpha` in [0, 1])
// in a width × height frame; `panels`, when given, receives the box of each panel drawn.
void layout_hud(const World& world, const CameraView& camera, const HudState& state, double alpha, int width,
                int height, HudLayer& out, std::vector<HudPanelBox>* panels = nullptr);

// What a player reads off the flight HUD that layout_hud() would draw for `camera` in a
// width × height window, in window pixels: the aim cues (hud_aim.h) and the radar's dots
// (hud_radar.h), from the same functions the layout draws with. The test pilot
// (tests/unit/game/human_pilot.h) plays from this alone.
struct HudPicture {
  bool flying = false;  // the followed ship is alive and the flight HUD is on: the rest is drawn
  double scale = 1;     // window pixels per canvas unit (hud_canvas_scale)
  AimCues aim;
  HudRect radar{0, 0, 0, 0};
  std::vector<RadarBlip> radar_blips;
  ThreatCues threats;  // the damage wedges and the missile warning
};
HudPicture hud_picture(const World& world, const CameraView& camera, const HudState& state, double alpha, int width,
                       int height);

// `text` broken at spaces (and inside words longer than a line; its own line breaks count as
// spaces) into lines of at most `max_chars` characters; at most `max_lines`, the last ending
// in "..." when text is cut.
std::vector<std::string> wrap_text(const std::string& text, size_t max_chars, size_t max_lines);

}  // namespace arc
