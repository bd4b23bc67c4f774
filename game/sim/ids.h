// game/sim/ids.h — the game layer's typed ids (core/typed_id.h): zero is null, and a ShipId
// cannot be passed, compared or stored where a TeamId or a model slot is meant.
//
// ShipId   a ship: World::ships[id.index()] (World::ship(id)); ids never move, dead ships stay.
// TeamId   a team: World::team_names[id.index()], resolved from the level's team names at load.
// ModelSlot a model the level needs: World::model_paths[slot.index()]; game/app maps each slot to
//          the renderer's ModelId when it loads the scene's resources.
// Particle owners (OwnerId) and effects (EffectId) are the particle engine's own ids
// (particles/particle_ids.h).
#pragma once
#include "core/typed_id.h"

namespace arc {

struct ShipTag;
using ShipId = Id<ShipTag>;
struct TeamTag;
using TeamId = Id<TeamTag>;
struct ModelSlotTag;
using ModelSlot = Id<ModelSlotTag>;

}  // namespace arc
