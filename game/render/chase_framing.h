// game/render/chase_framing.h — the chase view's lift that keeps a hostile ahead clear of the own hull (no GL).
//
// The chase rig (game/sim/camera_rig.h) sits above and behind the ship, so a hostile a little
// below the nose, or close ahead, lies on the line of sight through the own hull. The frame's
// camera (frame_camera(), game/render/render_view_builder.h) then rises along the view's up,
// just enough that such a hostile shows above the hull's silhouette with a margin, and looks a
// little further down so the hull stays on screen. The lift is a continuous function of where
// the ships are at the frame's alpha (no state: replays, the window and the test pilot see the
// same view, and the simulated rig and its hashes stay as they are):
//   - per hostile: the least rise that puts it above the silhouette's upper edge (the hull's
//     box, from its collision radius, seen from the raised eye) by the margin, eased in as it
//     crosses the silhouette's sides and bottom edge, so entering from there never jumps;
//   - weighted by how near it is to the nose (full within near_nose_deg, none beyond
//     far_nose_deg) and, for one just destroyed, fading out over the explosion's first moment;
//   - the frame takes the largest, at most max_rise (a share of the ship's radius).
// The silhouette matches covered_by_hull() (game/render/own_cover.h) for a box a little larger
// than the fighters' models, so what the lift clears the pilot's cover test sees clear.
#pragma once
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "game/render/own_cover.h"

namespace arc {

class World;
struct Ship;

struct FramingRules {
  double margin_deg = 2.5;           // the hostile shows this far above the hull's silhouette
  double ease_deg = 2.5;             // the lift eases in over this much inside the silhouette's sides
  double near_nose_deg = 24.0;       // hostiles within this angle of the nose count fully...
  double far_nose_deg = 32.0;        // ... and none beyond this one
  double max_rise_per_radius = 1.1;  // the most the eye rises, in ship collision radii
  double tilt_per_rise = 0.5;        // the view turns down by this share of the hull's drop below the eye's line
  double fade_s = 0.6;               // a hostile destroyed counts for this long after, fading
};

// The own hull's box for the framing, from the ship's collision radius (it holds the fighters' models).
HullBox framing_hull(const Ship& s);

// The least rise along `up` (metres, 0..max_m) that shows `point` above the hull's silhouette
// seen from `eye` (looking along `view`'s −Z) by `margin` (tan of the angle), eased in near
// the silhouette's sides and bottom; 0 when the hull does not cover it.
double rise_to_clear(const glm::dvec3& eye, const glm::dquat& view, const glm::dvec3& ship_pos,
                     const glm::dquat& ship_orientation, const HullBox& box, const glm::dvec3& point, double max_m,
                     const FramingRules& rules = {});

struct Framing {
  double rise_m = 0;    // along the view's up
  double tilt_rad = 0;  // the view turned down about its right axis
};

// The lift for the chase view of `w`'s focus ship from `eye` / `view` (the rig at `alpha`).
Framing chase_framing(const World& w, const glm::dvec3& eye, const glm::dquat& view, double alpha,
                      const FramingRules& rules = {});

// The chase view as drawn: `eye` / `view` (the rig at `alpha`) raised and turned down by
// chase_framing().
void lift_chase_view(const World& w, double alpha, glm::dvec3& eye, glm::dquat& view);

}  // namespace arc
