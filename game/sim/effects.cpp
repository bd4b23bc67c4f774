// game/sim/effects.cpp — loading the effect library; spawning effects and moving their owners.
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

EffectHandle spawn_fx(World& w, const std::string& name, const SpawnParams& p) {
  return w.particles->spawn(name, p);
}

void set_owner(World& w, uint32_t owner, const glm::dvec3& pos, const glm::dquat& q, const glm::dvec3& vel) {
  w.particles->set_owner_transform(owner, OwnerTransform{pos, q, vel});
}

void publish_owner_transforms(World& w) {
  for (const Ship& s : w.ships)
    if (s.alive) set_owner(w, ship_owner(s.id), s.position, s.orientation, s.velocity);
}

void spawn_level_effects(World& w) {
  for (const EffectSpawnDef& e : w.level.effects) {
    bool due = e.repeat_ticks > 0 ? w.tick % e.repeat_ticks == 1 % e.repeat_ticks : w.tick == 1;
    if (!due) continue;
    SpawnParams p;
    p.position = e.position;
    p.orientation = orientation_from_degrees(e.orientation_deg);
    p.scale = e.scale;
    spawn_fx(w, e.effect, p);
  }
}

}  // namespace arc
