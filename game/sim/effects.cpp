// game/sim/effects.cpp — loading the effect library and resolving the game's effects in it;
// spawning effects and moving their owners.
#include "game/sim/effects.h"

#include <filesystem>

#include <glm/geometric.hpp>

#include "core/data_layers.h"
#include "core/error.h"
#include "core/input_file.h"
#include "game/sim/geometry.h"
#include "game/sim/world.h"
#include "particles/effect_library.h"
#include "particles/sprites.h"

namespace arc {

std::shared_ptr<const EffectLibrary> load_effect_library(const std::string& root_dir) {
  auto lib = std::make_shared<EffectLibrary>();
  lib->load_directory((std::filesystem::path(root_dir) / "assets/effects").string());
  // The texture each cluster's sprite names is checked here, rendering or not, as a window would
  // find it missing.
  for (const std::string& name : lib->names()) {
    const EffectDef& def = lib->get(name);
    for (const ClusterDef& c : def.clusters) {
      const std::string sprite(kSpriteNames.at(c.sprite));
      const std::string texture = data_file(root_dir, "assets/textures/sprite_" + sprite + ".png");
      const std::string problem = input_path_problem(texture);
      if (!problem.empty())
        throw InputError(def.path + ": cluster '" + c.name + "': sprite '" + sprite + "' names texture " + texture +
                         ": " + (problem == "not found" ? "no such file" : problem));
    }
  }
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
  fx.flare = library.id("flare");
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

namespace {

// Level effects that move are attached to owners of their own, numbered from here by their
// index in the level: far beyond what allocate_owner hands out to ships and projectiles.
constexpr uint32_t kLevelEffectOwnerBase = 0x80000000u;

glm::dquat spawn_orientation(const EffectSpawnDef& e) {
  if (!e.has_target) return orientation_from_degrees(e.orientation_deg);
  // Forward (−Z) toward the target; the up hint leans off +Y so a vertical aim stays defined.
  return glm::quatLookAt(safe_norm(e.target - e.position, glm::dvec3(0, 0, -1)), glm::dvec3(0, 1, 0.001));
}

}  // namespace

OwnerId level_effect_owner(size_t index) { return OwnerId{kLevelEffectOwnerBase + uint32_t(index)}; }

void spawn_level_effects(World& w) {
  for (size_t i = 0; i < w.level.effects.size(); ++i) {
    const EffectSpawnDef& e = w.level.effects[i];
    const bool due = e.repeat_ticks > 0 ? w.tick % e.repeat_ticks == 1 % e.repeat_ticks : w.tick == 1;
    const bool moving = e.velocity != glm::dvec3(0.0) && e.repeat_ticks > 0;
    const glm::dquat q = spawn_orientation(e);
    if (moving) {
      // The owner's place is a function of the tick: it restarts at `position` with each spawn,
      // and the last spawn's trail, let go, stays where it was laid and fades.
      const int64_t age = (w.tick - 1) % e.repeat_ticks;
      if (due) w.particles->release_owner(level_effect_owner(i));
      set_owner(w, level_effect_owner(i), e.position + e.velocity * (double(age) * w.dt), q, e.velocity);
    }
    if (!due) continue;
    SpawnParams p;
    p.scale = e.scale;
    if (moving) {
      p.owner = level_effect_owner(i);
    } else {
      p.position = e.position;
      p.orientation = q;
    }
    const EffectHandle spawned = spawn_fx(w, w.fx.level[i], p);
    // Measured along the channel, so its zigzag ends a few per cent short of the target.
    if (e.has_target)
      for (ClusterHandle ch : spawned.clusters) w.particles->cut_lightning(ch, glm::length(e.target - e.position));
  }
}

}  // namespace arc
