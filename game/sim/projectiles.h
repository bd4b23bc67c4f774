// game/sim/projectiles.h — missiles and plasma bolts (game/sim/projectiles.cpp).
#pragma once
namespace arc {

class World;
struct Ship;

// Fires the selected secondary weapon when the button is held, cooled down and paid for.
void fire_secondary(World& w, Ship& s);
// The primary trigger of a loadout with plasma in its primary bank (Ship::primary_cooldown).
void fire_primary_plasma(World& w, Ship& s);
// Homing missiles turn toward their target; every projectile moves one tick.
void move_projectiles(World& w);
// Projectiles that hit a ship deal their damage and end; expired ones end.
void hit_projectiles(World& w);

}  // namespace arc
