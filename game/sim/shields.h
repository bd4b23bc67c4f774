// game/sim/shields.h — shields and energy (game/sim/shields.cpp).
#pragma once
namespace arc {

class World;
struct Ship;

// How long a hit keeps the shield sphere bright, in seconds.
inline constexpr double kFlashSeconds = 0.5;

// (Re)spawns the ship's shield sphere with `quarters` quarters of its full density.
void spawn_shield(World& w, Ship& s, int quarters);
// Energy and shield regeneration, and the sphere's density and brightness.
void update_shields_and_energy(World& w);

}  // namespace arc
