// game/app/input_bindings.h — from devices to InputFrames.
//
// Bindings come from a JSON file (assets/settings/bindings.json is the default; a user copy is
// written atomically). Each rendered frame the live loop samples the devices (InputState),
// and LiveInput turns that into the quantised InputFrames the simulation consumes on the ticks
// of that frame, plus edge-triggered game commands and app actions (screenshot, FPS counter).
//
// Mouse flight has two modes, chosen in the bindings file:
//   relative  mouse travel turns the ship: `sensitivity` degrees per pixel. The motion of a
//             frame is spread over every tick that frame simulates, and what a tick cannot give
//             (its quantisation error, and a flick's excess over the ship's full turn rate) is
//             owed to the next ticks, up to a half turn, so the ship turns as far as the mouse
//             went at any frame rate and a flick turns it as fast as it can. Motion back takes
//             from what is owed first.
//   joystick  a virtual cursor (drawn as a reticle by the HUD) moves with the mouse; its
//             offset from the screen centre sets the turn rate, full at `joystick_radius`.
// The throttle is a setting that stays where it is put: its keys change it at
// `throttle.rate` per second, two more keys set zero and full, and crossing zero stops there
// until the key is pressed again. InputFrame.throttle carries the set value every tick.
#pragma once
#include <string>
#include <vector>

#include "game/sim/input.h"
#include "platform/platform.h"

namespace arc {

struct KeyAxis { int negative = -1, positive = -1; };  // key_code()s (platform.h)

enum class MouseMode { Relative, Joystick };

struct Bindings {
  KeyAxis pitch, yaw, roll, throttle, strafe_x, strafe_y;
  int throttle_zero = -1, throttle_full = -1;
  int fire_primary = -1, fire_secondary = -1, afterburner = -1, assist_off = -1;
  int target_next = -1, target_nearest = -1, target_next_hostile = -1, switch_weapon = -1;
  int camera = -1, camera_padlock = -1, pause = -1, screenshot = -1, fps = -1;
  int countermeasure = -1, order_attack = -1, order_cover = -1, order_form_up = -1, order_engage = -1;
  int target_subsystem = -1;
  int comms = -1;  // opens the comms menu: 1..4 give the wing orders, the key again or Escape closes it
  bool mouse_enabled = true;
  MouseMode mouse_mode = MouseMode::Relative;
  double mouse_sensitivity = 0.12;  // relative mode: degrees of turn per pixel of travel
  bool mouse_invert_y = false;
  double joystick_radius = 0.25;    // joystick mode: full turn rate at this offset, in screen heights
  double joystick_deadzone = 0.06;  // joystick mode: no turn within this share of the radius
  double throttle_rate = 0.6;       // set-throttle change per second with a key held (or the stick full)
  int pad_pitch = 1, pad_yaw = 0, pad_roll = 2, pad_throttle = 3;  // gamepad_axis_code()s: LEFT_Y, LEFT_X, RIGHT_X, RIGHT_Y
  int pad_fire_primary = -1, pad_fire_secondary = -1, pad_afterburner = -1, pad_target_next = -1;
  int pad_switch_weapon = -1, pad_camera = -1, pad_pause = -1, pad_countermeasure = -1;
  double pad_deadzone = 0.12;
  bool pad_invert_y = false;
};

// Validates every key (positioned errors, exit 2 from the command line).
Bindings load_bindings(const std::string& path);
// The same from text, named `path` in messages (fuzz targets, tests).
Bindings parse_bindings(const std::string& text, const std::string& path);

// Presses of a key or mouse button (key_code()) between two samples: the press events the
// platform counted, or 1 when the code is down now and was not before (a caller that fills
// InputState by hand). Two taps within one frame are two presses.
int presses_between(const InputState& before, const InputState& now, int code);

// What turns pixels into turn rates: the flown ship's full rates and the simulation's tick.
struct FlightScale {
  double pitch_rate_degrees = 90.0, yaw_rate_degrees = 90.0;  // per second
  double tick_seconds = 1.0 / 60.0;
};

// The joystick mode's virtual cursor for the HUD, in screen heights from the centre (+y down).
struct MouseReticle {
  bool shown = false;
  double x = 0, y = 0, radius = 0, deadzone = 0;
};

enum class AppAction { Screenshot, ToggleFps, ToggleCamera, TogglePadlock, TogglePause };

class LiveInput {
 public:
  explicit LiveInput(Bindings b) : b_(std::move(b)) {}
  // A new flown ship or game: what the mouse still owed the old one is dropped.
  void set_flight_scale(const FlightScale& scale) { scale_ = scale; pitch_carry_ = yaw_carry_ = 0.0; }
  void set_screen_height(int pixels) { screen_height_ = pixels > 0 ? pixels : screen_height_; }
  // Samples one frame of device state; accumulates mouse motion and edges until consumed.
  void sample(const InputState& s);
  // The InputFrame for the next tick (live input goes through the same quantisation as
  // recordings). `ticks_left` counts this frame's ticks still to take, this one included:
  // the relative mouse motion not yet taken is shared evenly among them.
  InputFrame take_frame(int ticks_left = 1);
  // Drops mouse motion gathered so far and centres the virtual joystick (the cursor jumps
  // when capture is switched).
  void discard_mouse_motion();
  // A new game starts at zero throttle.
  void reset_throttle() { set_throttle_ = 0.0; throttle_held_at_zero_ = false; }
  double set_throttle() const { return set_throttle_; }
  MouseReticle reticle() const;
  std::vector<Command> take_commands();
  std::vector<AppAction> take_actions();
  // The comms menu (the HUD lists the four wing orders under keys 1..4 while it is open).
  bool comms_open() const { return comms_open_; }
  void close_comms() { comms_open_ = false; }

 private:
  bool down(const InputState& s, int code) const;
  void queue_commands_and_actions(const InputState& s);
  // While the comms menu is open: a number key's order, or closing it. True when the pause
  // key's presses were taken to close it.
  bool comms_keys(const InputState& s);
  void move_joystick(double dx, double dy);
  void advance_throttle(double change);
  double joystick_axis(double offset) const;

  Bindings b_;
  FlightScale scale_;
  int screen_height_ = 720;
  InputState prev_{};
  InputState cur_{};
  double mouse_dx_ = 0, mouse_dy_ = 0;          // relative mode: pixels not yet given to a tick
  double pitch_carry_ = 0, yaw_carry_ = 0;      // relative mode: turn owed to the next ticks, in axis units
  double joystick_x_ = 0, joystick_y_ = 0;      // joystick mode: cursor offset in pixels, +y down
  double set_throttle_ = 0;
  bool throttle_held_at_zero_ = false;          // crossed zero with the key held: wait for a new press
  bool first_sample_ = true;  // the cursor jumps when it is first captured: ignore that motion
  bool comms_open_ = false;
  std::vector<Command> commands_;
  std::vector<AppAction> actions_;
};

}  // namespace arc
