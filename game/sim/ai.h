// game/sim/ai.h — the AI pilots (game/sim/ai.cpp): fighters, gunners and drones set a ship's controls.
#pragma once
#include "game/sim/world.h"

namespace arc {

// The World's difficulty row of its level's AI table (assets/settings/ai.json).
const AiDifficultyDef& ai_difficulty(const World& w);
// How `s` flies: the player's own side by the table's "allies" row where it has one (the
// difficulty sets the enemy's skill, not the wing's), every other ship by ai_difficulty(w).
const AiDifficultyDef& ai_difficulty(const World& w, const Ship& s);

// Stick commands that turn the nose toward a world direction, damped by the current turn rate;
// the stick goes no further than `stick_limit` (calmer pilots turn more gently).
void steer_toward(const Ship& s, const glm::dvec3& dir, double stick_limit, InputFrame& out);
// A fighter: re-thinks at its reaction time (target, evade, break off; off a player's tail after
// the difficulty's tail_limit_s), then steers and fires.
void drive_ai(World& w, Ship& s);
// A gunner: holds still and fires every weapon straight ahead in bursts.
void drive_gunner(const World& w, Ship& s);
// A training drone: flies slow circles; fires its missile once at a target a training step gives it.
void drive_drone(const World& w, Ship& s);

}  // namespace arc
