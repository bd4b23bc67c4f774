// game/app/input_bindings.h — from devices to InputFrames.
//
// Bindings come from a JSON file (assets/settings/bindings.json is the default; a user copy is
// written atomically). Each rendered frame the live loop samples the devices (InputState),
// and LiveInput turns that into the quantised InputFrame the simulation consumes on the next
// tick, plus edge-triggered game commands and app actions (screenshot, FPS counter).
#pragma once
#include <string>
#include <vector>

#include "game/sim/input.h"
#include "platform/platform.h"

namespace arc {

struct KeyAxis { int negative = -1, positive = -1; };  // key_code()s (platform.h)

struct Bindings {
  KeyAxis pitch, yaw, roll, throttle, strafe_x, strafe_y;
  int fire_primary = -1, fire_secondary = -1, afterburner = -1, assist_off = -1;
  int target_next = -1, target_nearest = -1, target_next_hostile = -1, switch_weapon = -1;
  int camera = -1, pause = -1, screenshot = -1, fps = -1;
  bool mouse_enabled = true;
  double mouse_sensitivity = 0.004;
  bool mouse_invert_y = false;
  int pad_pitch = 1, pad_yaw = 0, pad_roll = 2, pad_throttle = 3;  // gamepad_axis_code()s: LEFT_Y, LEFT_X, RIGHT_X, RIGHT_Y
  int pad_fire_primary = -1, pad_fire_secondary = -1, pad_afterburner = -1, pad_target_next = -1;
  int pad_switch_weapon = -1, pad_camera = -1, pad_pause = -1;
  double pad_deadzone = 0.12;
  bool pad_invert_y = false;
};

// Validates every key (positioned errors, exit 2 from the command line).
Bindings load_bindings(const std::string& path);

enum class AppAction { Screenshot, ToggleFps, ToggleCamera, TogglePause };

class LiveInput {
 public:
  explicit LiveInput(Bindings b) : b_(std::move(b)) {}
  // Samples one frame of device state; accumulates mouse motion and edges until consumed.
  void sample(const InputState& s);
  // The InputFrame for the next tick (live input goes through the same quantisation as
  // recordings), and the commands that fired since the last call.
  InputFrame take_frame();
  // Drops mouse motion gathered so far (the cursor jumps when capture is switched).
  void discard_mouse_motion() { mouse_pitch_ = mouse_yaw_ = 0.0; first_sample_ = true; }
  std::vector<Command> take_commands();
  std::vector<AppAction> take_actions();

 private:
  bool down(const InputState& s, int code) const;
  bool pressed(const InputState& s, int code) const;  // went down this frame
  Bindings b_;
  InputState prev_{};
  InputState cur_{};
  double mouse_pitch_ = 0, mouse_yaw_ = 0;
  bool first_sample_ = true;  // the cursor jumps when it is first captured: ignore that motion
  std::vector<Command> commands_;
  std::vector<AppAction> actions_;
};

}  // namespace arc
