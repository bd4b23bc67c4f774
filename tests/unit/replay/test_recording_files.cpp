// The recording's files (game/app/session_recorder.h): a full disk leaves whole lines that
// replay, an earlier recording waits in NAME.bak until the new one has its first second, and a
// second recorder on the same path is refused by the lock.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "core/file_writer.h"
#include "game/app/all_settings.h"
#include "game/app/replay_player.h"
#include "game/app/session_recorder.h"
#include "game/sim/world.h"
#include "replay/script.h"

namespace fs = std::filesystem;
using namespace arc;

namespace {

const std::string kRange = "tests/replays/levels/range.json";

fs::path temp_dir(const std::string& name) {
  fs::path d = fs::temp_directory_path() / ("arcfire-test-recording-" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Throttle and yaw changing every few ticks, so every tick or two appends lines.
void fly(Game& game, SessionRecorder& rec, int ticks) {
  for (int i = 0; i < ticks; ++i) {
    InputFrame f;
    f.throttle = quantise_axis(0.2 + 0.1 * (i % 7));
    f.yaw = quantise_axis((i / 3) % 2 ? 0.4 : -0.4);
    rec.record(game, f, {});
    game.step(f, {});
  }
}

ReplayOutcome play(const fs::path& script) {
  ReplayRunOptions o;
  o.script_path = script.string();
  o.no_render = true;
  o.quiet = true;
  o.golden_dir = (script.parent_path() / "golden").string();
  return play_replay(o);
}

struct NoWriteLimit {
  ~NoWriteLimit() { set_write_limit(std::numeric_limits<uint64_t>::max()); }
};

}  // namespace

TEST(RecordingFiles, FullDiskKeepsWholeLinesThatReplay) {
  const fs::path file = temp_dir("full") / "live.replay";
  Game game = Game::load_level(kRange, GameOptions{});
  NoWriteLimit restore;
  set_write_limit(4000);  // the header and about two seconds of lines
  SessionRecorder rec(file.string(), kRange, game);
  fly(game, rec, 600);
  ASSERT_TRUE(rec.failed());
  EXPECT_EQ(rec.error(), file.string() + ": cannot write: No space left on device");
  const std::string notice = rec.stop(game, "");
  EXPECT_NE(notice.find("No space left on device"), std::string::npos) << notice;
  const std::string text = read(file);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << "a line was cut: " << text.substr(text.size() - 40);
  replay::Script s = replay::load_script(file.string(), all_settings());
  EXPECT_GE(s.hashes.size(), 1u);
  const ReplayOutcome r = play(file);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.failures, 0);
}

TEST(RecordingFiles, PreviousRecordingKeptAsBakUntilTheFirstSecond) {
  const fs::path dir = temp_dir("bak");
  const fs::path file = dir / "live.replay", bak = dir / "live.replay.bak";
  std::ofstream(file) << "previous recording\n";
  Game game = Game::load_level(kRange, GameOptions{});
  {
    SessionRecorder rec(file.string(), kRange, game);
    fly(game, rec, 30);
    EXPECT_EQ(read(bak), "previous recording\n");
    rec.stop(game, "");  // half a second: both stay
  }
  EXPECT_EQ(read(bak), "previous recording\n");
  EXPECT_TRUE(replay::load_script(file.string(), all_settings()).end_tick.has_value());
  // A later session: the .bak still holds the older recording (the short one is dropped) ...
  Game again = Game::load_level(kRange, GameOptions{});
  SessionRecorder rec(file.string(), kRange, again);
  fly(again, rec, 59);
  EXPECT_EQ(read(bak), "previous recording\n");
  // ... until this one has recorded its first second.
  fly(again, rec, 1);
  EXPECT_FALSE(fs::exists(bak));
  rec.finish(again);
  EXPECT_EQ(play(file).failures, 0);
}

TEST(RecordingFiles, SecondRecorderOnTheSamePathIsRefused) {
  const fs::path file = temp_dir("lock") / "live.replay";
  Game game = Game::load_level(kRange, GameOptions{});
  auto first = std::make_unique<SessionRecorder>(file.string(), kRange, game);
  EXPECT_TRUE(fs::exists(file.string() + ".lock"));
  try {
    SessionRecorder second(file.string(), kRange, game);
    ADD_FAILURE() << "a second recorder on the same path was allowed";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("--record " + file.string() + ": another arcfire (pid "), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
  EXPECT_FALSE(fs::exists(file.string() + ".bak")) << "the refused one must not touch the recording";
  fly(game, *first, 90);
  first->finish(game);
  EXPECT_EQ(play(file).failures, 0);
  first.reset();
  EXPECT_FALSE(fs::exists(file.string() + ".lock"));
  SessionRecorder third(file.string(), kRange, game);  // the lock is free again
}
