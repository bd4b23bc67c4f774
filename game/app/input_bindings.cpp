// Bindings loaded from JSON with positioned errors, and live device state turned into InputFrames.
#include "game/app/input_bindings.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.h"
#include "core/json.h"

namespace arc {
namespace {

// A device name through one of platform's lookups; an unknown name is a positioned error.
int lookup(const JsonValue& v, int (*code)(std::string_view), const char* what) {
  std::string name = v.string();
  int c = code(name);
  if (c < 0) v.fail("'" + v.name() + "': unknown " + what + " '" + name + "' (see the list at the top of the bindings file)");
  return c;
}

int key(JsonObject& o, const char* k) {
  auto v = o.get(k);
  return v ? lookup(*v, key_code, "key") : -1;
}

KeyAxis axis(JsonObject& o, const char* k) {
  auto v = o.get(k);
  if (!v) return {};
  auto items = v->array();
  if (items.size() != 2) v->fail("'" + std::string(k) + "' must be [negative key, positive key]");
  return {lookup(items[0], key_code, "key"), lookup(items[1], key_code, "key")};
}

int pad_axis(JsonObject& o, const char* k, int fallback) {
  auto v = o.get(k);
  return v ? lookup(*v, gamepad_axis_code, "gamepad axis") : fallback;
}
int pad_button(JsonObject& o, const char* k) {
  auto v = o.get(k);
  return v ? lookup(*v, gamepad_button_code, "gamepad button") : -1;
}

double deadzone(double v, double dz) {
  double a = std::fabs(v);
  if (a <= dz) return 0.0;
  return std::copysign((a - dz) / (1.0 - dz), v);
}

}  // namespace

Bindings load_bindings(const std::string& path) {
  auto doc = JsonDoc::load_file(path);
  JsonObject root = JsonValue(doc, "", &doc->root()).object();
  Bindings b;
  if (auto kv = root.get("keyboard")) {
    JsonObject k = kv->object();
    b.pitch = axis(k, "pitch");
    b.yaw = axis(k, "yaw");
    b.roll = axis(k, "roll");
    b.throttle = axis(k, "throttle");
    b.strafe_x = axis(k, "strafe_x");
    b.strafe_y = axis(k, "strafe_y");
    b.fire_primary = key(k, "fire_primary");
    b.fire_secondary = key(k, "fire_secondary");
    b.afterburner = key(k, "afterburner");
    b.assist_off = key(k, "assist_off");
    b.target_next = key(k, "target_next");
    b.target_nearest = key(k, "target_nearest");
    b.target_next_hostile = key(k, "target_next_hostile");
    b.switch_weapon = key(k, "switch_weapon");
    b.camera = key(k, "camera");
    b.pause = key(k, "pause");
    b.screenshot = key(k, "screenshot");
    b.fps = key(k, "fps");
    k.finish();
  }
  if (auto mv = root.get("mouse")) {
    JsonObject m = mv->object();
    b.mouse_enabled = m.boolean("enabled", true);
    b.mouse_sensitivity = m.number("sensitivity", 0.004, 0.0, 1.0);
    b.mouse_invert_y = m.boolean("invert_y", false);
    m.finish();
  }
  if (auto gv = root.get("gamepad")) {
    JsonObject g = gv->object();
    b.pad_pitch = pad_axis(g, "pitch", b.pad_pitch);
    b.pad_yaw = pad_axis(g, "yaw", b.pad_yaw);
    b.pad_roll = pad_axis(g, "roll", b.pad_roll);
    b.pad_throttle = pad_axis(g, "throttle", b.pad_throttle);
    b.pad_fire_primary = pad_button(g, "fire_primary");
    b.pad_fire_secondary = pad_button(g, "fire_secondary");
    b.pad_afterburner = pad_button(g, "afterburner");
    b.pad_target_next = pad_button(g, "target_next");
    b.pad_switch_weapon = pad_button(g, "switch_weapon");
    b.pad_camera = pad_button(g, "camera");
    b.pad_pause = pad_button(g, "pause");
    b.pad_deadzone = g.number("deadzone", 0.12, 0.0, 0.9);
    b.pad_invert_y = g.boolean("invert_y", false);
    g.finish();
  }
  root.finish();
  return b;
}

bool LiveInput::down(const InputState& s, int code) const {
  if (code < 0) return false;
  if (code >= kMouseButtonBase) return s.mouse_buttons[size_t(code - kMouseButtonBase) % s.mouse_buttons.size()];
  return size_t(code) < s.keys.size() && s.keys[size_t(code)];
}

bool LiveInput::pressed(const InputState& s, int code) const { return down(s, code) && !down(prev_, code); }

void LiveInput::sample(const InputState& s) {
  prev_ = cur_;
  cur_ = s;
  if (b_.mouse_enabled && !first_sample_) {
    mouse_yaw_ += -s.mouse_dx * b_.mouse_sensitivity;
    mouse_pitch_ += (b_.mouse_invert_y ? 1.0 : -1.0) * s.mouse_dy * b_.mouse_sensitivity;
  }
  first_sample_ = false;
  auto pad_pressed = [&](int button) {
    return button >= 0 && s.gamepad_present && s.gamepad_buttons[size_t(button)] &&
           !(prev_.gamepad_present && prev_.gamepad_buttons[size_t(button)]);
  };
  auto edge = [&](int key, int button) { return pressed(s, key) || pad_pressed(button); };
  if (edge(b_.target_next, b_.pad_target_next)) commands_.push_back(Command::TargetNext);
  if (edge(b_.target_nearest, -1)) commands_.push_back(Command::TargetNearest);
  if (edge(b_.target_next_hostile, -1)) commands_.push_back(Command::TargetNextHostile);
  if (edge(b_.switch_weapon, b_.pad_switch_weapon)) commands_.push_back(Command::SwitchWeapon);
  if (edge(b_.camera, b_.pad_camera)) actions_.push_back(AppAction::ToggleCamera);
  if (edge(b_.pause, b_.pad_pause)) actions_.push_back(AppAction::TogglePause);
  if (edge(b_.screenshot, -1)) actions_.push_back(AppAction::Screenshot);
  if (edge(b_.fps, -1)) actions_.push_back(AppAction::ToggleFps);
}

InputFrame LiveInput::take_frame() {
  const InputState& s = cur_;
  auto key_axis = [&](const KeyAxis& a) { return (down(s, a.positive) ? 1.0 : 0.0) - (down(s, a.negative) ? 1.0 : 0.0); };
  auto pad = [&](int axis_index) {
    return s.gamepad_present && axis_index >= 0 ? deadzone(s.gamepad_axes[size_t(axis_index)], b_.pad_deadzone) : 0.0;
  };
  double pad_y = b_.pad_invert_y ? 1.0 : -1.0;
  InputFrame f;
  // Mouse motion is consumed as a rate for this tick, so it quantises like a stick would.
  f.pitch = quantise_axis(key_axis(b_.pitch) + mouse_pitch_ + pad_y * -pad(b_.pad_pitch));
  f.yaw = quantise_axis(key_axis(b_.yaw) + mouse_yaw_ - pad(b_.pad_yaw));
  f.roll = quantise_axis(key_axis(b_.roll) - pad(b_.pad_roll));
  f.throttle = quantise_axis(key_axis(b_.throttle) - pad(b_.pad_throttle));
  f.strafe_x = quantise_axis(key_axis(b_.strafe_x));
  f.strafe_y = quantise_axis(key_axis(b_.strafe_y));
  mouse_pitch_ = mouse_yaw_ = 0.0;
  auto btn = [&](int b) { return b >= 0 && s.gamepad_present && s.gamepad_buttons[size_t(b)]; };
  if (down(s, b_.fire_primary) || btn(b_.pad_fire_primary)) f.buttons |= kFirePrimary;
  if (down(s, b_.fire_secondary) || btn(b_.pad_fire_secondary)) f.buttons |= kFireSecondary;
  if (down(s, b_.afterburner) || btn(b_.pad_afterburner)) f.buttons |= kAfterburner;
  if (down(s, b_.assist_off)) f.buttons |= kFlightAssist;
  return f;
}

std::vector<Command> LiveInput::take_commands() { return std::exchange(commands_, {}); }
std::vector<AppAction> LiveInput::take_actions() { return std::exchange(actions_, {}); }

}  // namespace arc
