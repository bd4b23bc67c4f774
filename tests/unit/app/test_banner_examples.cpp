// The usage examples in the banners of game/app headers, word for word, so an example that no
// longer matches the code fails to compile or fails here. Each banner names its test, and
// HeaderExamples.MatchTheirTests (tests/unit/core) checks that the banner's lines are its text.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "core/json.h"
#include "game/app/menu.h"
#include "game/app/all_settings.h"
#include "game/app/replay_player.h"
#include "game/app/serialization_test.h"
#include "game/app/session_recorder.h"
#include "replay/script.h"

namespace arc {
namespace {

TEST(BannerExample, ReplayPlayer) {
  testing::internal::CaptureStdout();

  ReplayRunOptions options;
  options.script_path = "tests/replays/range_beam_shield.replay";
  options.no_render = true;                      // hashes and expectations only: no GL context
  ReplayOutcome outcome = play_replay(options);  // prints one `ok` or `FAIL` line per check
  // outcome.exit_code is 0 when every check passed; outcome.final_hash, outcome.ticks
  // run_replay(options) plays it too and ends stdout with "final hash HEX at tick N"

  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(outcome.exit_code, 0) << out;
  EXPECT_EQ(outcome.failures, 0);
  EXPECT_GT(outcome.checks, 0);
  EXPECT_EQ(outcome.ticks, replay::load_script(options.script_path, all_settings()).last_tick());
}

TEST(BannerExample, Menu) {
  const UserFiles files;
  const Bindings bindings = load_bindings("assets/settings/bindings.json");
  PauseState paused;
  MissionResult result;
  result.victory = true;

  Menu menu(load_mission_catalog("levels", "."), files, bindings, bindings, "assets/settings/quality.json");
  menu.handle(UiInput::press(UiKey::Accept));  // Play: mission select
  menu.handle(UiInput::press(UiKey::Accept));  // the first mission's briefing
  std::vector<MenuRequest> go = menu.handle(UiInput::press(UiKey::Accept));  // Launch
  menu.pause(paused);                          // the game paused: Resume, Restart, ... Quit
  std::vector<MenuRequest> resume = menu.handle(UiInput::press(UiKey::Back));  // Esc: Resume
  menu.show_results(go[0].level, go[0].difficulty, result);  // the fight decided

  ASSERT_EQ(go.size(), 1u);
  EXPECT_EQ(go[0].kind, MenuRequest::Kind::Launch);
  EXPECT_EQ(go[0].level, "levels/training.json");
  ASSERT_EQ(resume.size(), 1u);
  EXPECT_EQ(resume[0].kind, MenuRequest::Kind::Resume);
  EXPECT_EQ(menu.screen(), MenuScreen::Results);
}

TEST(BannerExample, SessionRecorder) {
  const std::string level = "tests/replays/levels/range.json";
  const std::string path = testing::TempDir() + "/banner_example_session.replay";

  Game game = Game::load_level(level, GameOptions{});
  SessionRecorder recorder(path, level, game);  // the header is written now
  for (int tick = 0; tick < 120; ++tick) {
    InputFrame input;
    input.throttle = 127;
    std::vector<Command> commands;
    if (tick == 30) commands.push_back(Command::TargetNearest);
    recorder.record(game, input, commands);     // just before the step, with its arguments
    game.step(input, commands);
  }
  recorder.finish(game);                        // final hash and `end` (~SessionRecorder too)

  const replay::Script script = replay::load_script(path, all_settings());
  EXPECT_EQ(script.end_tick, 120u);
  EXPECT_EQ(script.commands.size(), 1u);
  ASSERT_FALSE(script.hashes.empty());
  EXPECT_EQ(script.hashes.back().value, game.hash());
  ReplayRunOptions replay_options;
  replay_options.script_path = path;
  replay_options.no_render = true;
  replay_options.quiet = true;
  EXPECT_EQ(play_replay(replay_options).final_hash, game.hash());
}

TEST(BannerExample, SerializationTest) {
  testing::internal::CaptureStdout();

  SerializationTestOptions options;
  options.level_path = "tests/replays/levels/range.json";
  options.every = 30;                              // save and restore every 30 ticks
  options.ticks = 120;
  int exit_code = run_serialization_test(options);  // 0: hashes equal on every tick

  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(exit_code, 0) << out;
  EXPECT_NE(out.find("4 save/restore cycles"), std::string::npos) << out;
}

}  // namespace
}  // namespace arc
