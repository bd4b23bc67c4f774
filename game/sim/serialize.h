// game/sim/serialize.h — binary snapshots of the whole simulation (behind Game::save/restore).
//
// A snapshot holds every piece of dynamic state: each ship (transforms, velocities, hull,
// shield, energy, timers, controls, weapons, beam channels, attached effects, AI state,
// targets), projectiles, props, recent explosions, the outcome, the camera rig, the tick and
// step counters, the settings the world was made with (seed, difficulty, particle budget,
// lightning interval, sub-steps) and the ParticleWorld's own snapshot. Static definitions
// (ship classes, effects, the level) are not in it: restoring loads the level first and then
// overwrites the dynamic state, checking that the snapshot belongs to that level.
//
// Format: core/snapshot_io.h's frame (magic "ARCSNAP1", version, size, checksum), then
// little-endian: the settings header (level name, tick rate, seed, difficulty, particle budget,
// lightning interval, sub-steps), then every saved field of the World in the order of the
// field visitors in game/sim/world.h (a list is its u32 length and its entries), the particle
// world's snapshot last. A truncated, corrupt or foreign snapshot throws
// InputError("snapshot: ...").
//
// Example, compiled as GameExamples.SaveAndLoad in tests/unit/game/test_game_examples.cpp:
//   std::vector<uint8_t> bytes = save_world(w);
//   GameOptions o = snapshot_options(bytes, base);     // the level is loaded with these
//   load_world(w2, bytes);                             // w2: that level, freshly initialised
#pragma once
#include <cstdint>
#include <vector>

#include "game/sim/game.h"

namespace arc {

class World;

std::vector<uint8_t> save_world(const World& w);
// `base` with the snapshot's seed, difficulty and simulation settings (root_dir kept).
GameOptions snapshot_options(const std::vector<uint8_t>& bytes, const GameOptions& base);
// Overwrites the dynamic state of `w` (initialised from the snapshot's level and options).
void load_world(World& w, const std::vector<uint8_t>& bytes);

}  // namespace arc
