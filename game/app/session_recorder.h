// game/app/session_recorder.h — `arcfire --record FILE`: writes a live session as a replay
// script (format: tests/replays/README.md) that replays bit for bit.
//
// The header (level, seed, tick rate, difficulty and the settings that change the simulation)
// goes to a temporary file renamed into place; then every tick that changes the held input or
// issues a command appends its lines and flushes, so a crash or a kill leaves a replayable
// file that lacks at most the last tick. A `hash` line every second of game time lets the
// replay check that it reproduces the live session.
//
// Nothing earlier is lost: recording onto an existing file first moves it to NAME.bak, which is
// removed only once the new session has recorded its first second (a session that ends sooner
// leaves both, and says so). NAME.lock, held with flock() while recording, refuses a second
// arcfire recording to the same path (a killed process releases it). Every append is checked:
// on a write error (a full disk) the file is cut back to its last whole line, so it still
// replays up to there, failed() turns true and the window stops the recording with the error
// on screen. A restart or hot reload stops the recording too (stop()): a script is one game
// played on one set of data files, and after a reload the earlier ticks no longer replay
// against the changed files, so a segment could not be followed faithfully.
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
#include <string>
#include <vector>

#include "game/sim/game.h"
#include "replay/script.h"

namespace arc {

class SessionRecorder {
 public:
  // WriteError when the file cannot be written; InputError when another arcfire holds the lock.
  SessionRecorder(const std::string& path, const std::string& level_path, const Game& game,
                  const std::string& build_id = "dev");
  SessionRecorder(const SessionRecorder&) = delete;
  SessionRecorder& operator=(const SessionRecorder&) = delete;
  ~SessionRecorder();

  // Call for every Game::step() (paused ones too), just before it, with exactly its arguments.
  void record(const Game& game, const InputFrame& input, const std::vector<Command>& commands);
  // Writes the final hash and `end` at the game's current tick and closes the file.
  void finish(const Game& game);
  // finish(), then one line on stdout (stderr after a write error) for the log; returns the
  // line for the screen. `why` names what ended it ("restart"; "" for the end of the session).
  std::string stop(const Game& game, const std::string& why);
  const std::string& path() const { return path_; }
  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }  // "PATH: cannot write: REASON"

 private:
  void write(const std::string& text);
  void lock();
  void unlock();
  void keep_previous();

  std::string path_, bak_path_, lock_path_;
  int lock_fd_ = -1;
  int fd_ = -1;
  uint64_t size_ = 0;        // bytes of whole lines in the file
  bool bak_pending_ = false;  // NAME.bak holds the previous recording until the first second
  bool moved_to_bak_ = false;  // this recorder moved NAME there (put back if the header fails)
  std::string error_;
  replay::InputState held_;
  uint64_t tick_rate_ = 60;
  uint64_t first_tick_ = 0;
  uint64_t last_tick_ = 0;
  uint64_t last_line_tick_ = 0;  // the tick of the last line written
  uint64_t replays_to_ = 0;  // the tick the file replays up to once stopped
  bool finished_ = false;
};

}  // namespace arc
