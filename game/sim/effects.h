// game/sim/effects.h — the effects the game spawns, resolved to EffectIds once per World, the
// library they come from, and how ships and projectiles own them in the particle world.
//
// resolve_game_effects() looks every name up once at level start (an unknown name is a data
// error: InputError); spawning then goes by id. Owners are the OwnerIds stored on Ship and
// Projectile (allocate_owner, game/sim/world.h); their transforms are published each tick
// before the particle world steps.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "particles/particle_world.h"

namespace arc {

class EffectLibrary;
class World;
struct LevelDef;

struct GameEffects {
  EffectId lightning_beam, shield_sphere, shield_hit, hull_sparks, ship_explosion, engine_exhaust, missile_trail,
      plasma_bolt, flare;
  std::vector<EffectId> level;  // one per LevelDef::effects entry
};

// Loads root_dir/assets/effects/*.json once per root and shares it between games (copies of a
// Game share the immutable library). Bad effect files throw InputError.
std::shared_ptr<const EffectLibrary> load_effect_library(const std::string& root_dir);
// The game's effects and the level's own, by name in `library` (InputError for an unknown one).
GameEffects resolve_game_effects(const EffectLibrary& library, const LevelDef& level);

EffectHandle spawn_fx(World& w, EffectId effect, const SpawnParams& p);
void set_owner(World& w, OwnerId owner, const glm::dvec3& pos, const glm::dquat& q, const glm::dvec3& vel);
// Every live ship's transform, for the clusters attached to it.
void publish_owner_transforms(World& w);
// The level's own effects, at tick 1 and then every repeat_ticks: a lightning channel with a
// target ("to") aimed at it and cut there; a moving effect attached to an owner of its own
// (level_effect_owner) that travels from its position at its velocity until the next spawn.
void spawn_level_effects(World& w);
// The particle owner of the level's moving effect number `index` (outside allocate_owner's range).
OwnerId level_effect_owner(size_t index);

}  // namespace arc
