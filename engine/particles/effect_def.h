// particles/effect_def.h — plain definitions of effects, filled by EffectLibrary from JSON.
//
// An EffectDef is a composite: several ClusterDefs, each one cluster of particles with one
// emitter, one animation (Hadwiger 2000 §4.2: linear, sphere, lightning), curves over particle
// life (size, colour, alpha, burn — Ilmonen 2006 §4), the sprite, how it is turned (camera-facing
// or stretched along its motion) and the soft-edge method.
// Units: metres, seconds, degrees in files (radians here).
#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "particles/curves.h"
#include "particles/render_output.h"

namespace arc {

// A uniform distribution [min, max]; min == max is a constant.
struct Range {
  double min = 0.0;
  double max = 0.0;
};

enum class EmitterShape : uint8_t { Point, Sphere, SphereSurface, Cone, Box, Line, Mesh };
enum class EmitDirection : uint8_t { Shape, Random, Forward };

struct EmitterDef {
  EmitterShape shape = EmitterShape::Point;
  glm::dvec3 offset{0.0};          // emitter centre in the effect frame
  double radius = 0.0;             // sphere, sphere_surface, cone base disc
  double angle = 0.0;              // cone half-angle around the axis (radians)
  glm::dquat axis_rotation{1, 0, 0, 0};  // turns −Z onto the emitter's axis (cone, "forward")
  glm::dvec3 half_extents{0.0};    // box
  double length = 0.0;             // line along −Z from the centre
  std::vector<glm::dvec3> triangles;  // mesh: 3 vertices per triangle
  std::vector<double> area_prefix;    // mesh: running sum of triangle areas (area weighting)
  double rate = 0.0;               // particles per second (fractional counts accumulate)
  double spacing = 0.0;            // m: one more particle per `spacing` of the emitter's path (0 = none)
  uint32_t burst = 0;              // particles at the first tick
  double duration = 0.0;           // seconds of emission; 0 = until stopped
  EmitDirection direction = EmitDirection::Shape;
};

struct ParticleInitDef {
  Range speed{0.0, 0.0};       // m/s along the emission direction
  Range lifetime{1.0, 1.0};    // s; 0 = lives as long as its cluster
  Range size{1.0, 1.0};        // half-width, m
  Range rotation{0.0, 0.0};    // initial rotation, radians
  Range spin{0.0, 0.0};        // radians per second
  double inherit_velocity = 1.0;  // fraction of the spawn/owner velocity given to particles
};

enum class AnimationType : uint8_t { Linear, Sphere, Lightning };
enum class SphereMotion : uint8_t { Static, Stochastic, Rotational };
enum class RadiusAnimation : uint8_t { Constant, Pulsating, Contracting, Exploding };

struct LinearDef {
  double drag = 0.0;                 // k, 1/s (exact exponential integration)
  glm::dvec3 acceleration{0.0};      // m/s², world frame (or owner frame for owner-space clusters)
};

struct SphereDef {
  SphereMotion motion = SphereMotion::Static;
  double radius = 1.0;               // m at scale 1
  glm::dvec3 rotation_rate{0.0};     // pitch, yaw, roll in radians per second (rotational)
  RadiusAnimation radius_animation = RadiusAnimation::Constant;
  double amplitude = 0.0;            // pulsating: fraction of the radius
  double frequency = 0.0;            // pulsating: Hz
  double ramp = 0.2;                 // contracting: fraction of the cluster life spent growing / shrinking
  double growth = 0.0;               // exploding: m/s
};

struct LightningDef {
  double seed_length = 10.0;         // m: the seed segment and the basic segment length
  double max_length = 500.0;         // m: the channel ends before exceeding this
  double max_angle = 0.3;            // radians: largest deviation of a segment from its guide direction
  double guide_distance = 0.0;       // m; 0: segments deviate from the seed direction (Hadwiger), so the
                                     // channel wanders off the seed line; > 0: from the direction toward
                                     // the seed line's point this far ahead, so it stays on the line
  double length_jitter = 0.3;        // segment length in seed_length·[1 − j, 1 + j]
  int sizzle_ticks = 3;              // re-evaluate every n ticks (Hadwiger §5.2 "sizzle")
  double width = 1.0;                // half-width of a segment's sprite, m
  double free_lifetime = 2.0;        // s: life of a channel spawned without an owner (nothing else ends it)
};

// How a cluster's particles are turned towards the camera ("billboard" in effect files).
enum class ClusterBillboard : uint8_t {
  Camera,    // camera-facing square, turned by the particle's rotation
  Velocity,  // axis-locked streak along the particle's motion relative to the camera
};

struct ClusterDef {
  std::string name;
  AnimationType animation = AnimationType::Linear;
  LinearDef linear;
  SphereDef sphere;
  LightningDef lightning;
  bool owner_space = false;          // particles move and turn with the owner; else world space
  double lifetime = 0.0;             // s; 0 = until destroyed or empty and no longer emitting
  EmitterDef emitter;
  ParticleInitDef particles;
  Curve size = Curve::flat(1.0f);    // multiplier of the particle's initial size
  Curve red = Curve::flat(1.0f), green = Curve::flat(1.0f), blue = Curve::flat(1.0f);
  Curve alpha = Curve::flat(1.0f);
  Curve burn = Curve::flat(0.0f);    // 0 alpha-blended … 1 additive (Ilmonen §4)
  uint16_t sprite = 0;
  ClusterBillboard billboard = ClusterBillboard::Camera;
  double stretch = 0.0;              // velocity billboards: seconds of motion a streak covers
  SoftEdge soft_edge = SoftEdge::Off;
  double soft_extent = 0.0;          // m; 0 = the particle size
  int priority = -1;                 // −1 = the spawn's priority
  ScreenPriority screen_priority = ScreenPriority::Normal;  // what an overdraw budget reduces first
};

struct EffectDef {
  std::string name;                  // file stem
  std::string path;
  std::vector<ClusterDef> clusters;
};

}  // namespace arc
