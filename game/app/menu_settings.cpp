// The menu's settings screen and its pages: Graphics, Sound, Controls with key remapping,
// Advanced (the raw settings), and the rule that a value changes only by Left/Right or a
// confirmed Enter.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gfx/device_class.h"
#include "game/app/key_remap.h"
#include "game/app/menu_items.h"

namespace arc {
namespace {

constexpr int kListRows = 13;  // rows of the key and raw-setting lists on screen at once

std::string number_text(const char* format, double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string on_off(bool v) { return v ? "on" : "off"; }
std::string toggle_text(bool v) { return std::string("< ") + on_off(v) + " >"; }

double stepped(double v, int step, double by, double lo, double hi) {
  return std::clamp(std::round((v + step * by) / by) * by, lo, hi);
}

const SettingDef* setting_def(const Settings& s, const std::string& key) {
  for (const SettingDef& d : s.all())
    if (d.key == key) return &d;
  return nullptr;
}

// Mesa's llvmpipe and softpipe, Google's SwiftShader, Microsoft's WARP-backed GDI driver.
bool software_rasteriser(const std::string& gl_renderer) { return is_software_rasteriser(gl_renderer); }

// What a preset costs, as a class: the built-in settings ("default") are made for a software
// rasteriser, where the look's presets (medium, high) take several times its frame time; they
// are meant for a GPU. Rated for this machine when the renderer's name is known.
struct PresetCost { const char *name, *software, *gpu, *what; };
constexpr PresetCost kPresetCosts[] = {
    {"low", "light", "light", "plain, half resolution"},
    {kDefaultQuality, "light", "light", "made for a software rasteriser"},
    {"medium", "heavy", "moderate", "the full look, for a GPU"},
    {"high", "too heavy", "heavy", "the full look at 1.25x resolution, for a GPU"},
    {"reference", "far too heavy", "very heavy", "reference images, not for play"},
};

const PresetCost* preset_cost(const std::string& preset) {
  for (const PresetCost& c : kPresetCosts)
    if (preset == c.name) return &c;
  return nullptr;
}

// "heavy here", or the class on either kind of machine when this one is not known.
std::string cost_label(const std::string& preset, const std::string& machine) {
  const PresetCost* c = preset_cost(preset);
  if (!c) return "not rated";
  if (!machine.empty()) return std::string(software_rasteriser(machine) ? c->software : c->gpu) + " here";
  if (std::string(c->software) == c->gpu) return std::string(c->software) + " anywhere";
  return std::string(c->software) + " on software, " + c->gpu + " on a GPU";
}

// "Music volume: < 100 % >" for a group's audio.*_volume setting.
std::string group_volume_label(const char* group, const char* key, const Settings& s) {
  return number_text((std::string(group) + " volume: < %.0f %% >").c_str(), s.number(key) * 100);
}

// The renderer's name without its details: "llvmpipe (LLVM 15.0.7, 256 bits)" → "llvmpipe".
std::string machine_name(const std::string& gl_renderer) { return gl_renderer.substr(0, gl_renderer.find(" (")); }

}  // namespace

std::vector<Menu::Item> Menu::settings_items() const {
  switch (screen_) {
    case MenuScreen::Settings:
      return {Item::Graphics, Item::Sound, Item::Controls, Item::Advanced, Item::ResetProgress, Item::Back};
    case MenuScreen::Graphics: return {Item::Quality, Item::Scale, Item::Fullscreen, Item::Vsync, Item::Fov, Item::Back};
    case MenuScreen::Sound:
      return {Item::MasterVolume, Item::EffectsVolume, Item::Mute,     Item::MusicVolume, Item::WeaponsVolume,
              Item::ImpactsVolume, Item::EnginesVolume, Item::UiVolume, Item::VoiceVolume, Item::Subtitles, Item::Back};
    case MenuScreen::Controls: return {Item::Sensitivity, Item::InvertY, Item::Deadzone, Item::RemapKeys, Item::Back};
    case MenuScreen::Keys: {
      std::vector<Item> v(remap_actions().size(), Item::Action);
      v.push_back(Item::ResetKeys);
      v.push_back(Item::Back);
      return v;
    }
    case MenuScreen::Advanced: {
      std::vector<Item> v{Item::DevPanel};
      v.insert(v.end(), effective_.all().size(), Item::RenderKey);
      v.push_back(Item::ResetRender);
      v.push_back(Item::Back);
      return v;
    }
    default: return {};
  }
}

std::string Menu::settings_label(Item item, int index) const {
  const UserSettings& s = files_.settings;
  const std::string asks = confirm_ == index ? "  (Enter again)" : "";
  switch (item) {
    case Item::Graphics: return "Graphics";
    case Item::Sound: return "Sound";
    case Item::Controls: return "Controls";
    case Item::Advanced:
      return "Advanced: raw settings (" + std::to_string(s.render.size()) + " of yours over the preset)";
    case Item::ResetProgress: return confirm_ == index ? "Reset progress: press again to confirm" : "Reset progress";
    case Item::Quality: return "Quality preset: < " + s.quality + " >  " + cost_label(s.quality, machine_) + asks;
    case Item::Scale: return number_text("Resolution scale: < %.2f >", effective_.number("render.scale")) + asks;
    case Item::Fullscreen: return "Fullscreen: " + toggle_text(s.fullscreen) + asks;
    case Item::Vsync: return "VSync: " + toggle_text(s.vsync) + asks;
    case Item::Fov: return number_text("Field of view: < %.0f > deg", s.fov) + asks;
    case Item::MasterVolume:
      return number_text("Master volume: < %.0f %% >", effective_.number("audio.volume") * 100) + asks;
    case Item::EffectsVolume:
      return number_text("Effects volume: < %.0f %% >", effective_.number("audio.effects_volume") * 100) + asks;
    case Item::Mute: return "Mute (M in the game): " + toggle_text(effective_.flag("audio.mute")) + asks;
    case Item::MusicVolume: return group_volume_label("Music", "audio.music_volume", effective_) + asks;
    case Item::WeaponsVolume: return group_volume_label("Weapons", "audio.weapons_volume", effective_) + asks;
    case Item::ImpactsVolume: return group_volume_label("Hits and explosions", "audio.impacts_volume", effective_) + asks;
    case Item::EnginesVolume: return group_volume_label("Engines", "audio.engines_volume", effective_) + asks;
    case Item::UiVolume: return group_volume_label("Interface and warnings", "audio.ui_volume", effective_) + asks;
    case Item::VoiceVolume: return group_volume_label("Radio voices", "audio.voice_volume", effective_) + asks;
    case Item::Subtitles: return "Radio subtitles: " + toggle_text(effective_.flag("audio.subtitles")) + asks;
    case Item::Sensitivity: return number_text("Mouse sensitivity: < %.2f > deg/px", s.mouse_sensitivity) + asks;
    case Item::InvertY: return "Invert Y: " + toggle_text(s.invert_y) + asks;
    case Item::Deadzone: return number_text("Gamepad dead zone: < %.2f >", s.pad_deadzone) + asks;
    case Item::RemapKeys: return "Remap keys";
    case Item::Action: {
      const RemapAction& a = remap_actions()[size_t(index)];
      std::string label = a.label;
      label.resize(24, ' ');
      const bool waiting = capturing_ && index == selection_;
      return label + (waiting ? "press a key..." : key_label(bound_key(bindings_, a.id)));
    }
    case Item::ResetKeys: return "Reset keys to defaults";
    case Item::DevPanel: return "Developer panel (F1): " + toggle_text(s.developer_panel) + asks;
    case Item::RenderKey: {
      const SettingDef& d = effective_.all()[size_t(index - 1)];
      std::string label = d.key;
      label.resize(std::max<size_t>(label.size() + 1, 30), ' ');
      return label + "< " + d.value + " >" + (s.render.count(d.key) ? "  *" : "") + asks;
    }
    case Item::ResetRender: return "Back to the preset's values";
    default: return "";
  }
}

void Menu::fill_settings_page(MenuPage& p) const {
  const std::string values = "Left/Right: change   Enter: open, or asks before a change   Esc: back (saved as you go)";
  auto scrolled = [&] {
    p.first = std::clamp(selection_ - kListRows / 2, 0, std::max(0, int(p.items.size()) - kListRows));
    p.rows = kListRows;
  };
  switch (screen_) {
    case MenuScreen::Settings: p.title = "SETTINGS"; break;
    case MenuScreen::Graphics:
      p.title = "GRAPHICS";
      p.subtitle = machine_.empty()                  ? "presets rated for a software rasteriser and a GPU"
                   : software_rasteriser(machine_) ? "this machine: " + machine_name(machine_) + ", a software rasteriser"
                                                   : "this machine: " + machine_name(machine_) + ", a GPU";
      p.hint = values;
      if (!device_why_.empty() && files_.settings.quality == device_preset_) p.subtitle += "; " + device_why_;
      if (selection_ == 0 && confirm_ != 0 && p.message.empty()) p.message = quality_note();
      break;
    case MenuScreen::Sound: p.title = "SOUND"; p.hint = values; break;
    case MenuScreen::Controls: p.title = "CONTROLS"; p.hint = values; break;
    case MenuScreen::Keys:
      p.title = "REMAP KEYS";
      p.hint = capturing_ ? "press the new key or mouse button   Esc: cancel" : "Enter: remap   Esc: back";
      scrolled();
      break;
    case MenuScreen::Advanced:
      p.title = "ADVANCED";
      p.subtitle = "raw settings for developers (preset " + files_.settings.quality + "; * marks yours)";
      p.hint = values;
      scrolled();
      if (selection_ == 0 && confirm_ != 0 && p.message.empty())
        p.message = "the F1 tweak panel in the game (always there with --dev); it pauses the game while open";
      if (selection_ >= 1 && selection_ <= int(effective_.all().size()) && confirm_ != selection_)
        p.message = effective_.all()[size_t(selection_ - 1)].doc;
      break;
    default: break;
  }
}

// The chosen preset's purpose and what every preset costs: "default: made for a software
// rasteriser. Here: low light, default light, medium heavy, ...".
std::string Menu::quality_note() const {
  const PresetCost* chosen = preset_cost(files_.settings.quality);
  std::string note = files_.settings.quality + ": " + (chosen ? chosen->what : "a preset of quality.json") + ". ";
  note += machine_.empty() ? "On a software rasteriser:" : "Here:";
  for (size_t i = 0; i < presets_.size(); ++i) {
    const PresetCost* c = preset_cost(presets_[i]);
    const bool software = machine_.empty() || software_rasteriser(machine_);
    note += (i ? ", " : " ") + presets_[i] + " " + (c ? (software ? c->software : c->gpu) : "not rated");
  }
  return note;
}

std::vector<MenuRequest> Menu::settings_accept(Item item) {
  using K = MenuRequest::Kind;
  UserSettings& s = files_.settings;
  switch (item) {
    case Item::Graphics: go(MenuScreen::Graphics); return {};
    case Item::Sound: go(MenuScreen::Sound); return {};
    case Item::Controls: go(MenuScreen::Controls); return {};
    case Item::Advanced: go(MenuScreen::Advanced); return {};
    case Item::RemapKeys: go(MenuScreen::Keys); return {};
    case Item::ResetProgress:
      if (confirm_ != selection_) {
        confirm_ = selection_;
        return {};
      }
      confirm_ = -1;
      files_.progress = {};
      message_ = "Progress reset: every best result is cleared";
      return {{K::SaveProgress}};
    case Item::Action: capturing_ = true; message_.clear(); return {};
    case Item::ResetKeys:
      s.keys.clear();
      bindings_ = default_bindings_;
      apply_user_settings(s, bindings_);
      message_ = "Keys reset to the defaults";
      return {{K::SaveSettings}, {K::ApplyBindings}};
    case Item::ResetRender:
      s.render.clear();
      refresh_effective();
      message_ = "Raw settings follow the " + s.quality + " preset again";
      return {{K::SaveSettings}};
    default: break;
  }
  // A value row: the first Enter asks, the second steps it as Right does.
  if (confirm_ != selection_) {
    confirm_ = selection_;
    message_ = "Enter again to change it; Left/Right change it at once";
    return {};
  }
  confirm_ = -1;
  message_.clear();
  return settings_adjust(item, 1);
}

std::vector<MenuRequest> Menu::set_user_value(const std::string& key, const std::string& value) {
  files_.settings.render[key] = value;
  refresh_effective();
  return {{MenuRequest::Kind::SaveSettings}};
}

std::vector<MenuRequest> Menu::step_user_number(const std::string& key, int step, double by) {
  const SettingDef* d = setting_def(effective_, key);
  if (!d) return {};
  return set_user_value(key, number_text("%.4g", stepped(std::stod(d->value), step, by, d->min, d->max)));
}

std::vector<MenuRequest> Menu::settings_adjust(Item item, int step) {
  using K = MenuRequest::Kind;
  UserSettings& s = files_.settings;
  switch (item) {
    case Item::Quality: {
      // Stops at either end: Left from the cheapest never lands on the most expensive.
      auto it = std::find(presets_.begin(), presets_.end(), s.quality);
      const int at = it == presets_.end() ? 0 : int(it - presets_.begin());
      const int next = std::clamp(at + step, 0, int(presets_.size()) - 1);
      if (presets_.empty() || next == at) return {};
      s.quality = presets_[size_t(next)];
      refresh_effective();
      return {{K::SaveSettings}};
    }
    case Item::Scale: return step_user_number("render.scale", step, 0.25);
    case Item::MasterVolume: return step_user_number("audio.volume", step, 0.1);
    case Item::EffectsVolume: return step_user_number("audio.effects_volume", step, 0.1);
    case Item::Mute: return set_user_value("audio.mute", effective_.flag("audio.mute") ? "false" : "true");
    case Item::MusicVolume: return step_user_number("audio.music_volume", step, 0.1);
    case Item::WeaponsVolume: return step_user_number("audio.weapons_volume", step, 0.1);
    case Item::ImpactsVolume: return step_user_number("audio.impacts_volume", step, 0.1);
    case Item::EnginesVolume: return step_user_number("audio.engines_volume", step, 0.1);
    case Item::UiVolume: return step_user_number("audio.ui_volume", step, 0.1);
    case Item::VoiceVolume: return step_user_number("audio.voice_volume", step, 0.1);
    case Item::Subtitles: return set_user_value("audio.subtitles", effective_.flag("audio.subtitles") ? "false" : "true");
    case Item::Sensitivity:
      s.mouse_sensitivity = stepped(s.mouse_sensitivity, step, 0.01, 0.01, 1.0);
      return {{K::SaveSettings}, {K::ApplyBindings}};
    case Item::Deadzone:
      s.pad_deadzone = stepped(s.pad_deadzone, step, 0.02, 0.0, 0.5);
      return {{K::SaveSettings}, {K::ApplyBindings}};
    case Item::Fov: s.fov = stepped(s.fov, step, 5.0, 40.0, 110.0); return {{K::SaveSettings}};
    case Item::InvertY: s.invert_y = !s.invert_y; return {{K::SaveSettings}, {K::ApplyBindings}};
    case Item::Fullscreen: s.fullscreen = !s.fullscreen; return {{K::SaveSettings}};
    case Item::Vsync: s.vsync = !s.vsync; return {{K::SaveSettings}};
    case Item::DevPanel: s.developer_panel = !s.developer_panel; return {{K::SaveSettings}};
    case Item::RenderKey: return adjust_render(selection_ - 1, step);
    default: return {};
  }
}

// One step of a raw setting: the next choice, the flag flipped, a number by a twentieth of
// its range (a range over a hundredfold by halves and doubles), kept as the user's own value.
std::vector<MenuRequest> Menu::adjust_render(int index, int step) {
  const SettingDef& d = effective_.all()[size_t(index)];
  std::string value;
  switch (d.kind) {
    case SettingDef::Kind::Choice: {
      auto it = std::find(d.choices.begin(), d.choices.end(), d.value);
      const int n = int(d.choices.size()), at = it == d.choices.end() ? 0 : int(it - d.choices.begin());
      value = d.choices[size_t((at + step + n) % n)];
      break;
    }
    case SettingDef::Kind::Flag: value = d.value == "true" ? "false" : "true"; break;
    case SettingDef::Kind::Number:
    case SettingDef::Kind::Integer: {
      const double v = std::stod(d.value);
      const bool wide = d.min > 0 && d.max / d.min > 100;
      const bool integer = d.kind == SettingDef::Kind::Integer;
      const double by = integer ? std::max(1.0, std::round((d.max - d.min) / 20)) : (d.max - d.min) / 20;
      double next = wide ? (step > 0 ? v * 2 : v / 2) : v + step * by;
      next = std::clamp(integer ? std::round(next) : next, d.min, d.max);
      value = d.kind == SettingDef::Kind::Integer ? std::to_string(int64_t(next)) : number_text("%.4g", next);
      break;
    }
  }
  return set_user_value(d.key, value);
}

// Esc on a settings page: back to the row that opened it. False on any other screen.
bool Menu::settings_back() {
  struct Up { MenuScreen page, parent; Item opener; };
  static const Up ups[] = {{MenuScreen::Graphics, MenuScreen::Settings, Item::Graphics},
                           {MenuScreen::Sound, MenuScreen::Settings, Item::Sound},
                           {MenuScreen::Controls, MenuScreen::Settings, Item::Controls},
                           {MenuScreen::Advanced, MenuScreen::Settings, Item::Advanced},
                           {MenuScreen::Keys, MenuScreen::Controls, Item::RemapKeys}};
  for (const Up& u : ups) {
    if (screen_ != u.page) continue;
    go(u.parent);
    const std::vector<Item> rows = settings_items();
    selection_ = int(std::find(rows.begin(), rows.end(), u.opener) - rows.begin());
    return true;
  }
  return false;
}

}  // namespace arc
