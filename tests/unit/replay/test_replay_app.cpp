// The replay modes against the real game: a recorded session replays to the same hashes (also
// when the recording was cut short), --update-golden fills in hashes, a changed simulation
// is reported at its first diverging tick, and the serialization test passes.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "core/error.h"
#include "core/file_writer.h"
#include "core/json.h"
#include "game/app/all_settings.h"
#include "game/app/replay_player.h"
#include "game/app/serialization_test.h"
#include "game/app/session_recorder.h"
#include "game/sim/world.h"
#include "replay/script.h"

namespace fs = std::filesystem;
using namespace arc;

namespace {

const std::string kRange = "tests/replays/levels/range.json";

fs::path temp_dir(const std::string& name) {
  fs::path d = fs::temp_directory_path() / ("arcfire-test-replay-" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Varied live-like input: axes sweeping, buttons toggling, commands now and then.
void play_live(Game& game, SessionRecorder& rec, int ticks) {
  for (int t = 0; t < ticks; ++t) {
    InputFrame f;
    f.throttle = quantise_axis(t < 120 ? 1.0 : 0.3);
    f.yaw = quantise_axis(std::sin(t * 0.05) * 0.7);
    f.pitch = quantise_axis(t % 90 < 30 ? 0.25 : 0.0);
    f.buttons = (t / 40) % 2 ? kFirePrimary : 0;
    if (t > 150 && t < 170) f.buttons |= kFireSecondary;
    std::vector<Command> cmds;
    if (t == 20) cmds.push_back(Command::TargetNearest);
    if (t == 100) cmds.push_back(Command::Pause);
    if (t == 130) cmds.push_back(Command::Resume);
    if (t == 200) cmds.push_back(Command::SwitchWeapon);
    rec.record(game, f, cmds);
    game.step(f, cmds);
  }
}

ReplayRunOptions quiet(const fs::path& script) {
  ReplayRunOptions o;
  o.script_path = script.string();
  o.no_render = true;
  o.quiet = true;
  o.golden_dir = (script.parent_path() / "golden").string();
  o.out_dir = (script.parent_path() / "out").string();
  return o;
}

}  // namespace

TEST(ReplayApp, RecordedSessionReplaysToTheSameHashes) {
  fs::path dir = temp_dir("record");
  fs::path file = dir / "live.replay";
  // Simulation settings differ from the replay's defaults: the header must carry them.
  GameOptions live;
  live.particle_budget = 3000;
  live.substeps = 2;
  live.cull_distance = 100;  // which clusters skip ticks is in the hash: it travels as a set line
  Game game = Game::load_level(kRange, live);
  {
    SessionRecorder rec(file.string(), kRange, game);
    play_live(game, rec, 330);
    rec.finish(game);
  }
  replay::Script s = replay::load_script(file.string(), all_settings());
  EXPECT_EQ(s.header.particle_budget, 3000u);
  EXPECT_EQ(s.header.substeps, 2);
  ASSERT_EQ(s.header.settings.size(), 1u);
  EXPECT_EQ(s.header.settings[0].key + "=" + s.header.settings[0].value, "particles.cull_distance=100");
  EXPECT_EQ(s.end_tick, 330u);
  EXPECT_GE(s.hashes.size(), 5u);  // one per second, and the final one
  EXPECT_EQ(s.commands.size(), 4u);
  ReplayOutcome r = play_replay(quiet(file));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.failures, 0);
  EXPECT_EQ(r.checks, int(s.hashes.size()));
  EXPECT_EQ(r.final_hash, game.hash());
  EXPECT_EQ(r.ticks, 330u);
}

TEST(ReplayApp, RecordingCutShortStillReplays) {
  fs::path dir = temp_dir("killed");
  fs::path file = dir / "killed.replay";
  Game game = Game::load_level(kRange, GameOptions{});
  // A killed process runs no destructor: leak the recorder instead of finishing it.
  auto* rec = new SessionRecorder(file.string(), kRange, game);
  play_live(game, *rec, 250);
  replay::Script s = replay::load_script(file.string(), all_settings());
  EXPECT_FALSE(s.end_tick.has_value());
  EXPECT_EQ(s.hashes.back().tick, 240u);
  ReplayOutcome r = play_replay(quiet(file));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.failures, 0);
  EXPECT_GE(r.checks, 4);
}

TEST(ReplayApp, UpdateGoldenFillsHashesAndAChangedRunDivergesAtItsFirstTick) {
  fs::path dir = temp_dir("golden");
  fs::path file = dir / "s.replay";
  const std::string text = "arcfire-replay 1\nlevel " + kRange +
                           "\n0 press fire_primary\n60 hash ?\n# keep\n90 full_hash ?\n120 axis yaw 0.5\n150 end\n";
  write_file_atomic(file.string(), text);
  ReplayRunOptions o = quiet(file);
  EXPECT_EQ(play_replay(o).exit_code, kExitCheckFailed);  // "?" is not a value
  o.update_golden = true;
  EXPECT_EQ(play_replay(o).exit_code, 0);
  replay::Script filled = replay::load_script(file.string(), all_settings());
  ASSERT_TRUE(filled.hashes[0].value && filled.hashes[1].value);
  EXPECT_NE(read_text_file(file.string()).find("# keep\n"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "golden" / "hashes.txt"));
  o.update_golden = false;
  EXPECT_EQ(play_replay(o).exit_code, 0);

  // The same script firing 30 ticks later must fail, and name tick 1 as the first divergence
  // (the beam's trigger shows in the hash of the first step's result).
  std::string changed = read_text_file(file.string());
  changed.replace(changed.find("0 press"), 7, "30 press");
  write_file_atomic(file.string(), changed);
  testing::internal::CaptureStdout();
  ReplayOutcome r = play_replay(o);
  std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(r.exit_code, kExitCheckFailed);
  EXPECT_NE(out.find("first diverging tick 1:"), std::string::npos) << out;
  EXPECT_NE(out.find("state at tick 1:\ntick 1 "), std::string::npos) << out;
  EXPECT_NE(out.find("FAIL " + file.string() + ":4: tick 60: 60 hash "), std::string::npos) << out;
}

TEST(ReplayApp, ExpectationFailuresNameTickAndLine) {
  fs::path dir = temp_dir("expect");
  fs::path file = dir / "e.replay";
  write_file_atomic(file.string(), "arcfire-replay 1\nlevel " + kRange +
                                       "\n30 expect hull Drone 0..10\n30 expect alive Drone\n30 expect winner red\n30 end\n");
  testing::internal::CaptureStdout();
  ReplayOutcome r = play_replay(quiet(file));
  std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(r.exit_code, kExitCheckFailed);
  EXPECT_EQ(r.failures, 2);
  EXPECT_NE(out.find(":3: tick 30: 30 expect hull Drone 0..10: hull of Drone is 220"), std::string::npos) << out;
  EXPECT_NE(out.find(":5: tick 30: 30 expect winner red: winner is none"), std::string::npos) << out;
}

TEST(ReplayApp, UnknownShipIsBadInputAtItsColumn) {
  fs::path dir = temp_dir("names");
  fs::path file = dir / "n.replay";
  write_file_atomic(file.string(), "arcfire-replay 1\nlevel " + kRange + "\n5 expect distance Player  \"Dron\" 0..1\n");
  try {
    play_replay(quiet(file));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file.string() + ":3:27: no ship named 'Dron'", 0), 0u) << e.what();
  }
}

// A script's `set` lines change the simulation as --set does, and its `quality` preset is
// looked up in assets/settings/quality.json; an unknown preset is bad input at its column.
TEST(ReplayApp, ScriptSettingsChangeTheSimulationLikeTheHeaderKeys) {
  fs::path dir = temp_dir("settings");
  const std::string body = "0 press fire_primary\n0 axis yaw 0.4\n120 end\n";
  auto final_hash = [&](const std::string& name, const std::string& header) {
    fs::path file = dir / (name + ".replay");
    write_file_atomic(file.string(), "arcfire-replay 1\nlevel " + kRange + "\n" + header + body);
    return play_replay(quiet(file)).final_hash;
  };
  const uint64_t plain = final_hash("plain", "");
  EXPECT_EQ(final_hash("set", "set sim.substeps=2\n"), final_hash("pinned", "substeps 2\n"));
  EXPECT_NE(final_hash("set", "set sim.substeps=2\n"), plain);
  EXPECT_EQ(final_hash("render_only", "set render.soft_edges=off\ntolerance 0/255 100%\n"), plain);
  EXPECT_EQ(final_hash("preset_pinned", "quality reference\nparticle_budget 200000\nsubsteps 1\n"), plain);

  fs::path file = dir / "bad.replay";
  write_file_atomic(file.string(), "arcfire-replay 1\nlevel " + kRange + "\n  quality ultra\n" + body);
  try {
    play_replay(quiet(file));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file.string() + ":3:11: unknown quality preset 'ultra'", 0), 0u) << e.what();
  }
}

TEST(ReplayApp, SerializationTestPasses) {
  SerializationTestOptions s;
  s.level_path = "levels/duel.json";
  s.every = 45;
  s.ticks = 400;
  testing::internal::CaptureStdout();
  int code = run_serialization_test(s);
  std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("final hash "), std::string::npos);
}
