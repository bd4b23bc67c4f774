#include <gtest/gtest.h>

#include "core/error.h"
#include "core/file_writer.h"
#include "core/json.h"
#include "game/app/contact_sheet.h"
#include "game/app/input_bindings.h"
#include "core/data_root.h"

namespace {
const std::string kDefaultBindings = arc::data_root() + "/assets/settings/bindings.json";

std::string write_temp(const std::string& name, const std::string& text) {
  std::string p = testing::TempDir() + "/" + name;
  arc::write_file_atomic(p, text);
  return p;
}
}  // namespace

TEST(Bindings, ShippedDefaultsLoad) {
  arc::Bindings b = arc::load_bindings(kDefaultBindings);
  EXPECT_EQ(b.throttle.positive, arc::key_code("W"));
  EXPECT_EQ(b.screenshot, arc::key_code("F12"));
}

TEST(Bindings, UnknownKeyNameIsPositioned) {
  std::string p = write_temp("b1.json", "{\n  \"keyboard\": {\n    \"pitch\": [\"UP\", \"DWON\"]\n  }\n}\n");
  try {
    arc::load_bindings(p);
    FAIL() << "no error";
  } catch (const arc::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(p + ":3:", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("unknown key 'DWON'"), std::string::npos) << e.what();
  }
}

TEST(Bindings, UnknownActionIsRejected) {
  std::string p = write_temp("b2.json", "{\"keyboard\": {\"jump\": \"J\"}}");
  EXPECT_THROW(arc::load_bindings(p), arc::InputError);
}

TEST(Bindings, MouseModeAndThrottleRateAreValidated) {
  std::string p = write_temp("b3.json", "{\n  \"mouse\": { \"mode\": \"trackball\" }\n}\n");
  try {
    arc::load_bindings(p);
    FAIL() << "no error";
  } catch (const arc::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(p + ":2:", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("joystick"), std::string::npos) << e.what();
  }
  EXPECT_THROW(arc::load_bindings(write_temp("b4.json", "{\"throttle\": {\"rate\": 0}}")), arc::InputError);
  EXPECT_THROW(arc::load_bindings(write_temp("b5.json", "{\"mouse\": {\"sensitivity\": -1}}")), arc::InputError);
  arc::Bindings b = arc::load_bindings(
      write_temp("b6.json", "{\"mouse\": {\"mode\": \"joystick\", \"invert_y\": true}, \"throttle\": {\"rate\": 2}}"));
  EXPECT_EQ(b.mouse_mode, arc::MouseMode::Joystick);
  EXPECT_TRUE(b.mouse_invert_y);
  EXPECT_EQ(b.throttle_rate, 2.0);
}

TEST(LiveInput, KeysBecomeFullAxesAndButtons) {
  arc::LiveInput in(arc::load_bindings(kDefaultBindings));
  arc::InputState s;
  s.keys[size_t(arc::key_code("F"))] = true;
  s.keys[size_t(arc::key_code("Q"))] = true;
  s.keys[size_t(arc::key_code("RIGHT"))] = true;
  s.mouse_buttons[0] = true;
  in.sample(s);
  arc::InputFrame f = in.take_frame();
  EXPECT_EQ(f.throttle, 127);
  EXPECT_EQ(f.roll, -127);
  EXPECT_EQ(f.yaw, 127);  // right arrow: nose right
  EXPECT_EQ(f.pitch, 0);
  EXPECT_TRUE(f.buttons & arc::kFirePrimary);
}

TEST(LiveInput, MouseMotionIsSharedAmongTheFramesTicksAndQuantised) {
  arc::LiveInput in(arc::load_bindings(kDefaultBindings));
  arc::FlightScale scale;  // 90 degrees per second at 60 Hz: 1.5 degrees per tick at full rate
  in.set_flight_scale(scale);
  arc::InputState s;
  s.mouse_dx = 500;  // the first sample's motion is the capture jump: ignored
  in.sample(s);
  EXPECT_EQ(in.take_frame().yaw, 0);
  s.mouse_dx = 30;  // 30 px · 0.12 degrees = 3.6 degrees over three ticks: 0.8 of full rate each
  in.sample(s);
  int total = 0;
  for (int left = 3; left >= 1; --left) {
    const int yaw = in.take_frame(left).yaw;
    EXPECT_NEAR(yaw, 0.8 * 127, 1.0) << left;
    total += yaw;
  }
  EXPECT_NEAR(total, 3 * 0.8 * 127, 0.5);
  EXPECT_EQ(in.take_frame().yaw, 0);
}

TEST(LiveInput, QuantisationErrorIsCarriedToTheNextTick) {
  arc::LiveInput in(arc::load_bindings(kDefaultBindings));
  in.set_flight_scale(arc::FlightScale{});
  arc::InputState s;
  in.sample(s);
  int total = 0;
  for (int frame = 0; frame < 100; ++frame) {
    s.mouse_dx = 0.1;  // 0.008 of full rate a tick: about one quantum, never a whole one
    in.sample(s);
    total += in.take_frame().yaw;
  }
  EXPECT_NEAR(total, 100 * 0.008 * 127, 1.0);
}

TEST(LiveInput, TwoTapsWithinOneFrameAreTwoPresses) {
  arc::LiveInput in(arc::load_bindings(kDefaultBindings));
  arc::InputState s;
  s.key_presses[size_t(arc::key_code("T"))] = 2;  // pressed, released, pressed before the poll
  s.keys[size_t(arc::key_code("T"))] = true;
  in.sample(s);
  EXPECT_EQ(in.take_commands(), (std::vector<arc::Command>{arc::Command::TargetNext, arc::Command::TargetNext}));
  s.key_presses.fill(0);  // held into the next frame: no press
  in.sample(s);
  EXPECT_TRUE(in.take_commands().empty());
  s.key_presses[size_t(arc::key_code("T"))] = 1;  // released and pressed again within the frame
  in.sample(s);
  EXPECT_EQ(in.take_commands().size(), 1u);
}

TEST(LiveInput, PressesBetweenCountsEventsOrAnEdge) {
  arc::InputState before, now;
  const int esc = arc::key_code("ESCAPE");
  now.keys[size_t(esc)] = true;
  EXPECT_EQ(arc::presses_between(before, now, esc), 1);  // filled by hand: the edge counts
  now.key_presses[size_t(esc)] = 3;
  EXPECT_EQ(arc::presses_between(before, now, esc), 3);
  now.mouse_presses[1] = 2;
  EXPECT_EQ(arc::presses_between(before, now, arc::key_code("MOUSE_RIGHT")), 2);
  EXPECT_EQ(arc::presses_between(before, now, -1), 0);
}

TEST(LiveInput, CommandsAreEdgeTriggered) {
  arc::LiveInput in(arc::load_bindings(kDefaultBindings));
  arc::InputState s;
  s.keys[size_t(arc::key_code("T"))] = true;
  in.sample(s);
  in.sample(s);  // still held: no second command
  auto c = in.take_commands();
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0], arc::Command::TargetNext);
}

TEST(Quantisation, RoundTripIsStableAndClamped) {
  for (int q = -127; q <= 127; ++q) EXPECT_EQ(arc::quantise_axis(arc::axis_value(int8_t(q))), q);
  EXPECT_EQ(arc::quantise_axis(5.0), 127);
  EXPECT_EQ(arc::quantise_axis(-5.0), -127);
  EXPECT_EQ(arc::quantise_axis(std::nan("")), 0);
}

TEST(ContactSheet, GridAndBoxFilter) {
  std::vector<arc::Image> frames(3);
  for (int i = 0; i < 3; ++i) {
    frames[i].width = 8;
    frames[i].height = 4;
    frames[i].rgba.assign(8 * 4 * 4, uint8_t(i * 100));
  }
  arc::Image sheet = arc::make_contact_sheet(frames, 2, 4);
  EXPECT_EQ(sheet.width, 4 + 2 * (4 + 4));
  EXPECT_EQ(sheet.height, 4 + 2 * (2 + 4));
  // Third frame (value 200) sits in row 1, column 0.
  size_t px = (size_t(4 + 6 + 1) * sheet.width + 4 + 1) * 4;
  EXPECT_EQ(sheet.rgba[px], 200);
}
