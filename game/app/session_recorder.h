// game/app/session_recorder.h — `arcfire --record FILE`: writes a live session as a replay
// script (format: tests/replays/README.md) that replays bit for bit.
//
// The header (level, seed, tick rate, difficulty and the settings that change the simulation)
// goes to a temporary file renamed into place; then every tick that changes the held input or
// issues a command appends its lines and flushes, so a crash or a kill leaves a replayable
// file that lacks at most the last tick. A `hash` line every second of game time lets the
// replay check that it reproduces the live session.
//
// Example, compiled as BannerExample.SessionRecorder in tests/unit/app/test_banner_examples.cpp:
//   Game game = Game::load_level(level, GameOptions{});
//   SessionRecorder recorder(path, level, game);  // the header is written now
//   for (int tick = 0; tick < 120; ++tick) {
//     InputFrame input;
//     input.throttle = 127;
//     std::vector<Command> commands;
//     if (tick == 30) commands.push_back(Command::TargetNearest);
//     recorder.record(game, input, commands);     // just before the step, with its arguments
//     game.step(input, commands);
//   }
//   recorder.finish(game);                        // final hash and `end` (~SessionRecorder too)
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "game/sim/game.h"
#include "replay/script.h"

namespace arc {

class SessionRecorder {
 public:
  // InputError when the file cannot be written.
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
  bool finished_ = false;
};

}  // namespace arc
