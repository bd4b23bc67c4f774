// game/app/serialization_test.h — `arcfire --serialization-test N`: proof that a saved game is
// complete.
//
// Saves the game every N ticks, restores the bytes into a second Game (game/sim/serialize.h)
// and steps both with the same input; fails (exit 1) at the first tick whose hashes differ,
// printing both state dumps. Input comes from a replay script when one is given, else the
// level runs with no input (AI ships still fight). SIGINT or SIGTERM stops it at the end of the
// tick with one line saying where (exit 130 or 143).
//
// Example, compiled as BannerExample.SerializationTest in tests/unit/app/test_banner_examples.cpp:
//   SerializationTestOptions options;
//   options.level_path = "tests/replays/levels/range.json";
//   options.every = 30;                              // save and restore every 30 ticks
//   options.ticks = 120;
//   int exit_code = run_serialization_test(options);  // 0: hashes equal on every tick
#pragma once
#include <cstdint>
#include <string>

#include "core/settings.h"
#include "game/app/all_settings.h"
#include "game/app/app_options.h"
#include "game/sim/game.h"

namespace arc {

struct SerializationTestOptions {
  SerializationTestOptions() = default;
  explicit SerializationTestOptions(const AppOptions& app);  // --serialization-test N [--level] [--ticks]

  std::string level_path = "levels/duel.json";
  std::string script_path;  // optional: inputs, commands, level, seed and length from a script
  GameOptions game;
  Settings settings = all_settings();  // a script's `quality` and `set` lines apply on top
  int64_t every = 60;       // save and restore into a second Game every N ticks
  int64_t ticks = 1800;     // without a script
};

// Returns 0 when the hashes agree on every tick, 1 at the first that differs (InputError for
// N < 1 or a bad level or script).
int run_serialization_test(const SerializationTestOptions& options);

}  // namespace arc
