// The training mission (levels/training.json, game/sim/training.h): a player who does nothing
// stays at the first step, each step waits until its condition holds, a pilot who follows the
// prompts wins, a restored game goes on alike, and bad "training" blocks are positioned errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "game/sim/geometry.h"
#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

using test::options;
using test::repo;

const std::string kTraining = "levels/training.json";

int step_of(const Game& g) { return g.world().training ? g.world().training->step : -1; }

// Stick toward a world point, as a pilot following the crosshair would.
void steer_at(const Ship& me, const glm::dvec3& at, InputFrame& f) {
  const glm::dvec3 local = glm::conjugate(me.orientation) * safe_norm(at - me.position, forward_of(me.orientation));
  const double behind = local.z > 0 ? (local.x < 0 ? -1.0 : 1.0) : 0.0;  // turn the shorter way round
  f.yaw = quantise_axis(std::clamp(4.0 * local.x + behind, -1.0, 1.0));
  f.pitch = quantise_axis(std::clamp(4.0 * local.y, -1.0, 1.0));
}

// What a pilot does at each step: the input and commands of one tick, from the world.
struct Pilot {
  InputFrame held;
  void act(const World& w, int step, InputFrame& f, std::vector<Command>& c) {
    const Ship& me = w.ship(w.player);
    f = held;
    switch (step) {
      case 0: f.yaw = quantise_axis(1.0); break;
      case 1: f.yaw = 0, f.throttle = quantise_axis(1.0); break;
      case 2: f.buttons |= kAfterburner; break;
      case 3: f.buttons = 0, f.throttle = quantise_axis(0.2), c.push_back(Command::TargetNearest); break;
      case 4:
      case 5:
        if (!me.target) c.push_back(Command::TargetNearest);
        else steer_at(me, w.ship(me.target).position, f);
        f.buttons = step == 4 ? kFirePrimary : kFireSecondary;
        break;
      case 6: f.buttons = 0, f.yaw = f.pitch = 0, c.push_back(Command::Countermeasure); break;
      case 7: c.push_back(Command::OrderAttack); break;
      default: break;
    }
    held = f;
  }
};

// Runs the course with `pilot`; after each step begins, the pilot first waits `idle` ticks doing
// nothing new, and the step must not advance meanwhile. Returns the tick each step ended at.
std::vector<int64_t> fly_course(Game& g, int idle, FILE* script = nullptr) {
  Pilot pilot;
  std::vector<int64_t> ended;
  int step = 0, idle_left = idle;
  InputFrame last;
  for (int t = 0; t < 60 * 120 && g.world().outcome == Outcome::Undecided; ++t) {
    InputFrame f = pilot.held;
    std::vector<Command> c;
    if (idle_left > 0) --idle_left;
    else pilot.act(g.world(), step, f, c);
    if (script) {
      const char* axes[] = {"pitch", "yaw", "throttle"};
      const int8_t now[] = {f.pitch, f.yaw, f.throttle}, was[] = {last.pitch, last.yaw, last.throttle};
      for (int a = 0; a < 3; ++a)
        if (now[a] != was[a]) std::fprintf(script, "%d axis %s %.6f\n", t, axes[a], now[a] / 127.0);
      const char* buttons[] = {"fire_primary", "fire_secondary", "afterburner"};
      for (int b = 0; b < 3; ++b)
        if ((f.buttons ^ last.buttons) & (1 << b))
          std::fprintf(script, "%d %s %s\n", t, (f.buttons >> b) & 1 ? "press" : "release", buttons[b]);
      for (Command k : c)
        std::fprintf(script, "%d command %s\n", t,
                     k == Command::TargetNearest ? "target_nearest" : k == Command::Countermeasure ? "countermeasure" : "order_attack");
    }
    last = f;
    g.step(f, c);
    if (step_of(g) != step) {
      EXPECT_EQ(step_of(g), step + 1) << "one step per tick, at tick " << g.tick();
      EXPECT_GE(idle_left, 0);
      ended.push_back(int64_t(g.tick()));
      step = step_of(g);
      idle_left = idle;
    }
    if (idle_left > 0) EXPECT_EQ(step_of(g), step) << "step " << step + 1 << " ended while the pilot did nothing new";
  }
  return ended;
}

TEST(Training, APlayerWhoDoesNothingStaysAtTheFirstStep) {
  Game g = Game::load_level(repo(kTraining), options());
  ASSERT_EQ(step_of(g), 0);
  for (int t = 0; t < 60 * 60; ++t) g.step(InputFrame{});
  EXPECT_EQ(step_of(g), 0);
  EXPECT_EQ(g.world().outcome, Outcome::Undecided);
  for (const Ship& s : g.world().ships)
    if (!s.player) EXPECT_TRUE(dormant(s)) << s.name << " has not arrived";
}

TEST(Training, EachStepWaitsForItsConditionAndTheCourseIsWon) {
  Game g = Game::load_level(repo(kTraining), options());
  const size_t steps = g.world().level.training.steps.size();
  // The script of tests/replays/training.replay comes from this pilot (TRAINING_SCRIPT=FILE).
  FILE* script = std::getenv("TRAINING_SCRIPT") ? std::fopen(std::getenv("TRAINING_SCRIPT"), "w") : nullptr;
  const std::vector<int64_t> ended = fly_course(g, 90, script);
  if (script) std::fclose(script);
  EXPECT_EQ(ended.size(), steps);
  EXPECT_EQ(g.world().outcome, Outcome::Victory);
  EXPECT_EQ(step_of(g), int(steps));
  for (size_t i = 0; i < ended.size(); ++i) std::printf("step %zu ended at tick %lld\n", i + 1, (long long)ended[i]);
}

// Held input alone: yaw (step 1 ends), the throttle (step 2), but never the afterburner step.
TEST(Training, ThrottleWithoutAfterburnerStopsAtTheAfterburnerStep) {
  Game g = Game::load_level(repo(kTraining), options());
  for (int t = 0; t < 120; ++t) g.step(InputFrame{.yaw = 127});
  EXPECT_EQ(step_of(g), 1);
  for (int t = 0; t < 60 * 20; ++t) g.step(InputFrame{.throttle = 127});
  EXPECT_EQ(step_of(g), 2) << "the Viper tops out at 160 m/s without the afterburner";
  g.step(InputFrame{.throttle = 127}, {Command::Countermeasure, Command::TargetNearest});
  EXPECT_EQ(step_of(g), 2) << "commands of later steps do not count";
}

TEST(Training, ARestoredGameGoesOnAlike) {
  Game b = Game::load_level(repo(kTraining), options());
  for (int t = 0; t < 200; ++t) b.step(InputFrame{.yaw = 127, .throttle = 127});
  const std::vector<uint8_t> bytes = b.save();
  Game c = Game::restore(bytes, repo(kTraining), options());
  EXPECT_EQ(c.save(), bytes);
  EXPECT_EQ(c.hash(), b.hash());
  EXPECT_EQ(step_of(c), step_of(b));
  for (int t = 0; t < 120; ++t) {
    b.step(InputFrame{.throttle = 127, .buttons = kAfterburner});
    c.step(InputFrame{.throttle = 127, .buttons = kAfterburner});
    ASSERT_EQ(b.hash(), c.hash()) << t;
  }
  EXPECT_EQ(step_of(b), 3) << "turned, throttled up, afterburner: the target step";
}

// Level text with one player, one inactive drone and the given training block.
std::string error_of(const std::string& training, const std::string& drone_extra = R"(, "inactive": true)") {
  const std::string text = R"({ "name": "t", "objective": "x", "win": { "type": "training_complete" },
    "lose": { "type": "player_destroyed" },
    "ships": [ { "name": "P", "class": "viper", "team": "blue", "player": true },
               { "name": "D", "class": "drone", "team": "red", "ai": "drone")" + drone_extra + R"( } ],
    "training": )" + training + "}";
  try {
    parse_level_def(text, "t.json", options().root_dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Training, BadBlocksArePositionedErrors) {
  const std::string ok = R"({ "steps": [ { "prompt": "Press {target_nearest}", "until": "target_selected", "spawn": ["D"] } ] })";
  EXPECT_EQ(error_of(ok), "");
  EXPECT_NE(error_of(R"({ "steps": [ { "prompt": "x", "until": "fly", "spawn": ["D"] } ] })").find("t.json:"), std::string::npos);
  EXPECT_NE(error_of(R"({ "steps": [ { "prompt": "x", "until": "fly", "spawn": ["D"] } ] })").find("turned_degrees"), std::string::npos);
  EXPECT_NE(error_of(R"({ "steps": [ { "prompt": "x", "until": "ship_destroyed", "ship": "Q", "spawn": ["D"] } ] })")
                .find("no ship of this level is named \"Q\""),
            std::string::npos);
  EXPECT_NE(error_of(R"({ "steps": [ { "prompt": "Press {Target}", "until": "wait_seconds", "value": 1, "spawn": ["D"] } ] })")
                .find("placeholders"),
            std::string::npos);
  EXPECT_NE(error_of(R"({ "steps": [ { "prompt": "x", "until": "wait_seconds", "spawn": ["D"] } ] })").find("value"),
            std::string::npos);
  EXPECT_NE(error_of(R"({ "steps": [ { "prompt": "x", "until": "wait_seconds", "value": 1 } ] })").find("no training step spawns it"),
            std::string::npos);
  EXPECT_NE(error_of(R"({ "steps": [ { "prompt": "x", "until": "wait_seconds", "value": 1, "spawn": ["D"] } ] })", "")
                .find("only ships with \"inactive\": true"),
            std::string::npos);
  EXPECT_NE(error_of(R"({ "steps": [] })").find("at least one step"), std::string::npos);
  EXPECT_NE(error_of(R"({ "steps": [ { "prompt": "x", "until": "command_issued", "commands": ["fly"], "spawn": ["D"] } ] })")
                .find("order_attack"),
            std::string::npos);
}

}  // namespace
}  // namespace arc
