// game/app/replay_expectations.h — what a script's `expect` lines mean for a World.
//
// Names in expectations must exist in the level: check_expectation_names() reports a typo as
// bad input (InputError at the name's line and column) before anything runs, so a failing
// expectation always means the game did something else, never that the script is wrong.
#pragma once
#include <optional>
#include <string>

#include "game/render/sound_events.h"
#include "replay/script.h"

namespace arc {

class World;

// InputError "path:line:col: no ship named ..." for an unknown ship or sound event name, or a
// header tick rate that differs from the level's.
void check_expectation_names(const replay::Script& script, const World& world);

// Why the expectation fails ("hull of Drone is 220"), or nullopt when it holds. `sounds` are
// the sound events of the tick just stepped.
std::optional<std::string> expectation_failure(const replay::Expectation& expectation, const World& world,
                                               const std::vector<SoundEvent>& sounds = {});

}  // namespace arc
