// Mouse flight and the set throttle through the live-input path: device frames at a given
// frame rate, the fixed-step clock, LiveInput's InputFrames, and the duel's player Viper.
#include <cmath>
#include <cstdio>
#include <vector>
#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include "core/clock.h"
#include "game/app/input_bindings.h"
#include "game/sim/game.h"
#include "game/sim/simulation.h"
#include "game/sim/world.h"
#include "core/data_root.h"

namespace {

const std::string kDefaultBindings = arc::data_root() + "/assets/settings/bindings.json";
const std::string kDuel = arc::data_root() + "/levels/duel.json";
constexpr double kDegreesPerRadian = 57.29577951308232;

// A live session without a window: the duel, its player's turn rates given to the input as
// the window loop gives them, and a frame loop that takes one InputFrame per tick.
struct LiveFlight {
  arc::LiveInput input;
  arc::Game game;
  arc::FixedStepClock clock{60};
  arc::InputState devices;

  explicit LiveFlight(arc::Bindings b) : input(std::move(b)), game(load()) {
    const arc::World& w = game.world();
    arc::FlightScale scale;
    scale.pitch_rate_degrees = me().cls->turn_rate[0];
    scale.yaw_rate_degrees = me().cls->turn_rate[1];
    scale.tick_seconds = w.dt;
    input.set_flight_scale(scale);
    input.sample(devices);  // the capture jump of the first sample is ignored
  }
  static arc::Game load() {
    arc::GameOptions o;
    o.root_dir = arc::data_root();
    return arc::Game::load_level(kDuel, o);
  }
  const arc::Ship& me() const { return game.world().ship(game.world().player); }

  // One rendered frame: sample the devices, then every tick the frame owes, as window_loop does.
  template <class PerTick>
  void frame(double seconds, PerTick per_tick) {
    input.sample(devices);
    devices.key_presses.fill(0);
    const int ticks = clock.advance(seconds);
    for (int i = 0; i < ticks; ++i) {
      const glm::dquat before = me().orientation;
      game.step(input.take_frame(ticks - i), input.take_commands());
      per_tick(before);
    }
  }
};

struct TurnRun {
  double degrees = 0;    // yaw about the ship's up axis, positive to the right
  double peak_rate = 0;  // largest yaw rate as a share of the ship's full rate
};

// `pixels` of rightward mouse travel at `px_per_second`, then `settle` seconds more.
TurnRun turn_from_mouse(double pixels, double px_per_second, double fps, double settle = 2.0) {
  LiveFlight live(arc::load_bindings(kDefaultBindings));
  double fed = 0;
  TurnRun r;
  const double full_rate = live.me().cls->turn_rate[1] / kDegreesPerRadian;
  for (double t = 0; t < pixels / px_per_second + settle; t += 1.0 / fps) {
    live.devices.mouse_dx = std::min(px_per_second / fps, pixels - fed);
    fed += live.devices.mouse_dx;
    live.frame(1.0 / fps, [&](const glm::dquat& before) {
      const glm::dquat d = glm::conjugate(before) * live.me().orientation;
      r.degrees -= 2.0 * std::atan2(d.y, d.w) * kDegreesPerRadian;  // +Y turns the nose left
      r.peak_rate = std::max(r.peak_rate, std::fabs(live.me().angular_velocity.y) / full_rate);
    });
  }
  return r;
}

}  // namespace

// 1500 px of travel turn the ship about 180 degrees at 20, 60 and 144 fps (before: 32 000 to
// 36 000 px, 8 degrees per 1500 px), and a fast motion reaches the full turn rate at each.
TEST(MouseFlight, HalfTurnTakesAbout1500PixelsAtAnyFrameRate) {
  for (double fps : {20.0, 60.0, 144.0}) {
    const TurnRun slow = turn_from_mouse(1500, 400, fps);
    const TurnRun fast = turn_from_mouse(3000, 3000, fps);
    std::printf("[ measure  ] %3.0f fps: 1500 px at 400 px/s turn %.2f deg (%.0f px per 180 deg); "
                "3000 px/s reach %.3f of the full yaw rate\n",
                fps, slow.degrees, 1500 * 180 / slow.degrees, fast.peak_rate);
    EXPECT_NEAR(slow.degrees, 180.0, 2.0) << fps << " fps";
    EXPECT_GT(fast.peak_rate, 0.97) << fps << " fps";
  }
}

// A flick faster than the ship can turn still turns it all the way, at its full turn rate
// (700 px in 0.35 s mean 84 degrees at 0.12 degrees per pixel), at every frame rate; a slow
// move turns by its pixels (350 px over one second: 42 degrees).
TEST(MouseFlight, FlickTurnsAsFarAsTheMouseWent) {
  for (double fps : {20.0, 60.0, 144.0}) {
    const TurnRun flick = turn_from_mouse(700, 2000, fps);
    const TurnRun slow = turn_from_mouse(350, 350, fps);
    std::printf("[ measure  ] %3.0f fps: 700 px in 0.35 s turn %.2f deg; 350 px in 1 s turn %.2f deg\n", fps,
                flick.degrees, slow.degrees);
    EXPECT_NEAR(flick.degrees, 84.0, 2.0) << fps << " fps";
    EXPECT_NEAR(slow.degrees, 42.0, 1.0) << fps << " fps";
    EXPECT_GT(flick.peak_rate, 0.97) << fps << " fps";  // as fast as the ship can
  }
}

// The turn still owed is bounded: a wild flick of two full turns ends after about a half turn
// more than the ship turned while the mouse moved.
TEST(MouseFlight, FlickBacklogIsAtMostAHalfTurn) {
  const TurnRun wild = turn_from_mouse(6000, 30000, 60, 4.0);  // 720 degrees in 0.2 s
  std::printf("[ measure  ] 6000 px in 0.2 s turn %.2f deg\n", wild.degrees);
  EXPECT_GT(wild.degrees, 180.0);
  EXPECT_LT(wild.degrees, 215.0);
}

// Moving the mouse back takes from what a flick still owes first, pixel for pixel: a flick and
// its correction end where the mouse did, and moving back further than is owed turns the other
// way at once.
TEST(MouseFlight, ReversingTheMouseTakesFromTheBacklog) {
  for (double fps : {20.0, 60.0, 144.0}) {
    LiveFlight live(arc::load_bindings(kDefaultBindings));
    double degrees = 0;
    auto yaw = [&](const glm::dquat& before) {
      const glm::dquat d = glm::conjugate(before) * live.me().orientation;
      degrees -= 2.0 * std::atan2(d.y, d.w) * kDegreesPerRadian;
    };
    const int flick_frames = int(std::lround(0.35 * fps));
    for (int i = 0; i < flick_frames; ++i) {
      live.devices.mouse_dx = 700.0 / flick_frames;
      live.frame(1.0 / fps, yaw);
    }
    live.devices.mouse_dx = -100;  // 12 degrees back
    live.frame(1.0 / fps, yaw);
    live.devices.mouse_dx = 0;
    for (int i = 0; i < int(3 * fps); ++i) live.frame(1.0 / fps, yaw);
    EXPECT_NEAR(degrees, 72.0, 2.0) << fps << " fps";
  }
  LiveFlight live(arc::load_bindings(kDefaultBindings));
  live.devices.mouse_dx = 500;  // 60 degrees in one frame: far more than one tick turns
  live.frame(1.0 / 60, [](const glm::dquat&) {});
  live.devices.mouse_dx = -600;  // back past where it started
  live.input.sample(live.devices);
  EXPECT_LT(live.input.take_frame().yaw, 0);
}

// The frames LiveInput gives are the frames the simulation and a recording see: replaying
// them gives the same ship, whatever backlog the live input carried between them.
TEST(MouseFlight, FlickFramesReplayBitForBit) {
  LiveFlight live(arc::load_bindings(kDefaultBindings));
  LiveFlight replay(arc::load_bindings(kDefaultBindings));
  std::vector<arc::InputFrame> frames;
  for (int i = 0; i < 240; ++i) {
    live.devices.mouse_dx = i < 20 ? 90 : i == 100 ? -400 : 0;
    live.devices.mouse_dy = i < 10 ? -60 : 0;
    live.input.sample(live.devices);
    frames.push_back(live.input.take_frame());
    live.game.step(frames.back(), {});
  }
  for (const arc::InputFrame& f : frames) replay.game.step(f, {});
  EXPECT_EQ(live.me().orientation, replay.me().orientation);
  EXPECT_EQ(live.me().position, replay.me().position);
}

// The afterburner flies at its full boost from any set throttle, zero and reverse included,
// and the ship returns to the set throttle when it is let go.
TEST(Afterburner, BoostsFromZeroThrottleAndReturnsToIt) {
  for (const char* throttle_key : {"", "S"}) {
    LiveFlight live(arc::load_bindings(kDefaultBindings));
    if (*throttle_key) {
      live.devices.keys[size_t(arc::key_code(throttle_key))] = true;  // half a second: reverse 0.3
      for (int i = 0; i < 30; ++i) live.frame(1.0 / 60, [](const glm::dquat&) {});
      live.devices.keys[size_t(arc::key_code(throttle_key))] = false;
    }
    const double set = live.input.set_throttle();
    live.devices.keys[size_t(arc::key_code("LEFT_SHIFT"))] = true;
    for (int i = 0; i < 120; ++i) live.frame(1.0 / 60, [](const glm::dquat&) {});
    const arc::Ship& me = live.me();
    const double boosted = glm::dot(me.velocity, arc::forward_of(me.orientation));
    std::printf("[ measure  ] set throttle %.2f: 2 s of afterburner reach %.1f m/s forward (boost %.0f m/s)\n", set,
                boosted, me.cls->max_speed * me.cls->afterburner_speed);
    EXPECT_GT(boosted, 0.8 * me.cls->max_speed * me.cls->afterburner_speed) << "throttle " << set;
    live.devices.keys[size_t(arc::key_code("LEFT_SHIFT"))] = false;
    for (int i = 0; i < 600; ++i) live.frame(1.0 / 60, [](const glm::dquat&) {});
    const double after = glm::dot(me.velocity, arc::forward_of(me.orientation));
    EXPECT_NEAR(after, set * (set < 0 ? me.cls->reverse_fraction : 1.0) * me.cls->max_speed, 1.0);
  }
}

TEST(MouseFlight, MouseRightAndUpTurnTheNoseRightAndUp) {
  LiveFlight live(arc::load_bindings(kDefaultBindings));
  live.devices.mouse_dx = 100;
  live.devices.mouse_dy = -100;
  for (int i = 0; i < 20; ++i) live.frame(1.0 / 60, [](const glm::dquat&) {});
  const glm::dvec3 nose = arc::forward_of(live.me().orientation);
  EXPECT_GT(nose.x, 0.1);
  EXPECT_GT(nose.y, 0.1);
}

TEST(MouseFlight, InvertYLowersTheNoseWhenTheMouseMovesUp) {
  arc::Bindings b = arc::load_bindings(kDefaultBindings);
  b.mouse_invert_y = true;
  LiveFlight live(b);
  live.devices.mouse_dy = -100;
  for (int i = 0; i < 20; ++i) live.frame(1.0 / 60, [](const glm::dquat&) {});
  EXPECT_LT(arc::forward_of(live.me().orientation).y, -0.1);
}

TEST(MouseFlight, JoystickOffsetSetsTheTurnRateAndTheReticle) {
  arc::Bindings b = arc::load_bindings(kDefaultBindings);
  b.mouse_mode = arc::MouseMode::Joystick;
  arc::LiveInput in(b);
  in.set_screen_height(720);  // radius 0.25 screen heights: 180 px
  arc::InputState s;
  in.sample(s);
  s.mouse_dx = 5;  // within the dead zone (6 % of 180 px)
  in.sample(s);
  EXPECT_EQ(in.take_frame().yaw, 0);
  s.mouse_dx = 85;  // 90 px right: half way out of the dead zone's remainder and beyond
  in.sample(s);
  EXPECT_EQ(in.take_frame().yaw, arc::quantise_axis((0.5 - 0.06) / 0.94));
  EXPECT_EQ(in.take_frame().yaw, arc::quantise_axis((0.5 - 0.06) / 0.94));  // held, not consumed
  s.mouse_dx = 1000;  // far beyond the ring: the cursor stays on it
  in.sample(s);
  EXPECT_EQ(in.take_frame().yaw, 127);
  const arc::MouseReticle r = in.reticle();
  EXPECT_TRUE(r.shown);
  EXPECT_NEAR(r.x, 0.25, 1e-12);
  s.mouse_dx = -180;  // back to the centre at once
  in.sample(s);
  EXPECT_EQ(in.take_frame().yaw, 0);
  in.discard_mouse_motion();
  EXPECT_EQ(in.reticle().x, 0.0);
}

TEST(Throttle, StaysWhereItIsSet) {
  arc::LiveInput in(arc::load_bindings(kDefaultBindings));
  arc::InputState s;
  s.keys[size_t(arc::key_code("W"))] = true;
  in.sample(s);
  int8_t t = 0;
  for (int i = 0; i < 60; ++i) t = in.take_frame().throttle;  // one second at 0.6 per second
  EXPECT_EQ(t, arc::quantise_axis(0.6));
  s.keys[size_t(arc::key_code("W"))] = false;
  in.sample(s);
  for (int i = 0; i < 120; ++i) t = in.take_frame().throttle;
  EXPECT_EQ(t, arc::quantise_axis(0.6));  // released: no spring back
}

TEST(Throttle, SlowingDownStopsAtZeroUntilPressedAgain) {
  arc::LiveInput in(arc::load_bindings(kDefaultBindings));
  arc::InputState s;
  s.keys[size_t(arc::key_code("F"))] = true;  // full at once
  in.sample(s);
  EXPECT_EQ(in.take_frame().throttle, 127);
  s.keys[size_t(arc::key_code("F"))] = false;
  s.keys[size_t(arc::key_code("S"))] = true;
  in.sample(s);
  int8_t t = 127;
  for (int i = 0; i < 240; ++i) t = in.take_frame().throttle;
  EXPECT_EQ(t, 0);  // four seconds of S: down to zero, not into reverse
  s.keys[size_t(arc::key_code("S"))] = false;
  in.sample(s);
  in.take_frame();
  s.keys[size_t(arc::key_code("S"))] = true;
  in.sample(s);
  for (int i = 0; i < 30; ++i) t = in.take_frame().throttle;
  EXPECT_EQ(t, arc::quantise_axis(-0.3));  // pressed again: reverse
  s.keys[size_t(arc::key_code("S"))] = false;
  s.keys[size_t(arc::key_code("X"))] = true;
  in.sample(s);
  EXPECT_EQ(in.take_frame().throttle, 0);
}

// The set throttle flies the Viper at that share of its top speed, and keeps it there.
TEST(Throttle, ShipHoldsTheSetSpeedAfterTheKeyIsReleased) {
  LiveFlight live(arc::load_bindings(kDefaultBindings));
  live.devices.keys[size_t(arc::key_code("W"))] = true;
  for (int i = 0; i < 50; ++i) live.frame(1.0 / 60, [](const glm::dquat&) {});
  live.devices.keys[size_t(arc::key_code("W"))] = false;
  for (int i = 0; i < 600; ++i) live.frame(1.0 / 60, [](const glm::dquat&) {});
  const double speed = std::sqrt(glm::dot(live.me().velocity, live.me().velocity));
  EXPECT_NEAR(speed, arc::axis_value(live.me().controls.throttle) * live.me().cls->max_speed, 1e-6);
  EXPECT_GT(speed, 0.45 * live.me().cls->max_speed);
}
