// game/sim/effects.h — the effect names the game spawns and the library they come from.
#pragma once
#include <memory>
#include <string>

namespace arc {

class EffectLibrary;

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

}  // namespace arc
