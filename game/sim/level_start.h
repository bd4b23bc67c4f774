// game/sim/level_start.h — a World built from a level (game/sim/level_start.cpp).
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include "game/sim/defs.h"
#include "game/sim/game.h"

namespace arc {

class EffectLibrary;
class ParticleStore;
class World;
struct Ship;

// Ships, props, the particle world, the camera rig and the ships' shields and exhausts, from a
// validated LevelDef. A level naming an effect the library lacks throws InputError.
// `store`, when given, large enough and unused, holds the particles (Game::load_level).
void init_world(World& w, LevelDef level, std::shared_ptr<const EffectLibrary> effects, const GameOptions& options,
                std::shared_ptr<ParticleStore> store = nullptr);

// A dormant ship ("inactive" in the level) arrives where the level placed it, with its shield
// and exhausts; a ship that is alive or was destroyed is left alone.
void arrive_ship(World& w, Ship& s);
// A ship's shield sphere and engine exhausts, at the start or when its wave arrives.
void attach_ship_effects(World& w, Ship& s);

// The most engine plumes a ship carries: each is an effect with its own particle pools, so a
// class outlined in thousands of vents would otherwise take memory per vent.
constexpr size_t kMaxExhaustPlumes = 8;
// The exhaust points that carry a plume: all of them up to kMaxExhaustPlumes, beyond that the
// middle point of each of kMaxExhaustPlumes equal runs of the list, in order.
std::vector<glm::dvec3> exhaust_plume_points(const std::vector<glm::dvec3>& exhausts);

}  // namespace arc
