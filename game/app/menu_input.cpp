// Devices to menu inputs: keys and D-pad by their press edges, the stick by crossing half way,
// the mouse against the drawn item boxes.
#include "game/app/menu_input.h"

#include "game/app/input_bindings.h"
#include "game/app/key_remap.h"
#include "game/render/menu_layout.h"

namespace arc {
namespace {

constexpr float kStickPush = 0.5f;  // a stick counts as a press when it crosses half way

// Every key or mouse button newly pressed, Esc left out: the key a remap waits for.
void add_binds(const InputState& before, const InputState& now, std::vector<UiInput>& out) {
  const int escape = key_code("ESCAPE");
  for (int code = 0; code < int(now.keys.size()); ++code)
    if (code != escape && presses_between(before, now, code) > 0) out.push_back(UiInput::bind(code));
  for (int b = 0; b < int(now.mouse_buttons.size()); ++b)
    if (presses_between(before, now, kMouseButtonBase + b) > 0) out.push_back(UiInput::bind(kMouseButtonBase + b));
  for (int b = 0; now.gamepad_present && b < int(now.gamepad_buttons.size()); ++b)
    if (now.gamepad_buttons[size_t(b)] && !before.gamepad_buttons[size_t(b)])
      out.push_back(UiInput::bind(kPadButtonBase + b));
}

void add_gamepad(const InputState& before, const InputState& now, std::vector<UiInput>& out) {
  if (!now.gamepad_present) return;
  auto edge = [&](const char* name) {
    const int b = gamepad_button_code(name);
    return b >= 0 && now.gamepad_buttons[size_t(b)] && !before.gamepad_buttons[size_t(b)];
  };
  const std::pair<const char*, UiKey> buttons[] = {{"DPAD_UP", UiKey::Up},       {"DPAD_DOWN", UiKey::Down},
                                                   {"DPAD_LEFT", UiKey::Left},   {"DPAD_RIGHT", UiKey::Right},
                                                   {"A", UiKey::Accept},         {"B", UiKey::Back}};
  for (const auto& [name, key] : buttons)
    if (edge(name)) out.push_back(UiInput::press(key));
  auto stick = [&](const char* axis, float sign) {
    const int a = gamepad_axis_code(axis);
    if (a < 0) return false;
    return now.gamepad_axes[size_t(a)] * sign > kStickPush && before.gamepad_axes[size_t(a)] * sign <= kStickPush;
  };
  if (stick("LEFT_Y", -1.0f)) out.push_back(UiInput::press(UiKey::Up));
  if (stick("LEFT_Y", 1.0f)) out.push_back(UiInput::press(UiKey::Down));
  if (stick("LEFT_X", -1.0f)) out.push_back(UiInput::press(UiKey::Left));
  if (stick("LEFT_X", 1.0f)) out.push_back(UiInput::press(UiKey::Right));
}

}  // namespace

std::vector<UiInput> menu_inputs(const InputState& before, const InputState& now, bool capturing,
                                 const std::vector<HudBox>& item_boxes) {
  std::vector<UiInput> out;
  auto hits = [&](const char* key) { return presses_between(before, now, key_code(key)); };
  if (capturing) {
    if (hits("ESCAPE") > 0) out.push_back(UiInput::press(UiKey::Back));
    else add_binds(before, now, out);
    return out;
  }
  const std::pair<const char*, UiKey> keys[] = {{"UP", UiKey::Up},         {"DOWN", UiKey::Down},
                                                {"LEFT", UiKey::Left},     {"RIGHT", UiKey::Right},
                                                {"ENTER", UiKey::Accept},  {"SPACE", UiKey::Accept},
                                                {"ESCAPE", UiKey::Back},   {"BACKSPACE", UiKey::Back}};
  for (const auto& [name, key] : keys)
    for (int n = hits(name); n > 0; --n) out.push_back(UiInput::press(key));
  add_gamepad(before, now, out);
  const int item = menu_item_at(item_boxes, now.mouse_x, now.mouse_y);
  const bool moved = now.mouse_x != before.mouse_x || now.mouse_y != before.mouse_y;
  if (moved && item >= 0) out.push_back(UiInput::hover(item));
  if (item >= 0 && hits("MOUSE_LEFT") > 0) out.push_back(UiInput::click(item));
  return out;
}

}  // namespace arc
