// game/app/music_director.h — which piece of music the fight calls for, read from the World.
//
// calm     no hostile within kTensionRange and nothing aimed at the player;
// tension  a hostile within kTensionRange, a hostile's missile lock building on the player, or
//          a missile homing on the player;
// combat   the player hit, firing at a hostile, or a hostile's beam on the player, within the
//          last kCombatHold seconds;
// victory / defeat once the outcome is decided (the player's death is a defeat); a level without
//          a player (the attract demo) plays the menu theme.
// Each mood holds a few seconds before stepping down, so a lull does not flap the music. A pure
// function of the World's sequence: a replay gives the same choices every run.
#pragma once
#include <cstdint>
#include <string>

namespace arc {

class World;

class MusicDirector {
 public:
  static constexpr double kTensionRange = 2500;  // world units
  static constexpr double kCombatHold = 6, kTensionHold = 4;  // seconds

  // The piece for this tick: "menu", "calm", "tension", "combat", "victory" or "defeat".
  const char* mood(const World& w);

 private:
  int64_t combat_until_ = -1, tension_until_ = -1;  // ticks
  int64_t last_tick_ = -1;
};

}  // namespace arc
