// game/sim/beams.h — the lightning beam (game/sim/beams.cpp).
#pragma once
#include <vector>
#include <glm/vec3.hpp>

#include "game/sim/world.h"

namespace arc {

// The beam's first hit along a polyline: ship id (or −1) and distance along the line.
struct BeamHit {
  ShipId ship;  // null: nothing hit
  double distance = -1;
  glm::dvec3 point{0.0};
  bool on_shield = false;
};
BeamHit trace_beam(const World& w, ShipId shooter, const std::vector<glm::dvec3>& polyline);

// Starts or stops the beam with the fire button and spends its energy.
void update_beam_trigger(World& w, Ship& s);
// Destroys the beam's channels (the trigger released, or the ship died).
void stop_beam(World& w, Ship& s);
// Traces every firing beam, cuts its channels at the hit and deals the damage.
void resolve_beams(World& w);

}  // namespace arc
