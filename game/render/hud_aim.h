// game/render/hud_aim.h — the aim cues at the crosshair and on the target, from the World (no GL).
//
// Each cue says which weapon it is for and tells the truth about it:
//   beam ring    a ring around the crosshair that lights, labelled "BEAM", while the beam fired
//                now would hit a hostile: the beam is instant along the nose up to its range
//                (game/sim/beams.cpp), so it needs no lead and the crosshair is its aim,
//   brackets     around the target, never smaller than 28 canvas units, bolder within beam
//                range with "IN RANGE" above; below them the distance and small shield and hull
//                bars, at any range,
//   missile cue  with missiles selected: a circle around the target labelled "MSL", whole while
//                the target is within the missile's reach and launch cone (missile_ready()),
//                broken otherwise, with no lead point since missiles home on the target,
//                over it the lock ring, red, filling clockwise from the top over the lock time
//                (game/sim/seekers.h), and once locked a bold double ring labelled "LOCK",
//   plasma lead  with plasma selected: a diamond labelled "PLS" where the bolts meet the target,
//   off-screen   an arrow toward a target out of view, where the line from the screen centre
//                toward it leaves the area between the HUD's panels, its distance beside it,
//   nav point    the waypoint a mission's route order gives the player (NavCue), likewise.
// Sizes are in canvas units (hud_draw.h); nothing is remembered between frames.
#pragma once
#include "game/render/hud_radar.h"
#include "game/render/screen_projection.h"
#include "gfx/render_view.h"

namespace arc {

class World;
struct Ship;

// Whether `me`'s beam, fired now, would hit a hostile ship first: the straight line from each
// mount along the nose, traced like the beam itself (trace_beam), within the beam's range.
bool beam_would_hit(const World& w, const Ship& me);

// A missile launched now reaches `t`: it is within the missile's speed × lifetime, and within
// the angle the missile turns in its first kMissileConeSeconds of flight off the nose.
inline constexpr double kMissileConeSeconds = 0.5;
bool missile_ready(const Ship& me, const Ship& t);

// What the aim cues show, in canvas units: where layout_aim_cues() draws each cue and what it
// says. The renderer draws from it and the test pilot (tests/unit/game/human_pilot.h) reads it,
// so the pilot sees the cues exactly as drawn.
struct TargetCues {
  bool selected = false;       // a live target: its cues (or its arrow) are drawn
  bool hostile = false;        // red, else blue
  bool on_screen = false;      // brackets around `centre`; otherwise the off-screen arrow
  glm::dvec2 centre{0.0};
  double half_size = 0;        // the brackets' half-size
  double distance = 0;         // metres, as printed under the brackets or beside the arrow
  bool in_range = false;       // within the beam's range: "IN RANGE", bolder brackets
  bool missile_cue = false;    // the "MSL" circle (missiles selected, target hostile)
  bool missile_ready = false;  //   whole: missile_ready()
  double lock = 0;             //   the lock ring, 0..1; "LOCK" at 1 (game/sim/seekers.h)
  bool plasma_lead = false;    // the "PLS" diamond at `lead` (plasma selected, target hostile)
  glm::dvec2 lead{0.0};
  glm::dvec2 arrow_dir{0.0};   // off screen: the arrow's unit direction from the screen centre
  glm::dvec2 arrow_tip{0.0};   //   and its tip, within the arrow area
};
// The nav point an event's route order gives the player's ship (levels/README.md "order"): a
// green diamond labelled "NAV" with its distance, or a green arrow toward it when out of view.
struct NavCue {
  bool shown = false;
  bool on_screen = false;
  glm::dvec2 at{0.0};          // on screen: the diamond's centre
  double distance = 0;         // metres, as printed
  glm::dvec2 arrow_dir{0.0};   // off screen: as TargetCues's arrow
  glm::dvec2 arrow_tip{0.0};
};
struct AimCues {
  glm::dvec2 crosshair{0.0};
  bool beam_ring_lit = false;  // "BEAM": beam_would_hit()
  TargetCues target;
  NavCue nav;
};
AimCues aim_cues(const World& w, const Ship& me, const Projector& pr, double alpha, double canvas_w, double canvas_h,
                 const HudRect& arrow_area);

// The crosshair with its beam ring, and the target's cues (or the off-screen arrow, drawn
// within `arrow_area`). Not drawn while paused.
void layout_aim_cues(const World& w, const Ship& me, const Projector& pr, double alpha, double canvas_w,
                     double canvas_h, const HudRect& arrow_area, HudLayer& h);

}  // namespace arc
