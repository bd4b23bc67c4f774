// game/sim/wing.h — the player's wing: orders from the wing commands, the HUD messages they
// post (game/sim/wing.cpp), and how an ordered wingman picks its target and flies
// (game/sim/ai_orders.cpp, called from the fighter AI).
//
// Orders: attack the player's target; cover the player (engage whoever attacks the player, or
// the hostile nearest to the player, within kCoverRadius of the player); form up (fly in
// formation on the player and hold fire); engage at will (the fighter AI's own choice). Each
// order is answered by a message ("Alpha 2: covering you"; "No wingmen" when none is alive).
#pragma once
#include <string>

#include "game/sim/input.h"
#include "game/sim/world.h"

namespace arc {

struct Rng;

inline constexpr double kCoverRadius = 1200.0;  // metres from the player a covering wingman fights within

// Posts a HUD line at this tick; the list keeps the newest kMaxMessages.
void post_message(World& w, MessageKind kind, std::string text);
// One of the four order commands (others are ignored): sets every live wingman's order and
// posts the reply.
void order_wing(World& w, Command c);
// An attack order whose target is gone falls back to engaging at will, with a report.
void update_wing_orders(World& w);

// The wing entry of a ship, or null for a ship outside the player's wing.
const Wingman* wingman_of(const World& w, ShipId ship);
// The target an ordered wingman takes at a decision: the ordered one, the player's attacker,
// none while forming up (and while covering with nobody near the player), or for engage at
// will `current` kept or a fresh pick by `pick` (the fighter AI's own choice).
ShipId wing_target(const World& w, const Ship& s, const Wingman& m, ShipId fallback);
// Whether a wingman should pull out of the fight now: shields low while a hostile is on its
// tail, or alone among several hostiles. Sets the AI's break-off toward the player.
bool wing_withdraw(World& w, Ship& s, const Rng& rng);
// How much farther a hostile counts when an AI pilot picks its target, in levels where the
// player leads a wing (1 elsewhere): the player twice as far, and every ship by 0.6
// for each pilot of the chooser's side already on it, so the wing meets the enemy first and
// fights spread instead of a pack hunting one ship.
double target_weight(const World& w, const Ship& chooser, const Ship& candidate);
// Whether `chooser` leaves capital ships alone when it picks a target of its own: every AI
// pilot on the player's side but the player's own ship does, so a capital ship falls to the
// player's strike; an attack order (the player's F5 or a level event) still sends it at one.
bool leaves_capitals(const World& w, const Ship& chooser);
// Flies a wingman that has no target to fight: in formation on the player. False when the
// wingman has a target (the fighter AI flies it).
bool fly_formation(const World& w, const Ship& s, const Wingman& m, InputFrame& c);

}  // namespace arc
