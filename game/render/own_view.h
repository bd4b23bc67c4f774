// game/render/own_view.h — keeps the followed ship's own effects out of its pilot's eyes (no GL).
//
// The simulation draws every ship's shield, exhausts and beam alike; only the view knows which
// ship the camera rides with. After collect(), keep_own_effects_out_of_view() edits that ship's
// particles (found by their cluster, ParticleInstance::cluster = ClusterHandle::index):
//   chase:   shield particles fade out around the crosshair, so nothing of the own sphere lies
//            between the camera and the view ahead, and the sphere shows only as its rim (the
//            part seen edge-on), so a hit lights a thin outline, never a screen-filling glow
//            (the impact's own sparks are other particles and stay);
//   chase:   the sparks and smoke of hits around the own ship and of anything near the eye
//            (hull sparks the ship leaves behind, which the camera flies through) are kept
//            to a small size on screen and fade out toward the eye, so an impact reads as a
//            flash where it landed instead of streaks and smoke over the whole screen (a ship
//            blowing up there keeps its whole fireball and smoke);
//   cockpit: no own shield and no own exhaust (the camera sits inside the sphere);
//   both:    the own beam fades out toward the eye and is never wider on screen than a few
//            pixels, so it starts at the muzzles as a thin bolt instead of filling the view;
//            other ships' beams have a wider limit, so one striking the own shield a few
//            metres from the eye stays a bolt instead of a screen-filling flare.
// A hit on the ship also shows as a glow at the screen edge toward it (hud_combat.h).
#pragma once
#include <vector>

#include "game/sim/ids.h"
#include "gfx/render_view.h"

namespace arc {

class World;

struct OwnViewRules {
  double clear_radius = 0.25;     // chase: own shield gone within this share of the screen height around the crosshair
  double clear_fade = 0.12;       // ... and fading back in over this much more
  double rim_facing = 0.2;        // chase: own shield kept where |cos| between its normal and the view ray is below this
  double rim_fade = 0.15;         // ... fading out over this much more (rim_facing 1: the whole sphere)
  double near_own_radius = 1.6;   // chase: hits within this many shield radii of the own ship's centre...
  double near_eye_m = 12.0;       // ... or within this many metres of the eye...
  double near_half_width = 0.012; // ... are at most this half-width on screen (share of the height)...
  double near_eye_fade = 10.0;    // ... and fade to nothing over this many metres toward the eye
  double beam_half_width = 0.005; // own beam: widest half-width on screen, share of the screen height
  double beam_near_fade = 6.0;    // own beam: fades to nothing over this many metres toward the eye
  double other_beam_half_width = 0.02;  // other ships' beams: widest half-width on screen, share of the height
};

// `ship` is the ship the camera follows (World::focus_ship()); `cockpit` whether it rides inside
// it; `alpha` interpolates the crosshair like the meshes.
void keep_own_effects_out_of_view(const World& w, ShipId ship, bool cockpit, const CameraView& camera, double alpha,
                                  int width, int height, const OwnViewRules& rules,
                                  std::vector<ParticleInstance>& particles);

}  // namespace arc
