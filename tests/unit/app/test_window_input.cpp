// The GLFW window's key and mouse-button callbacks under a real X server: two taps that
// arrive between two polls are two presses. Runs only when ARCFIRE_WINDOW_TESTS=1 (ctest's app_window_input
// sets it and starts the suite under xvfb-run), because it sends X key events with xdotool
// to whatever display it finds.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "platform/platform.h"

namespace {

bool window_tests_enabled() {
  const char* on = std::getenv("ARCFIRE_WINDOW_TESTS");
  return on && std::string(on) == "1";
}

void settle(arc::Window& window, arc::InputState& input) {
  for (int i = 0; i < 10; ++i) {
    window.poll(input);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  window.poll(input);
}

}  // namespace

TEST(WindowInput, TwoTapsBetweenPollsAreTwoPresses) {
  if (!window_tests_enabled()) GTEST_SKIP() << "set ARCFIRE_WINDOW_TESTS=1 under xvfb-run (ctest app_window_input)";
  ASSERT_TRUE(arc::display_available());
  arc::WindowDesc desc;
  desc.width = 320;
  desc.height = 200;
  desc.title = "ArcfireKeyTaps";
  auto window = arc::open_window(desc);
  arc::InputState input;
  settle(*window, input);
  ASSERT_EQ(std::system("xdotool search --sync --onlyvisible --name ArcfireKeyTaps windowfocus --sync"), 0);
  settle(*window, input);
  // Both taps reach the X server before the next poll: one frame's worth of events.
  ASSERT_EQ(std::system("xdotool key --delay 1 t t"), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  window->poll(input);
  EXPECT_EQ(input.key_presses[size_t(arc::key_code("T"))], 2);
  window->poll(input);
  EXPECT_EQ(input.key_presses[size_t(arc::key_code("T"))], 0);  // counted once, then reset
  ASSERT_EQ(std::system("xdotool search --onlyvisible --name ArcfireKeyTaps mousemove --sync --window %1 60 60"), 0);
  settle(*window, input);
  ASSERT_EQ(std::system("xdotool click --delay 1 --repeat 3 1"), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  window->poll(input);
  EXPECT_EQ(input.mouse_presses[0], 3);
}
