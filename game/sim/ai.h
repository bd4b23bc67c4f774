// game/sim/ai.h — the AI pilots (game/sim/ai.cpp): fighters and gunners set a ship's controls.
#pragma once
#include "game/sim/world.h"

namespace arc {

// Difficulty parameters (easy, normal, hard), exposed for the tests.
struct AiTuning {
  double aim_error;    // radians of aim scatter
  double reaction_s;   // seconds between decisions
  double aggression;   // 0..1: fire cone, missile use, how late it evades
};
AiTuning ai_tuning(int difficulty);

// A fighter: re-thinks at its reaction time (target, evade, break off), then steers and fires.
void drive_ai(World& w, Ship& s);
// A gunner: holds still and fires every weapon straight ahead in bursts.
void drive_gunner(const World& w, Ship& s);

}  // namespace arc
