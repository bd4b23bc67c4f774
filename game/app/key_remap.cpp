// Remapping keys: the table of remappable actions, swaps on conflict, overrides for settings.json.
#include "game/app/key_remap.h"

#include "core/error.h"
#include "platform/platform.h"

namespace arc {
namespace {

// The binding field of each action, in remap_actions() order.
int* slot(Bindings& b, const std::string& id) {
  static const std::map<std::string, int Bindings::*> single = {
      {"throttle_zero", &Bindings::throttle_zero}, {"throttle_full", &Bindings::throttle_full},
      {"fire_primary", &Bindings::fire_primary},   {"fire_secondary", &Bindings::fire_secondary},
      {"afterburner", &Bindings::afterburner},     {"assist_off", &Bindings::assist_off},
      {"target_next", &Bindings::target_next},     {"target_nearest", &Bindings::target_nearest},
      {"target_next_hostile", &Bindings::target_next_hostile}, {"switch_weapon", &Bindings::switch_weapon},
      {"camera", &Bindings::camera},               {"camera_padlock", &Bindings::camera_padlock},
      {"countermeasure", &Bindings::countermeasure}, {"order_attack", &Bindings::order_attack},
      {"order_cover", &Bindings::order_cover},     {"order_form_up", &Bindings::order_form_up},
      {"order_engage", &Bindings::order_engage}, {"comms", &Bindings::comms},
      {"target_subsystem", &Bindings::target_subsystem},
      {"pause", &Bindings::pause},
      {"screenshot", &Bindings::screenshot},       {"fps", &Bindings::fps}};
  static const std::map<std::string, std::pair<KeyAxis Bindings::*, bool>> axes = {
      {"pitch_down", {&Bindings::pitch, false}},  {"pitch_up", {&Bindings::pitch, true}},
      {"yaw_left", {&Bindings::yaw, false}},      {"yaw_right", {&Bindings::yaw, true}},
      {"roll_left", {&Bindings::roll, false}},    {"roll_right", {&Bindings::roll, true}},
      {"slower", {&Bindings::throttle, false}},   {"faster", {&Bindings::throttle, true}},
      {"strafe_left", {&Bindings::strafe_x, false}}, {"strafe_right", {&Bindings::strafe_x, true}},
      {"strafe_down", {&Bindings::strafe_y, false}}, {"strafe_up", {&Bindings::strafe_y, true}}};
  static const std::map<std::string, int Bindings::*> pad = {
      {"pad_fire_primary", &Bindings::pad_fire_primary},   {"pad_fire_secondary", &Bindings::pad_fire_secondary},
      {"pad_afterburner", &Bindings::pad_afterburner},     {"pad_target_next", &Bindings::pad_target_next},
      {"pad_switch_weapon", &Bindings::pad_switch_weapon}, {"pad_camera", &Bindings::pad_camera},
      {"pad_countermeasure", &Bindings::pad_countermeasure},
      {"pad_pause", &Bindings::pad_pause}};
  if (auto s = single.find(id); s != single.end()) return &(b.*(s->second));
  if (auto p = pad.find(id); p != pad.end()) return &(b.*(p->second));
  if (auto a = axes.find(id); a != axes.end()) {
    KeyAxis& axis = b.*(a->second.first);
    return a->second.second ? &axis.positive : &axis.negative;
  }
  return nullptr;
}

bool is_pad_action(const std::string& id) { return id.rfind("pad_", 0) == 0; }
bool is_pad_code(int code) { return code >= kPadButtonBase; }

// The binding field's value in the remap code space (gamepad fields hold bare button numbers).
int code_in(const std::string& id, int field) {
  return field < 0 ? -1 : is_pad_action(id) ? field + kPadButtonBase : field;
}
int field_of(int code) { return code < 0 ? -1 : is_pad_code(code) ? code - kPadButtonBase : code; }

std::string label_of(const std::string& id) {
  for (const RemapAction& a : remap_actions())
    if (id == a.id) return a.label;
  return id;
}

}  // namespace

const std::vector<RemapAction>& remap_actions() {
  static const std::vector<RemapAction> actions = {
      {"fire_primary", "Fire beam"},        {"fire_secondary", "Fire missile"},
      {"switch_weapon", "Switch weapon"},   {"faster", "Throttle up"},
      {"slower", "Throttle down"},          {"throttle_zero", "Throttle zero"},
      {"throttle_full", "Throttle full"},   {"afterburner", "Afterburner"},
      {"assist_off", "Flight assist off"},  {"pitch_down", "Pitch: nose down"},
      {"pitch_up", "Pitch: nose up"},       {"yaw_left", "Yaw left"},
      {"yaw_right", "Yaw right"},           {"roll_left", "Roll left"},
      {"roll_right", "Roll right"},         {"strafe_left", "Strafe left"},
      {"strafe_right", "Strafe right"},     {"strafe_down", "Strafe down"},
      {"strafe_up", "Strafe up"},           {"target_next", "Target next"},
      {"target_nearest", "Target nearest"}, {"target_next_hostile", "Target next hostile"},
      {"target_subsystem", "Target subsystem"},
      {"camera", "Camera"},                 {"camera_padlock", "Padlock view"},
      {"countermeasure", "Countermeasure"}, {"order_attack", "Wing: attack my target"},
      {"order_cover", "Wing: cover me"},    {"order_form_up", "Wing: form up"},
      {"order_engage", "Wing: engage at will"}, {"comms", "Comms menu (wing orders)"},
      {"pause", "Pause menu"},
      {"screenshot", "Screenshot"},         {"fps", "FPS counter"},
      {"pad_fire_primary", "Gamepad: fire beam"},       {"pad_fire_secondary", "Gamepad: fire missile"},
      {"pad_afterburner", "Gamepad: afterburner"},      {"pad_target_next", "Gamepad: target next"},
      {"pad_switch_weapon", "Gamepad: switch weapon"},  {"pad_camera", "Gamepad: camera"},
      {"pad_countermeasure", "Gamepad: countermeasure"},
      {"pad_pause", "Gamepad: pause menu"}};
  return actions;
}

int bound_key(const Bindings& b, const std::string& action) {
  int* s = slot(const_cast<Bindings&>(b), action);
  if (!s) throw InputError("unknown action '" + action + "'");
  return code_in(action, *s);
}

std::map<std::string, std::string> key_names(const Bindings& b) {
  std::map<std::string, std::string> out;
  for (const RemapAction& a : remap_actions())
    if (!is_pad_action(a.id)) out[a.id] = key_label(bound_key(b, a.id));
  return out;
}

std::string key_label(int code) {
  if (code < 0) return "NONE";
  if (is_pad_code(code)) {
    const std::string pad = gamepad_button_name(code - kPadButtonBase);
    return pad.empty() ? "PAD_" + std::to_string(code - kPadButtonBase) : "PAD_" + pad;
  }
  const std::string name = key_name(code);
  return name.empty() ? "KEY " + std::to_string(code) : name;
}

int code_of_label(const std::string& name) {
  if (name.rfind("PAD_", 0) == 0) {
    const int b = gamepad_button_code(name.substr(4));
    return b < 0 ? -1 : kPadButtonBase + b;
  }
  return key_code(name);
}

RemapOutcome remap_key(Bindings& b, const std::string& action, int key) {
  int* mine = slot(b, action);
  if (!mine) throw InputError("unknown action '" + action + "'");
  RemapOutcome out;
  if (key >= 0 && is_pad_action(action) != is_pad_code(key)) {
    const char* takes = is_pad_action(action) ? " takes a gamepad button, not " : " takes a key or mouse button, not ";
    out.message = label_of(action) + takes + key_label(key);
    return out;
  }
  if (code_in(action, *mine) == key) return out;
  const int previous = code_in(action, *mine);
  for (const RemapAction& other : remap_actions()) {
    int* theirs = slot(b, other.id);
    if (other.id == action || code_in(other.id, *theirs) != key || key < 0) continue;
    *theirs = field_of(previous);
    out.conflict = other.id;
    out.message = key_label(key) + " was on " + other.label + ": " + other.label +
                  (previous < 0 ? " now has no key" : " now uses " + key_label(previous));
  }
  *mine = field_of(key);
  out.changed = true;
  if (out.message.empty()) out.message = label_of(action) + ": " + key_label(key);
  return out;
}

std::map<std::string, std::string> key_overrides(const Bindings& now, const Bindings& defaults) {
  std::map<std::string, std::string> out;
  for (const RemapAction& a : remap_actions())
    if (bound_key(now, a.id) != bound_key(defaults, a.id)) out[a.id] = key_label(bound_key(now, a.id));
  return out;
}

void apply_key_overrides(const std::map<std::string, std::string>& keys, Bindings& b) {
  for (const auto& [id, name] : keys)
    if (int* s = slot(b, id)) *s = field_of(name == "NONE" ? -1 : code_of_label(name));
}

}  // namespace arc
