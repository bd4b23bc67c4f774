// The session recorder: a live Game's input, commands and periodic hashes as a replay script.
#include "game/app/session_recorder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/data_layers.h"
#include "core/error.h"
#include "core/file_writer.h"
#include "core/input_file.h"
#include "game/app/script_feeder.h"
#include "game/sim/world.h"

namespace arc {
namespace {

std::string read_small_file(const std::string& path) {
  std::string text;
  try {  // the holder's pid is a courtesy: a lock file that cannot be read just goes unnamed
    InputFile in(path, 4096, "a lock file");
    char buf[64];
    text.assign(buf, in.read_some(buf, sizeof buf));
  } catch (const InputError&) {
    text.clear();
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

bool same_file(int fd, const std::string& path) {
  struct stat a {}, b {};
  return ::fstat(fd, &a) == 0 && ::stat(path.c_str(), &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

}  // namespace

// flock() on NAME.lock: released by the kernel when the process ends, however it ends. The
// file is removed by its holder, so a lock taken on a file just removed is retried.
void SessionRecorder::lock() {
  lock_path_ = path_ + ".lock";
  for (int attempt = 0; attempt < 5; ++attempt) {
    const int fd = ::open(lock_path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0)
      throw WriteError("--record " + path_ + ": cannot create the lock file " + lock_path_ + ": " + system_reason(errno),
                       kExitBadInput);
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      ::close(fd);
      if (err != EWOULDBLOCK)
        throw WriteError("--record " + path_ + ": cannot lock " + lock_path_ + ": " + system_reason(err), kExitBadInput);
      const std::string holder = read_small_file(lock_path_);
      throw InputError("--record " + path_ + ": another arcfire" + (holder.empty() ? "" : " (pid " + holder + ")") +
                       " is recording to this file; refused (lock " + lock_path_ + ")");
    }
    if (same_file(fd, lock_path_)) {
      const std::string pid = std::to_string(::getpid()) + "\n";
      if (::ftruncate(fd, 0) == 0) write_all(fd, pid.data(), pid.size());  // who holds it, for the message
      lock_fd_ = fd;
      return;
    }
    ::close(fd);
  }
  throw InputError("--record " + path_ + ": cannot take the lock " + lock_path_ + " (it keeps being replaced)");
}

void SessionRecorder::unlock() {
  if (lock_fd_ < 0) return;
  ::unlink(lock_path_.c_str());
  ::close(lock_fd_);
  lock_fd_ = -1;
}

// An existing recording moves to NAME.bak. An existing NAME.bak is older still: the session
// that left it ended before its first second, so NAME is that short file and NAME.bak stays.
void SessionRecorder::keep_previous() {
  namespace fs = std::filesystem;
  bak_path_ = path_ + ".bak";
  std::error_code ec;
  if (fs::exists(path_, ec) && !fs::exists(bak_path_, ec)) {
    if (std::rename(path_.c_str(), bak_path_.c_str()) != 0)
      throw WriteError("--record " + path_ + ": cannot keep the previous recording as " + bak_path_ + ": " +
                           system_reason(errno),
                       kExitBadInput);
    moved_to_bak_ = true;
  }
  bak_pending_ = fs::exists(bak_path_, ec);
}

SessionRecorder::SessionRecorder(const std::string& path, const std::string& level_path, const Game& game,
                                 const std::string& build_id)
    : path_(path) {
  const World& w = game.world();
  replay::Header h;
  h.level = level_path;
  h.seed = w.seed;
  tick_rate_ = static_cast<uint64_t>(std::lround(1.0 / w.dt));
  h.tick_rate = static_cast<int>(tick_rate_);
  h.difficulty = difficulty_name(static_cast<Difficulty>(w.difficulty));
  h.ship = w.options.ship;
  h.loadout = w.options.loadout;
  h.build = build_id;
  for (const ModLayer& m : data_layers().mods()) h.mods.push_back({m.name, m.hash});  // replays refuse other data
  // The settings that change the simulation travel with the recording, so a session played
  // with --quality low replays exactly under any other quality.
  h.particle_budget = w.options.particle_budget;
  h.lightning_interval = w.options.lightning_interval;
  h.substeps = w.options.substeps;
  // The cull distance decides which clusters skip ticks, and that is in the hash.
  if (w.options.cull_distance != GameOptions{}.cull_distance) {
    char text[32];  // the shortest text that reads back as the same double
    char* end = std::to_chars(text, text + sizeof text, w.options.cull_distance).ptr;
    h.settings.push_back({"particles.cull_distance", std::string(text, size_t(end - text))});
  }
  const std::string header = replay::header_text(h) + "# recorded live session\n";
  lock();
  try {
    keep_previous();
    // The header lands complete or not at all; lines are then appended to the renamed file.
    write_file_checked(path, header);
    fd_ = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd_ < 0) throw WriteError("--record " + path + ": cannot open for appending: " + system_reason(errno), kExitBadInput);
  } catch (...) {
    if (moved_to_bak_) std::rename(bak_path_.c_str(), path_.c_str());  // no new recording: the old one is back
    unlock();
    throw;
  }
  size_ = header.size();
  first_tick_ = last_tick_ = last_line_tick_ = w.steps;
}

SessionRecorder::~SessionRecorder() {
  if (!finished_ && fd_ >= 0) write(replay::end_line(last_tick_));
  if (fd_ >= 0) ::close(fd_);
  unlock();
}

// Appends whole lines or nothing: a failed write is cut back to the last complete line.
void SessionRecorder::write(const std::string& text) {
  if (text.empty() || fd_ < 0 || failed()) return;
  if (const int err = write_all(fd_, text.data(), text.size())) {
    const bool cut = ::ftruncate(fd_, off_t(size_)) == 0;
    error_ = path_ + ": cannot write: " + system_reason(err) + (cut ? "" : " (and cannot cut the last line short)");
    return;
  }
  size_ += text.size();
}

void SessionRecorder::record(const Game& game, const InputFrame& input, const std::vector<Command>& commands) {
  if (finished_ || failed()) return;
  // Script ticks count step() calls: paused steps do not advance game time but do count.
  const uint64_t t = game.world().steps;
  std::string lines;
  if (t % tick_rate_ == 0 && t > 0) {
    replay::HashCheck h;
    h.tick = t;
    h.value = game.hash();
    lines += replay::hash_line(h);
  }
  const replay::InputState now = to_input_state(input);
  lines += replay::input_diff_lines(t, held_, now);
  held_ = now;
  for (Command c : commands) {
    if (c == Command::None) continue;
    replay::CommandEvent e;
    e.tick = t;
    e.command = static_cast<replay::ScriptCommand>(c);
    lines += replay::command_line(e);
  }
  write(lines);
  if (failed()) {
    replays_to_ = last_line_tick_;  // a replay ends at the file's last line
    return;
  }
  if (!lines.empty()) last_line_tick_ = t;
  last_tick_ = t + 1;
  if (bak_pending_ && last_tick_ - first_tick_ >= tick_rate_) {
    ::unlink(bak_path_.c_str());  // the new session has its first second: it replaces the old one
    bak_pending_ = false;
  }
}

void SessionRecorder::finish(const Game& game) {
  if (finished_ || fd_ < 0) return;
  replay::HashCheck h;
  h.tick = game.world().steps;
  h.value = game.hash();
  const bool failed_before = failed();
  write(replay::hash_line(h) + replay::end_line(h.tick));
  if (!failed_before) replays_to_ = h.tick;
  ::close(fd_);
  fd_ = -1;
  finished_ = true;
  unlock();
}

std::string SessionRecorder::stop(const Game& game, const std::string& why) {
  finish(game);
  const std::string tick = std::to_string(replays_to_);
  const std::string kept = bak_pending_ ? "; it has less than a second, so the previous recording stays as " + bak_path_
                                        : "";
  if (failed()) {
    std::fprintf(stderr, "arcfire: %s; recording stopped, it replays up to tick %s%s\n", error_.c_str(), tick.c_str(),
                 kept.c_str());
    return "Recording stopped: " + error_ + " (it replays up to tick " + tick + ")";
  }
  if (why.empty()) std::printf("arcfire: recorded %s%s\n", path_.c_str(), kept.c_str());
  else
    std::printf("arcfire: recording %s stopped by the %s; it replays up to tick %s%s\n", path_.c_str(), why.c_str(),
                tick.c_str(), kept.c_str());
  std::fflush(stdout);
  return "Recording stopped (" + why + "): " + path_ + " replays up to here";
}

}  // namespace arc
