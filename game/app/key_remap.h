// game/app/key_remap.h — remapping the keyboard and mouse bindings from the settings screen.
//
// Every remappable action has an id (as settings.json's "keys" spell it) and a label. Binding
// a key that another action already uses swaps them: the other action takes this action's
// previous key, so no action is silently left without one, and the outcome's message says
// what moved. Keyboard actions take keys and mouse buttons (key_code()); the gamepad's
// actions (ids "pad_...") take gamepad buttons, as kPadButtonBase + gamepad_button_code(), named
// PAD_A, PAD_START, ...; a key offered to a gamepad action (or the reverse) changes nothing and
// says so. No GL, no window: the rules are unit-tested.
//
// Example, compiled as AppExamples.RemapAKey in tests/unit/app/test_app_examples.cpp:
//   Bindings b = load_bindings("assets/settings/bindings.json");
//   RemapOutcome r = remap_key(b, "fire_primary", key_code("SPACE"));
//   // r.conflict == "strafe_up": strafe up now has MOUSE_LEFT
#pragma once
#include <map>
#include <string>
#include <vector>

#include "game/app/input_bindings.h"

namespace arc {

constexpr int kPadButtonBase = 2000;  // gamepad button b is kPadButtonBase + b in the remap code space

struct RemapAction {
  const char* id;
  const char* label;
};
const std::vector<RemapAction>& remap_actions();

// The key (key_code()) bound to an action, −1 for none; InputError names an unknown id.
int bound_key(const Bindings& b, const std::string& action);

struct RemapOutcome {
  bool changed = false;
  std::string conflict;  // the action that had the key ("" when none)
  std::string message;   // for the screen, e.g. "SPACE was on Strafe up: Strafe up now uses MOUSE_LEFT"
};
RemapOutcome remap_key(Bindings& b, const std::string& action, int key);

// The actions whose key differs from `defaults`, as action id → key name ("NONE" for none).
std::map<std::string, std::string> key_overrides(const Bindings& now, const Bindings& defaults);
// Applies such overrides (unknown ids and key names were rejected when the file was read).
void apply_key_overrides(const std::map<std::string, std::string>& keys, Bindings& b);

// Every keyboard action's key name (key_label), by action id: what the HUD's training prompts
// show for their {action} placeholders.
std::map<std::string, std::string> key_names(const Bindings& b);

// A key's name for the screen and settings.json ("NONE" for −1, PAD_A for a gamepad button).
std::string key_label(int code);
// The code of such a name, −1 for none or an unknown name.
int code_of_label(const std::string& name);

}  // namespace arc
