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
//                broken otherwise; missiles home on the target, so they need no lead point;
//                over it the lock ring, red, filling clockwise from the top over the lock time
//                (game/sim/seekers.h), and once locked a bold double ring labelled "LOCK",
//   plasma lead  with plasma selected: a diamond labelled "PLS" where the bolts meet the target,
//   off-screen   an arrow toward a target out of view, where the line from the screen centre
//                toward it leaves the area between the HUD's panels, its distance beside it.
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

// The crosshair with its beam ring, and the target's cues (or the off-screen arrow, drawn
// within `arrow_area`). Not drawn while paused.
void layout_aim_cues(const World& w, const Ship& me, const Projector& pr, double alpha, double canvas_w,
                     double canvas_h, const HudRect& arrow_area, HudLayer& h);

}  // namespace arc
