// game/app/replay_player.h — `arcfire --replay`: plays a script headless, as fast as it can,
// and checks it.
//
// The script (engine/replay; format in tests/replays/README.md) drives a Game: its held input
// and commands go in at their ticks (ScriptFeeder); its expectations, `hash` lines and
// snapshots are checked, and the cheap state hash of every tick is compared with the golden
// hash log (golden/<script>/hashes.txt), so a changed simulation is reported at its first
// diverging tick with a state dump. Snapshots render through FrameRenderer and compare with
// golden PNGs (within the script's `tolerance`) under the settings the script names; only
// snapshots create a GL context. Exit codes: 0 every check passed, 1 a check failed; a bad
// script, level or golden folder throws InputError (exit 2) before any tick. SIGINT or SIGTERM
// stops it at the end of the tick: one line says where, the checks not reached count as
// neither passed nor failed, --update-golden changes nothing, and the code is 130 or 143.
//
// Example, compiled as BannerExample.ReplayPlayer in tests/unit/app/test_banner_examples.cpp:
//   ReplayRunOptions options;
//   options.script_path = "tests/replays/range_beam_shield.replay";
//   options.no_render = true;                      // hashes and expectations only: no GL context
//   ReplayOutcome outcome = play_replay(options);  // prints one `ok` or `FAIL` line per check
//   // outcome.exit_code is 0 when every check passed; outcome.final_hash, outcome.ticks
//   // run_replay(options) plays it too and ends stdout with "final hash HEX at tick N"
#pragma once
#include <cstdint>
#include <string>

#include "core/settings.h"
#include "game/app/all_settings.h"
#include "game/app/app_options.h"
#include "game/sim/game.h"

namespace arc {

struct ReplayRunOptions {
  ReplayRunOptions() = default;
  explicit ReplayRunOptions(const AppOptions& app);  // --replay FILE and the options beside it

  std::string script_path;
  std::string out_dir;          // snapshots, actual and diff PNGs; "" = out/replay/<script stem>
  bool update_golden = false;   // fill in hash values, rewrite the hash log and golden PNGs
  bool no_render = false;       // skip snapshots: no GL context at all
  GameOptions game;             // budget, sub-steps, root_dir; seed and difficulty come from the script
  Settings settings = all_settings();  // the script's quality and `set` lines apply on top
  std::string golden_dir;       // "" = <script folder>/golden/<script stem>; snapshots_like NAME
                                // reads the PNGs of its sibling folder NAME
  int full_hash_every = 60;     // ticks between full hashes in the hash log
  bool quiet = false;           // no per-check output (benchmarks); failures still printed
  int render_every = 0;         // benchmarks: also render every N-th tick without checking (0 = never)
  std::string sounds_path = "assets/sounds/sounds.json";
  std::string audio_out;        // --audio-out: the replay's sound as WAV, through the loopback device
  RunFiles files;               // the command line's other files: no output of the replay may be one
};

struct ReplayOutcome {
  int exit_code = 0;
  uint64_t final_hash = 0;
  uint64_t ticks = 0;
  int checks = 0;
  int failures = 0;
  int frames_rendered = 0;
  bool stopped = false;      // SIGINT or SIGTERM ended it after `ticks`, before the script's end
  double setup_seconds = 0;  // wall clock spent before the first tick (level, GL context, assets)
  double run_seconds = 0;    // wall clock of the ticks themselves
};

// Runs the script as fast as it can. InputError for a bad script, level or golden folder.
ReplayOutcome play_replay(const ReplayRunOptions& options);
// play_replay, then "final hash HEX at tick N" as the last line of stdout (not when stopped by
// a signal); returns the exit code.
int run_replay(const ReplayRunOptions& options);

}  // namespace arc
