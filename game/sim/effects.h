// game/sim/effects.h — the effects the game spawns: their names, the library they come from,
// and how ships and projectiles own them in the particle world.
//
// Names come from validated data, so an unknown name at a spawn is a data error of the level
// (InputError). Owners are ship_owner(id) and projectile_owner(serial) (game/sim/world.h);
// their transforms are published each tick before the particle world steps.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "particles/particle_world.h"

namespace arc {

class EffectLibrary;
class World;

inline constexpr const char* kFxLightningBeam = "lightning_beam";
inline constexpr const char* kFxShieldSphere = "shield_sphere";
inline constexpr const char* kFxShieldHit = "shield_hit";
inline constexpr const char* kFxHullSparks = "hull_sparks";
inline constexpr const char* kFxShipExplosion = "ship_explosion";
inline constexpr const char* kFxEngineExhaust = "engine_exhaust";
inline constexpr const char* kFxMissileTrail = "missile_trail";
inline constexpr const char* kFxPlasmaBolt = "plasma_bolt";

// Loads root_dir/assets/effects/*.json once per root and shares it between games (copies of a
// Game share the immutable library). Bad effect files throw InputError.
std::shared_ptr<const EffectLibrary> load_effect_library(const std::string& root_dir);

EffectHandle spawn_fx(World& w, const std::string& name, const SpawnParams& p);
void set_owner(World& w, uint32_t owner, const glm::dvec3& pos, const glm::dquat& q, const glm::dvec3& vel);
// Every live ship's transform, for the clusters attached to it.
void publish_owner_transforms(World& w);
// The level's own effects, at tick 1 and then every repeat_ticks.
void spawn_level_effects(World& w);

}  // namespace arc
