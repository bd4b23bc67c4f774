// game/app/replay_modes.h — wires the replay command-line options to engine/replay's player.
#pragma once
#include "game/app/app_options.h"

namespace arc {

int run_replay_from_options(const AppOptions& options);              // --replay FILE
int run_serialization_test_from_options(const AppOptions& options);  // --serialization-test N

}  // namespace arc
