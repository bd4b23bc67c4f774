// Device codes by name: the GLFW key, mouse-button and gamepad codes that InputState is indexed
// by, under the names bindings files use, so code outside platform never sees a GLFW header.
#include <GLFW/glfw3.h>

#include <utility>

#include "platform/platform.h"

namespace arc {
namespace {

using Table = std::vector<std::pair<std::string, int>>;

const Table& keys() {
  static const Table t = [] {
    Table v;
    for (char c = 'A'; c <= 'Z'; ++c) v.emplace_back(std::string(1, c), GLFW_KEY_A + (c - 'A'));
    for (char c = '0'; c <= '9'; ++c) v.emplace_back(std::string(1, c), GLFW_KEY_0 + (c - '0'));
    for (int f = 1; f <= 12; ++f) {
      std::string name = "F";
      name += std::to_string(f);
      v.emplace_back(name, GLFW_KEY_F1 + f - 1);
    }
    const Table named = {
        {"SPACE", GLFW_KEY_SPACE}, {"ESCAPE", GLFW_KEY_ESCAPE}, {"ENTER", GLFW_KEY_ENTER},
        {"TAB", GLFW_KEY_TAB}, {"BACKSPACE", GLFW_KEY_BACKSPACE}, {"UP", GLFW_KEY_UP},
        {"DOWN", GLFW_KEY_DOWN}, {"LEFT", GLFW_KEY_LEFT}, {"RIGHT", GLFW_KEY_RIGHT},
        {"LEFT_SHIFT", GLFW_KEY_LEFT_SHIFT}, {"RIGHT_SHIFT", GLFW_KEY_RIGHT_SHIFT},
        {"LEFT_CONTROL", GLFW_KEY_LEFT_CONTROL}, {"RIGHT_CONTROL", GLFW_KEY_RIGHT_CONTROL},
        {"LEFT_ALT", GLFW_KEY_LEFT_ALT}, {"RIGHT_ALT", GLFW_KEY_RIGHT_ALT}, {"HOME", GLFW_KEY_HOME},
        {"END", GLFW_KEY_END}, {"PAGE_UP", GLFW_KEY_PAGE_UP}, {"PAGE_DOWN", GLFW_KEY_PAGE_DOWN},
        {"INSERT", GLFW_KEY_INSERT}, {"DELETE", GLFW_KEY_DELETE}, {"COMMA", GLFW_KEY_COMMA},
        {"PERIOD", GLFW_KEY_PERIOD}, {"SLASH", GLFW_KEY_SLASH}, {"SEMICOLON", GLFW_KEY_SEMICOLON},
        {"MINUS", GLFW_KEY_MINUS}, {"EQUAL", GLFW_KEY_EQUAL}, {"BACKSLASH", GLFW_KEY_BACKSLASH},
        {"MOUSE_LEFT", kMouseButtonBase + GLFW_MOUSE_BUTTON_LEFT},
        {"MOUSE_RIGHT", kMouseButtonBase + GLFW_MOUSE_BUTTON_RIGHT},
        {"MOUSE_MIDDLE", kMouseButtonBase + GLFW_MOUSE_BUTTON_MIDDLE}};
    v.insert(v.end(), named.begin(), named.end());
    return v;
  }();
  return t;
}

const Table kPadAxes = {
    {"LEFT_X", GLFW_GAMEPAD_AXIS_LEFT_X},   {"LEFT_Y", GLFW_GAMEPAD_AXIS_LEFT_Y},
    {"RIGHT_X", GLFW_GAMEPAD_AXIS_RIGHT_X}, {"RIGHT_Y", GLFW_GAMEPAD_AXIS_RIGHT_Y},
    {"LEFT_TRIGGER", GLFW_GAMEPAD_AXIS_LEFT_TRIGGER}, {"RIGHT_TRIGGER", GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER}};
const Table kPadButtons = {
    {"A", GLFW_GAMEPAD_BUTTON_A}, {"B", GLFW_GAMEPAD_BUTTON_B}, {"X", GLFW_GAMEPAD_BUTTON_X},
    {"Y", GLFW_GAMEPAD_BUTTON_Y}, {"LEFT_BUMPER", GLFW_GAMEPAD_BUTTON_LEFT_BUMPER},
    {"RIGHT_BUMPER", GLFW_GAMEPAD_BUTTON_RIGHT_BUMPER}, {"BACK", GLFW_GAMEPAD_BUTTON_BACK},
    {"START", GLFW_GAMEPAD_BUTTON_START}, {"DPAD_UP", GLFW_GAMEPAD_BUTTON_DPAD_UP},
    {"DPAD_RIGHT", GLFW_GAMEPAD_BUTTON_DPAD_RIGHT}, {"DPAD_DOWN", GLFW_GAMEPAD_BUTTON_DPAD_DOWN},
    {"DPAD_LEFT", GLFW_GAMEPAD_BUTTON_DPAD_LEFT}, {"LEFT_THUMB", GLFW_GAMEPAD_BUTTON_LEFT_THUMB},
    {"RIGHT_THUMB", GLFW_GAMEPAD_BUTTON_RIGHT_THUMB}};

int find(const Table& t, std::string_view name) {
  for (const auto& [n, code] : t)
    if (n == name) return code;
  return -1;
}

std::string name_of(const Table& t, int code) {
  for (const auto& [n, c] : t)
    if (c == code) return n;
  return "";
}

}  // namespace

std::string key_name(int code) { return name_of(keys(), code); }
std::string gamepad_button_name(int code) { return name_of(kPadButtons, code); }

int key_code(std::string_view name) { return find(keys(), name); }
int gamepad_axis_code(std::string_view name) { return find(kPadAxes, name); }
int gamepad_button_code(std::string_view name) { return find(kPadButtons, name); }

}  // namespace arc
