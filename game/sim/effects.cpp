// game/sim/effects.cpp — loading the effect library and resolving the game's effects in it;
// spawning effects and moving their owners.
#include "game/sim/effects.h"

#include <filesystem>

#include "game/sim/geometry.h"
#include "game/sim/world.h"
#include "particles/effect_library.h"

namespace arc {

std::shared_ptr<const EffectLibrary> load_effect_library(const std::string& root_dir) {
  auto lib = std::make_shared<EffectLibrary>();
  lib->load_directory((std::filesystem::path(root_dir) / "assets/effects").string());
  return lib;
}

GameEffects resolve_game_effects(const EffectLibrary& library, const LevelDef& level) {
  GameEffects fx;
  fx.lightning_beam = library.id("lightning_beam");
  fx.shield_sphere = library.id("shield_sphere");
  fx.shield_hit = library.id("shield_hit");
  fx.hull_sparks = library.id("hull_sparks");
  fx.ship_explosion = library.id("ship_explosion");
  fx.engine_exhaust = library.id("engine_exhaust");
  fx.missile_trail = library.id("missile_trail");
  fx.plasma_bolt = library.id("plasma_bolt");
  for (const EffectSpawnDef& e : level.effects) fx.level.push_back(library.id(e.effect));
  return fx;
}

EffectHandle spawn_fx(World& w, EffectId effect, const SpawnParams& p) { return w.particles->spawn(effect, p); }

void set_owner(World& w, OwnerId owner, const glm::dvec3& pos, const glm::dquat& q, const glm::dvec3& vel) {
  w.particles->set_owner_transform(owner, OwnerTransform{pos, q, vel});
}

void publish_owner_transforms(World& w) {
  for (const Ship& s : w.ships)
    if (s.alive) set_owner(w, s.particle_owner, s.position, s.orientation, s.velocity);
}

void spawn_level_effects(World& w) {
  for (size_t i = 0; i < w.level.effects.size(); ++i) {
    const EffectSpawnDef& e = w.level.effects[i];
    bool due = e.repeat_ticks > 0 ? w.tick % e.repeat_ticks == 1 % e.repeat_ticks : w.tick == 1;
    if (!due) continue;
    SpawnParams p;
    p.position = e.position;
    p.orientation = orientation_from_degrees(e.orientation_deg);
    p.scale = e.scale;
    spawn_fx(w, w.fx.level[i], p);
  }
}

}  // namespace arc
