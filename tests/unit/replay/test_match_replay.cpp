// A network match's record is a replay script (format version 2): it parses, writes back the
// same, and plays with --replay to the hashes every peer computed, dropped pilots included.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/file_writer.h"
#include "game/app/all_settings.h"
#include "game/app/replay_player.h"
#include "game/net/match_record.h"
#include "game/net/rollback.h"
#include "game/net/scripted_pilot.h"
#include "replay/script.h"

namespace fs = std::filesystem;
using namespace arc;

namespace {

// Slot 0 local, slot 1's inputs `lag` ticks late (rollbacks all along); slot 1's pilot leaves
// at `drop` (0: never).
RollbackSession played(const std::string& level, int ticks, int lag, int64_t drop) {
  const Game start = Game::load_level(level, {});
  RollbackSession s(Game(start), {2, 0, 0, 12, {}});
  for (int t = 1; t <= ticks + lag; ++t) {
    if (t <= ticks) {
      s.add_local_input(scripted_pilot_input(0, t));
      s.advance();
    }
    if (t - lag >= 1 && (drop == 0 || t - lag < drop)) s.add_remote_input(1, t - lag, scripted_pilot_input(1, t - lag));
    if (drop > 0 && t == drop + lag) s.drop_slot(1, drop);
  }
  s.settle();
  return s;
}

TEST(NetMatchRecord, Example) {
  RollbackSession session = played("levels/duel.json", 120, 3, 0);
  const std::string text = match_record_text(session, "levels/duel.json", {"Host", "Pilot1"});
  replay::Script s = replay::parse_script(text, "match.replay", all_settings());
  EXPECT_EQ(s.header.version, 2);
  EXPECT_EQ(s.header.slots, 2);
  ASSERT_EQ(s.header.pilots.size(), 2u);
  EXPECT_EQ(s.header.pilots[1].name, "Pilot1");
  EXPECT_EQ(s.end_tick, 120u);
  EXPECT_TRUE(replay::parse_script(replay::write_script(s), "again.replay", all_settings()).same_content(s));
}

int replay_record(const RollbackSession& session, const std::string& level, const std::string& name, uint64_t* final_hash) {
  const fs::path dir = fs::temp_directory_path() / ("arcfire-test-match-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / (name + ".replay");
  write_file_atomic(file.string(), match_record_text(session, level, {"Host", "Pilot \"One\""}));
  ReplayRunOptions o;
  o.script_path = file.string();
  o.no_render = true;
  o.quiet = true;
  o.golden_dir = (dir / "golden").string();
  o.out_dir = (dir / "out").string();
  const ReplayOutcome r = play_replay(o);
  *final_hash = r.final_hash;
  EXPECT_GT(r.checks, 5);
  EXPECT_EQ(r.failures, 0);
  return r.exit_code;
}

TEST(NetMatchRecord, ReplaysToThePeersHashes) {
  RollbackSession s = played("levels/duel.json", 600, 7, 0);
  ASSERT_GT(s.stats().rollbacks, 20u);
  uint64_t hash = 0;
  EXPECT_EQ(replay_record(s, "levels/duel.json", "duel", &hash), 0);
  EXPECT_EQ(hash, s.hash_at(600));
}

TEST(NetMatchRecord, DroppedPilotReplaysWithTheAi) {
  RollbackSession s = played("levels/duel.json", 480, 4, 200);
  ASSERT_EQ(s.drop_tick(1), 200);
  const std::string text = match_record_text(s, "levels/duel.json", {"Host", "Pilot1"});
  EXPECT_NE(text.find("\ndrop 1 199\n"), std::string::npos);
  uint64_t hash = 0;
  EXPECT_EQ(replay_record(s, "levels/duel.json", "dropped", &hash), 0);
  EXPECT_EQ(hash, s.hash_at(480));
}

}  // namespace
