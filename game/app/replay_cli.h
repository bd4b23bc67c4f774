// game/app/replay_cli.h — the replay modes of `arcfire`: play a script headless and check it,
// the serialization test, and the recorder the live window loop feeds.
//
// Scripts are parsed by engine/replay (format: tests/replays/README.md); this file drives a
// Game with them. Command-line parsing lives in app_options.cpp; these functions get plain
// options and return the exit code (0 all checks passed, 1 a check failed, 2 bad input —
// InputError is thrown for the caller to print as one line).
//
//   ReplayRunOptions o;  o.script_path = "tests/replays/duel_course.replay";
//   int code = run_replay(o);                 // last stdout line: "final hash HEX at tick N"
//
//   SessionRecorder rec("session.replay", "levels/duel.json", game);   // header written now
//   each tick:  rec.record(game, input, commands);  game.step(input, commands);
//   on quit:    rec.finish(game);                                       // also in ~SessionRecorder
#pragma once
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/settings.h"
#include "game/sim/game.h"
#include "replay/script.h"

namespace arc {

struct ReplayRunOptions {
  std::string script_path;
  std::string out_dir;          // snapshots, actual and diff PNGs; "" = out/replay/<script stem>
  bool update_golden = false;   // fill in hash values, rewrite the hash log and golden PNGs
  bool no_render = false;       // skip snapshots: no GL context at all
  GameOptions game;             // budget, sub-steps, root_dir; seed and difficulty come from the script
  Settings settings = Settings::defaults();  // renderer settings for snapshots
  std::string golden_dir;       // "" = <script folder>/golden/<script stem>
  int full_hash_every = 60;     // ticks between full hashes in the hash log
  bool quiet = false;           // no per-check output (benchmarks); failures still printed
  int render_every = 0;         // benchmarks: also render every N-th tick without checking (0 = never)
};

struct ReplayOutcome {
  int exit_code = 0;
  uint64_t final_hash = 0;
  uint64_t ticks = 0;
  int checks = 0;
  int failures = 0;
  int frames_rendered = 0;
  double setup_seconds = 0;  // wall clock spent before the first tick (level, GL context, assets)
  double run_seconds = 0;    // wall clock of the ticks themselves
};

// Runs the script as fast as it can. InputError for a bad script, level or golden folder.
ReplayOutcome play_replay(const ReplayRunOptions& options);
int run_replay(const ReplayRunOptions& options);

struct SerializationTestOptions {
  std::string level_path = "levels/duel.json";
  std::string script_path;  // optional: inputs, commands, level, seed and length from a script
  GameOptions game;
  int64_t every = 60;       // save and restore into a second Game every N ticks
  int64_t ticks = 1800;     // without a script
};

// Saves the game every N ticks, restores the bytes into a second Game and steps both with the
// same inputs; fails (exit 1) at the first tick whose hashes differ, with both state dumps.
int run_serialization_test(const SerializationTestOptions& options);

// Converts between the script's held input and the simulation's InputFrame.
InputFrame to_input_frame(const replay::InputState& s);
replay::InputState to_input_state(const InputFrame& f);

// Records a live session as a replay script. The header goes to a temporary file renamed
// into place, then lines are appended and flushed on every tick that wrote one, so a crash
// or a kill leaves a replayable file that lacks at most the last tick. A `hash` line every
// second of game time lets the replay check it reproduces the live session.
class SessionRecorder {
 public:
  SessionRecorder(const std::string& path, const std::string& level_path, const Game& game,
                  const std::string& build_id = "dev");
  SessionRecorder(const SessionRecorder&) = delete;
  SessionRecorder& operator=(const SessionRecorder&) = delete;
  ~SessionRecorder();

  // Call for every Game::step() (paused ones too), just before it, with exactly its arguments.
  void record(const Game& game, const InputFrame& input, const std::vector<Command>& commands);
  // Writes the final hash and `end` at the game's current tick and closes the file.
  void finish(const Game& game);
  const std::string& path() const { return path_; }

 private:
  void write(const std::string& text);

  std::string path_;
  std::FILE* file_ = nullptr;
  replay::InputState held_;
  uint64_t tick_rate_ = 60;
  uint64_t last_tick_ = 0;
  uint64_t last_hash_ = 0;
  bool finished_ = false;
};

}  // namespace arc
