#include <cmath>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "game/sim/flight.h"

namespace arc {
namespace {

ShipClassDef test_class() {
  ShipClassDef c;
  c.mass = 10000;
  c.thrust = 500000;  // 50 m/s²
  c.strafe_thrust = 200000;
  c.max_speed = 100;
  c.afterburner_speed = 1.5;
  return c;
}

Ship ship_of(const ShipClassDef& c) {
  Ship s;
  s.cls = &c;
  return s;
}

constexpr double kDt = 1.0 / 60.0;

TEST(Flight, FullThrottleAcceleratesForwardAtEngineLimit) {
  ShipClassDef c = test_class();
  Ship s = ship_of(c);
  s.controls.throttle = 127;
  integrate_flight(s, kDt);
  EXPECT_NEAR(s.velocity.z, -50.0 * kDt, 1e-12);  // forward is −Z
  EXPECT_NEAR(s.velocity.x, 0.0, 1e-12);
  EXPECT_LT(s.position.z, 0.0);
}

TEST(Flight, AssistHoldsCommandedSpeedAndNeverExceedsIt) {
  ShipClassDef c = test_class();
  Ship s = ship_of(c);
  s.controls.throttle = 127;
  double top = 0;
  for (int i = 0; i < 600; ++i) {
    integrate_flight(s, kDt);
    top = std::max(top, glm::length(s.velocity));
  }
  EXPECT_NEAR(glm::length(s.velocity), c.max_speed, 1e-9);
  EXPECT_LE(top, c.max_speed + 1e-9);
}

TEST(Flight, AssistKillsSidewaysDriftWithZeroThrottle) {
  ShipClassDef c = test_class();
  Ship s = ship_of(c);
  s.velocity = {40.0, 0.0, 0.0};
  for (int i = 0; i < 30; ++i) integrate_flight(s, kDt);  // 0.5 s at 50 m/s² removes 25 m/s
  EXPECT_NEAR(s.velocity.x, 15.0, 1e-9);
  for (int i = 0; i < 30; ++i) integrate_flight(s, kDt);
  EXPECT_NEAR(glm::length(s.velocity), 0.0, 1e-9);
}

TEST(Flight, WithoutAssistMotionIsNewtonian) {
  ShipClassDef c = test_class();
  Ship s = ship_of(c);
  s.velocity = {40.0, 0.0, -10.0};
  s.controls.buttons = kFlightAssist;  // held: assist off
  for (int i = 0; i < 60; ++i) integrate_flight(s, kDt);
  EXPECT_DOUBLE_EQ(s.velocity.x, 40.0);
  EXPECT_DOUBLE_EQ(s.velocity.z, -10.0);
  EXPECT_NEAR(s.position.x, 40.0, 1e-9);
}

TEST(Flight, HardSpeedLimitIsMaxSpeedTimesAfterburner) {
  ShipClassDef c = test_class();
  Ship s = ship_of(c);
  s.controls.throttle = 127;
  s.controls.buttons = kFlightAssist;
  for (int i = 0; i < 1200; ++i) integrate_flight(s, kDt);
  EXPECT_NEAR(glm::length(s.velocity), c.max_speed * c.afterburner_speed, 1e-9);
}

TEST(Flight, AfterburnerRaisesAssistedSpeed) {
  ShipClassDef c = test_class();
  Ship s = ship_of(c);
  s.controls.throttle = 127;
  s.afterburner_on = true;
  for (int i = 0; i < 1200; ++i) integrate_flight(s, kDt);
  EXPECT_NEAR(glm::length(s.velocity), c.max_speed * c.afterburner_speed, 1e-9);
}

// The afterburner is full boost forward whatever the set throttle: from a standstill at zero
// (or reverse) throttle it reaches the boosted speed, assisted or not.
TEST(Flight, AfterburnerBoostsFromZeroAndReverseThrottle) {
  ShipClassDef c = test_class();
  for (int8_t throttle : {int8_t(0), int8_t(-127), int8_t(40)}) {
    for (uint16_t buttons : {uint16_t(0), uint16_t(kFlightAssist)}) {
      Ship s = ship_of(c);
      s.controls.throttle = throttle;
      s.controls.buttons = buttons;
      s.afterburner_on = true;
      for (int i = 0; i < 120; ++i) integrate_flight(s, kDt);
      EXPECT_GT(-s.velocity.z, 0.8 * c.max_speed * c.afterburner_speed) << int(throttle) << " " << buttons;
    }
  }
}

TEST(Flight, AfterburnerOffReturnsToTheSetThrottle) {
  ShipClassDef c = test_class();
  Ship s = ship_of(c);
  s.afterburner_on = true;
  for (int i = 0; i < 240; ++i) integrate_flight(s, kDt);
  EXPECT_NEAR(glm::length(s.velocity), c.max_speed * c.afterburner_speed, 1e-9);
  s.afterburner_on = false;
  for (int i = 0; i < 240; ++i) integrate_flight(s, kDt);
  EXPECT_NEAR(glm::length(s.velocity), 0.0, 1e-9);
}

TEST(Flight, StickAxesTurnTheNoseTheExpectedWay) {
  ShipClassDef c = test_class();
  Ship yaw = ship_of(c), pitch = ship_of(c);
  yaw.controls.yaw = 127;
  pitch.controls.pitch = 127;
  for (int i = 0; i < 20; ++i) integrate_flight(yaw, kDt), integrate_flight(pitch, kDt);
  EXPECT_GT(forward_of(yaw.orientation).x, 0.1);    // positive yaw turns right
  EXPECT_GT(forward_of(pitch.orientation).y, 0.1);  // positive pitch raises the nose
  EXPECT_NEAR(glm::length(yaw.orientation), 1.0, 1e-12);
}

TEST(Flight, TurnRateFollowsStickExponentiallyUpToTheClassRate) {
  ShipClassDef c = test_class();
  Ship s = ship_of(c);
  s.controls.yaw = 127;
  integrate_flight(s, kDt);
  const double target = -c.turn_rate[1] * 3.14159265358979323846 / 180.0;
  EXPECT_NEAR(s.angular_velocity.y, target * (1.0 - std::exp(-c.turn_response * kDt)), 1e-12);
  for (int i = 0; i < 600; ++i) integrate_flight(s, kDt);
  EXPECT_NEAR(s.angular_velocity.y, target, 1e-9);
}

}  // namespace
}  // namespace arc
