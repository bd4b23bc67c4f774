// game/render/own_cover.h — whether the own ship's hull covers a point, as a camera sees it (no GL).
//
// The hull's silhouette is taken as the convex outline of its model's bounding box projected
// from the eye; a point is covered when it falls inside that outline and lies farther from
// the eye than the ship. The chase-framing test counts the ticks a target near the nose is
// covered so, and the test pilot does not see a target that is. In the cockpit the eye is
// inside the box and the own ship is not drawn: callers ask only for views that draw it.
#pragma once
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace arc {

struct Ship;

// A model's bounds in its own frame (ModelData::bounds_min / bounds_max).
struct HullBox {
  glm::dvec3 lo{0.0}, hi{0.0};
};

// `eye` looks along its local −Z; `ship` is drawn at its position and orientation.
bool covered_by_hull(const glm::dvec3& eye, const glm::dquat& eye_orientation, const Ship& ship, const HullBox& box,
                     const glm::dvec3& point);

}  // namespace arc
