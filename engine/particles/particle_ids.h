// particles/particle_ids.h — the typed ids of the particle engine's interface (core/typed_id.h).
//
// OwnerId names something clusters can be attached to (a ship, a missile): the caller allocates
// them, zero means free-floating. EffectId names an effect of an EffectLibrary, resolved once
// from its name (EffectLibrary::id) so spawning does not look a string up every time.
#pragma once
#include "core/typed_id.h"

namespace arc {

struct OwnerTag;
using OwnerId = Id<OwnerTag>;
struct EffectTag;
using EffectId = Id<EffectTag>;

}  // namespace arc
