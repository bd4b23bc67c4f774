#include <gtest/gtest.h>

#include "core/error.h"
#include "core/json.h"
#include "game/app/contact_sheet.h"
#include "game/app/input_bindings.h"

namespace {
const std::string kDefaultBindings = std::string(ARCFIRE_SOURCE_DIR) + "/assets/settings/bindings.json";

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

TEST(LiveInput, KeysBecomeFullAxesAndButtons) {
  arc::LiveInput in(arc::load_bindings(kDefaultBindings));
  arc::InputState s;
  s.keys[size_t(arc::key_code("W"))] = true;
  s.keys[size_t(arc::key_code("Q"))] = true;
  s.mouse_buttons[0] = true;
  in.sample(s);
  arc::InputFrame f = in.take_frame();
  EXPECT_EQ(f.throttle, 127);
  EXPECT_EQ(f.roll, -127);
  EXPECT_EQ(f.pitch, 0);
  EXPECT_TRUE(f.buttons & arc::kFirePrimary);
}

TEST(LiveInput, MouseMotionIsConsumedOncePerTickAndQuantised) {
  arc::LiveInput in(arc::load_bindings(kDefaultBindings));
  arc::InputState s;
  s.mouse_dx = 500;  // the first sample's motion is the capture jump: ignored
  in.sample(s);
  EXPECT_EQ(in.take_frame().yaw, 0);
  s.mouse_dx = 100;  // 100 px · 0.004 = 0.4 of full yaw rate, to the left
  in.sample(s);
  arc::InputFrame f = in.take_frame();
  EXPECT_EQ(f.yaw, arc::quantise_axis(-0.4));
  EXPECT_EQ(in.take_frame().yaw, 0);
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
