// game/sim/mission_events.h — a level's events and objectives as the simulation runs them
// (game/sim/mission_events.cpp), and the one way a waiting ship enters the fight.
//
// Each tick, before the ships fly, every event not yet run checks its trigger against the
// state the previous tick left; once it holds, the event waits its delay and then runs its
// actions in order, all inside the tick, so a replay repeats them exactly. Events run in file
// order, so an "event" trigger on an earlier event fires in the same tick. Nothing runs after
// the outcome is decided. Waves (waves.h) and training steps bring ships in through spawn_ships.
#pragma once
#include <cstddef>
#include <vector>

#include "game/sim/world.h"

namespace arc {

// The state a level with events or objectives starts with (sized to its lists and ships).
MissionProgress new_mission_progress(const World& w);
// Sets World::mission at level start (levels with events or objectives only).
void start_mission(World& w);
// The events' step of a tick (see above).
void update_events(World& w);

// Whether a trigger holds in this World now (events and waves).
bool trigger_holds(const World& w, const TriggerDef& t);
// Waiting ships (World order indices) enter the fight; with `at`, moved together so the first
// arrives there. Ships that are alive or were destroyed are left alone.
void spawn_ships(World& w, const std::vector<size_t>& ships, const glm::dvec3* at = nullptr);
// Posts "Reinforcements: N friendly (or hostile) ships" for ships that just arrived.
void announce_reinforcements(World& w, const std::vector<size_t>& ships);

// The order an event gave a ship, or null (levels without events, or none given).
const ShipOrder* order_of(const World& w, ShipId ship);
// Flies a ship under a route or hold order; false when it has none (its own pilot flies it).
bool fly_order(World& w, Ship& s);
// The ship an attack order names while it lives, else null.
ShipId ordered_target(const World& w, ShipId ship);

// Objectives: won when every primary one is done, lost when one has failed (WinKind::Objectives).
bool primary_objectives_done(const World& w);
bool primary_objective_failed(const World& w);

}  // namespace arc
