// Bindings files to Bindings, and LiveInput: devices to quantised InputFrames, commands and
// app actions (the mouse-flight modes and the set throttle are described in the header).
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
  if (items.size() != 2) v->fail("'" + v->name() + "' must be [negative key, positive key]");
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

// Quantises base + mouse + what earlier ticks still owe, and keeps what this tick could not
// give: the rounding, so small per-tick mouse shares add up to the motion that was made, and a
// flick's excess over the full turn rate, so the ship turns as far as the mouse went, as fast as
// it can. Motion back takes from what is owed first. At most `limit` is owed (a half turn).
int8_t quantise_carrying(double base, double mouse, double& carry, double limit) {
  constexpr double kRounding = 0.6 / 127.0;  // a rounding error, not a backlog to turn
  if (mouse == 0.0 && std::fabs(carry) <= kRounding) {
    carry = 0.0;
    return quantise_axis(base);
  }
  const double wanted = std::clamp(base, -1.0, 1.0) + mouse + carry;
  const int8_t q = quantise_axis(wanted);
  carry = std::clamp(wanted - axis_value(q), -limit, limit);
  return q;
}

}  // namespace

// One line per bound action, in the file's order.
static Bindings bindings_from(const std::shared_ptr<const JsonDoc>& doc) {
  JsonObject root = JsonValue(doc, "", &doc->root()).object();
  Bindings b;
  if (auto kv = root.get("keyboard")) {
    JsonObject k = kv->object();
    b.pitch = axis(k, "pitch");
    b.yaw = axis(k, "yaw");
    b.roll = axis(k, "roll");
    b.throttle = axis(k, "throttle");
    b.throttle_zero = key(k, "throttle_zero");
    b.throttle_full = key(k, "throttle_full");
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
    b.camera_padlock = key(k, "camera_padlock");
    b.countermeasure = key(k, "countermeasure");
    b.order_attack = key(k, "order_attack");
    b.order_cover = key(k, "order_cover");
    b.order_form_up = key(k, "order_form_up");
    b.order_engage = key(k, "order_engage");
    b.target_subsystem = key(k, "target_subsystem");
    b.comms = key(k, "comms");
    b.pause = key(k, "pause");
    b.screenshot = key(k, "screenshot");
    b.fps = key(k, "fps");
    k.finish();
  }
  if (auto mv = root.get("mouse")) {
    JsonObject m = mv->object();
    b.mouse_enabled = m.boolean("enabled", true);
    b.mouse_mode = m.choice("mode", "relative", {"relative", "joystick"}) == "joystick" ? MouseMode::Joystick
                                                                                       : MouseMode::Relative;
    b.mouse_sensitivity = m.number("sensitivity", b.mouse_sensitivity, 0.001, 10.0);
    b.mouse_invert_y = m.boolean("invert_y", false);
    b.joystick_radius = m.number("joystick_radius", b.joystick_radius, 0.02, 0.5);
    b.joystick_deadzone = m.number("joystick_deadzone", b.joystick_deadzone, 0.0, 0.9);
    m.finish();
  }
  if (auto tv = root.get("throttle")) {
    JsonObject t = tv->object();
    b.throttle_rate = t.number("rate", b.throttle_rate, 0.05, 10.0);
    t.finish();
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
    b.pad_countermeasure = pad_button(g, "countermeasure");
    b.pad_pause = pad_button(g, "pause");
    b.pad_deadzone = g.number("deadzone", 0.12, 0.0, 0.9);
    b.pad_invert_y = g.boolean("invert_y", false);
    g.finish();
  }
  root.finish();
  return b;
}

Bindings load_bindings(const std::string& path) { return bindings_from(JsonDoc::load_file(path)); }

Bindings parse_bindings(const std::string& text, const std::string& path) {
  return bindings_from(JsonDoc::parse(text, path));
}

int presses_between(const InputState& before, const InputState& now, int code) {
  if (code < 0) return 0;
  if (code >= kMouseButtonBase) {
    const size_t b = size_t(code - kMouseButtonBase);
    if (b >= now.mouse_buttons.size()) return 0;
    return std::max<int>(now.mouse_presses[b], now.mouse_buttons[b] && !before.mouse_buttons[b] ? 1 : 0);
  }
  const size_t k = size_t(code);
  if (k >= now.keys.size()) return 0;
  return std::max<int>(now.key_presses[k], now.keys[k] && !before.keys[k] ? 1 : 0);
}

bool LiveInput::down(const InputState& s, int code) const {
  if (code < 0) return false;
  if (code >= kMouseButtonBase) return s.mouse_buttons[size_t(code - kMouseButtonBase) % s.mouse_buttons.size()];
  return size_t(code) < s.keys.size() && s.keys[size_t(code)];
}

void LiveInput::sample(const InputState& s) {
  prev_ = cur_;
  cur_ = s;
  if (b_.mouse_enabled && !first_sample_) {
    if (b_.mouse_mode == MouseMode::Joystick) move_joystick(s.mouse_dx, s.mouse_dy);
    else mouse_dx_ += s.mouse_dx, mouse_dy_ += s.mouse_dy;
  }
  first_sample_ = false;
  if (presses_between(prev_, s, b_.throttle_zero) > 0) reset_throttle();
  if (presses_between(prev_, s, b_.throttle_full) > 0) set_throttle_ = 1.0, throttle_held_at_zero_ = false;
  queue_commands_and_actions(s);
}

void LiveInput::queue_commands_and_actions(const InputState& s) {
  auto pad_pressed = [&](int button) {
    return button >= 0 && s.gamepad_present && s.gamepad_buttons[size_t(button)] &&
           !(prev_.gamepad_present && prev_.gamepad_buttons[size_t(button)]);
  };
  auto presses = [&](int key, int button) { return presses_between(prev_, s, key) + (pad_pressed(button) ? 1 : 0); };
  auto command = [&](int n, Command c) { commands_.insert(commands_.end(), size_t(n), c); };
  auto action = [&](int n, AppAction a) { actions_.insert(actions_.end(), size_t(n), a); };
  command(presses(b_.target_next, b_.pad_target_next), Command::TargetNext);
  command(presses(b_.target_nearest, -1), Command::TargetNearest);
  command(presses(b_.target_next_hostile, -1), Command::TargetNextHostile);
  command(presses(b_.switch_weapon, b_.pad_switch_weapon), Command::SwitchWeapon);
  command(presses(b_.countermeasure, b_.pad_countermeasure), Command::Countermeasure);
  command(presses(b_.order_attack, -1), Command::OrderAttack);
  command(presses(b_.order_cover, -1), Command::OrderCover);
  command(presses(b_.order_form_up, -1), Command::OrderFormUp);
  command(presses(b_.order_engage, -1), Command::OrderEngage);
  command(presses(b_.target_subsystem, -1), Command::TargetSubsystem);
  const bool closed_by_pause = comms_keys(s);
  action(presses(b_.camera, b_.pad_camera), AppAction::ToggleCamera);
  action(presses(b_.camera_padlock, -1), AppAction::TogglePadlock);
  if (!closed_by_pause) action(presses(b_.pause, b_.pad_pause), AppAction::TogglePause);
  action(presses(b_.screenshot, -1), AppAction::Screenshot);
  action(presses(b_.fps, -1), AppAction::ToggleFps);
}

// The comms key opens and closes the menu; while open, 1..4 issue the orders in the menu's
// order (the same commands as the order keys, so replays record them) and close it, and the
// pause key or Escape closes it without pausing.
bool LiveInput::comms_keys(const InputState& s) {
  if (presses_between(prev_, s, b_.comms) % 2 == 1) comms_open_ = !comms_open_;
  if (!comms_open_) return false;
  static const Command orders[] = {Command::OrderAttack, Command::OrderCover, Command::OrderFormUp, Command::OrderEngage};
  for (int i = 0; i < 4; ++i) {
    if (presses_between(prev_, s, key_code(std::string(1, char('1' + i)))) > 0) {
      commands_.push_back(orders[i]);
      comms_open_ = false;
      return false;
    }
  }
  if (presses_between(prev_, s, b_.pause) > 0 || presses_between(prev_, s, key_code("ESCAPE")) > 0) {
    comms_open_ = false;
    return true;
  }
  return false;
}

// The virtual cursor stays within the radius, so turning back starts at once.
void LiveInput::move_joystick(double dx, double dy) {
  const double radius = b_.joystick_radius * screen_height_;
  joystick_x_ += dx;
  joystick_y_ += dy;
  const double len = std::sqrt(joystick_x_ * joystick_x_ + joystick_y_ * joystick_y_);
  if (len > radius && len > 0) joystick_x_ *= radius / len, joystick_y_ *= radius / len;
}

// One axis of the virtual joystick: the offset in radii, with the dead zone cut out.
double LiveInput::joystick_axis(double offset) const {
  const double radius = b_.joystick_radius * screen_height_;
  return deadzone(std::clamp(offset / radius, -1.0, 1.0), b_.joystick_deadzone);
}

void LiveInput::discard_mouse_motion() {
  mouse_dx_ = mouse_dy_ = 0.0;
  pitch_carry_ = yaw_carry_ = 0.0;
  joystick_x_ = joystick_y_ = 0.0;
  first_sample_ = true;
}

MouseReticle LiveInput::reticle() const {
  if (!b_.mouse_enabled || b_.mouse_mode != MouseMode::Joystick) return {};
  return {true, joystick_x_ / screen_height_, joystick_y_ / screen_height_, b_.joystick_radius,
          b_.joystick_radius * b_.joystick_deadzone};
}

// Moves the set throttle at the bound rate; a change that would cross zero stops at zero and
// waits until the key (or stick) is let go, so slowing to a stop never backs up by accident.
void LiveInput::advance_throttle(double change) {
  if (change == 0.0) {
    throttle_held_at_zero_ = false;
    return;
  }
  if (throttle_held_at_zero_) return;
  const double next = std::clamp(set_throttle_ + change * b_.throttle_rate * scale_.tick_seconds, -1.0, 1.0);
  if ((set_throttle_ > 0.0 && next < 0.0) || (set_throttle_ < 0.0 && next > 0.0)) {
    set_throttle_ = 0.0;
    throttle_held_at_zero_ = true;
    return;
  }
  set_throttle_ = next;
}

InputFrame LiveInput::take_frame(int ticks_left) {
  const InputState& s = cur_;
  auto key_axis = [&](const KeyAxis& a) { return (down(s, a.positive) ? 1.0 : 0.0) - (down(s, a.negative) ? 1.0 : 0.0); };
  auto pad = [&](int axis_index) {
    return s.gamepad_present && axis_index >= 0 ? deadzone(s.gamepad_axes[size_t(axis_index)], b_.pad_deadzone) : 0.0;
  };
  const double pad_y = b_.pad_invert_y ? 1.0 : -1.0;
  const double mouse_y = b_.mouse_invert_y ? 1.0 : -1.0;  // screen y grows downward: up raises the nose
  double mouse_pitch = 0.0, mouse_yaw = 0.0;
  if (b_.mouse_mode == MouseMode::Joystick) {
    mouse_pitch = mouse_y * joystick_axis(joystick_y_);
    mouse_yaw = joystick_axis(joystick_x_);
  } else {
    // This tick's share of the motion, as a fraction of the ship's full turn over one tick.
    const double dx = mouse_dx_ / std::max(ticks_left, 1), dy = mouse_dy_ / std::max(ticks_left, 1);
    mouse_dx_ -= dx;
    mouse_dy_ -= dy;
    mouse_pitch = mouse_y * dy * b_.mouse_sensitivity / (scale_.pitch_rate_degrees * scale_.tick_seconds);
    mouse_yaw = dx * b_.mouse_sensitivity / (scale_.yaw_rate_degrees * scale_.tick_seconds);
  }
  // A half turn, in ticks of the full turn rate.
  const double pitch_limit = 180.0 / (scale_.pitch_rate_degrees * scale_.tick_seconds);
  const double yaw_limit = 180.0 / (scale_.yaw_rate_degrees * scale_.tick_seconds);
  InputFrame f;
  f.pitch = quantise_carrying(key_axis(b_.pitch) + pad_y * -pad(b_.pad_pitch), mouse_pitch, pitch_carry_, pitch_limit);
  f.yaw = quantise_carrying(key_axis(b_.yaw) + pad(b_.pad_yaw), mouse_yaw, yaw_carry_, yaw_limit);
  if (b_.mouse_mode == MouseMode::Joystick) pitch_carry_ = yaw_carry_ = 0.0;  // a held rate: nothing to carry
  f.roll = quantise_axis(key_axis(b_.roll) + pad(b_.pad_roll));
  advance_throttle(std::clamp(key_axis(b_.throttle) - pad(b_.pad_throttle), -1.0, 1.0));
  f.throttle = quantise_axis(set_throttle_);
  f.strafe_x = quantise_axis(key_axis(b_.strafe_x));
  f.strafe_y = quantise_axis(key_axis(b_.strafe_y));
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
