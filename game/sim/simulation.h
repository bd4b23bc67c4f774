// game/sim/simulation.h — the per-tick rules behind Game::step (internal to game/sim).
//
// init_world() builds a World from a validated LevelDef; step_world() advances one fixed tick:
// commands → AI and player controls → flight → particle owners → particles → beams →
// projectiles → collisions → deaths → shields/energy → outcome → camera rig.
#pragma once
#include <vector>

#include "game/sim/world.h"

namespace arc {

// Difficulty parameters (easy, normal, hard), exposed for the tests.
struct AiTuning {
  double aim_error;    // radians of aim scatter
  double reaction_s;   // seconds between decisions
  double aggression;   // 0..1: fire cone, missile use, how late it evades
};
AiTuning ai_tuning(int difficulty);

void init_world(World& w, LevelDef level, std::shared_ptr<const EffectLibrary> effects, const GameOptions& options);
void step_world(World& w, const InputFrame& input, const std::vector<Command>& commands);

// Flight for one ship and one tick from its `controls` (exposed for the flight tests).
void integrate_flight(Ship& s, double dt);
// Applies damage at a world point: shield first, then hull; records the attacker.
void apply_damage(World& w, Ship& target, double amount, const glm::dvec3& point, int attacker);
// Ray/segment against a sphere: smallest t in [0, 1] of a + t(b − a) on the sphere, or −1.
double segment_sphere(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& centre, double radius);
// The beam's first hit along a polyline: ship id (or −1) and distance along the line.
struct BeamHit {
  int ship = -1;
  double distance = -1;
  glm::dvec3 point{0.0};
  bool on_shield = false;
};
BeamHit trace_beam(const World& w, int shooter, const std::vector<glm::dvec3>& polyline);

glm::dquat orientation_from_degrees(const glm::dvec3& yaw_pitch_roll);
inline glm::dvec3 forward_of(const glm::dquat& q) { return q * glm::dvec3(0, 0, -1); }

}  // namespace arc
