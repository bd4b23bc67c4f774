// game/render/hud_radar.h — the radar at the bottom right of the HUD (no GL).
//
// Seen from above the followed ship (its nose up the screen), every other live ship is a dot
// (red hostile, blue friendly, larger for the target) with a tick for its height, and every
// missile homing on the ship a white dot. The range follows the nearest threats: it fits the
// HudRules::radar_threats nearest hostiles and incoming missiles, times radar_margin, rounded up
// to 1, 2 or 5 × 10^n m and kept within [radar_min_range, radar_max_range]; it is printed
// under the radar. radar_rect() is where it sits, so other cues can stay clear of it.
#pragma once
#include <cstdint>
#include <vector>
#include <glm/vec2.hpp>

#include "game/render/hud_rules.h"
#include "gfx/render_view.h"

namespace arc {

class World;
struct Ship;

struct HudRect {
  double x, y, w, h;
  bool overlaps(double ox, double oy, double ow, double oh) const {
    return ox < x + w && ox + ow > x && oy < y + h && oy + oh > y;
  }
};

HudRect radar_rect(double canvas_w, double canvas_h);

// One dot on the radar, in canvas units: its centre, its side, and the height tick's length
// (upward on the screen when the contact is above the ship).
enum class RadarBlipKind : uint8_t { Hostile, Friendly, Missile };
struct RadarBlip {
  glm::dvec2 at{0.0};
  double size = 0;
  double rise = 0;
  RadarBlipKind kind = RadarBlipKind::Hostile;
  bool target = false;  // the selected target's dot, drawn larger
};
// The dots layout_radar() draws (the renderer and the test pilot read the same list).
std::vector<RadarBlip> radar_blips(const World& w, const Ship& me, const HudRules& rules, double canvas_w,
                                   double canvas_h);
// The radar's range in metres for `me` now.
double radar_range(const World& w, const Ship& me, const HudRules& rules);
void layout_radar(const World& w, const Ship& me, const HudRules& rules, double canvas_w, double canvas_h,
                  HudLayer& h);

}  // namespace arc
