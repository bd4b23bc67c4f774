// game/sim/camera_rig.h — the simulated camera (game/sim/camera_rig.cpp).
//
// Chase: behind and above the focus ship, high enough that its hull sits below the crosshair's
// line and a target ahead stays above it, looking a little down; the view lags the ship's turns a little (at most
// max_lag_deg, so a pitch toward a target never swings the hull over it). Padlock: the same
// offset, turned to look at the ship's target (chase when it has none). Cockpit: at the pilot's
// seat. Fixed: the level's view.
#pragma once
#include "particles/particle_world.h"

namespace arc {

class World;
struct Ship;
struct CameraRig;

// Where the chase and padlock cameras sit: `up` and `back` metres from the ship's centre in its
// frame, each `per_radius` times the ship's collision radius plus a constant.
struct ChaseFraming {
  double up_per_radius = 1.2, up_m = 3.0;
  double back_per_radius = 3.4, back_m = 8.0;
  double tilt_down_deg = 6.0; // the view looks this much below the ship's nose: the hull sits higher on
                             // screen, clear of the HUD's bottom edge, and the crosshair a little above the centre
  double lag_rate = 6.0;      // 1/s: how fast the view follows the ship's turns
  double max_lag_deg = 4.0;   // the view is never further than this from the ship's attitude
};

// One tick of the chase camera after `prev` (dt seconds later).
CameraRig chase_rig(const CameraRig& prev, const Ship& s, double dt, const ChaseFraming& f = {});
// One tick of the padlock camera after `prev`: the chase offset, turned toward `target`.
CameraRig padlock_rig(const CameraRig& prev, const Ship& s, const Ship& target, double dt, const ChaseFraming& f = {});

// Follows the focus ship (chase, padlock or cockpit) or holds the level's fixed view.
void update_camera(World& w);
// The camera rig as the particle world's culling view.
ParticleCamera particle_camera(const World& w);

}  // namespace arc
