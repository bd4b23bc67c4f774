// The menu state machine: screens, their items, navigation, settings changes, remapping, results.
#include "game/app/menu.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <sstream>

#include "core/error.h"
#include "game/app/all_settings.h"
#include "game/app/key_remap.h"
#include "game/sim/world.h"
#include "platform/platform.h"

namespace arc {

enum class Menu::Item {
  Play, Effects, Settings, Quit,                                   // main
  Mission, Effect, Difficulty, Launch, Back,                       // lists and briefing
  Quality, RenderSettings, Sensitivity, InvertY, Deadzone, Fov,     // settings
  Fullscreen, Vsync, RenderKey, ResetRender,
  Controls, ResetProgress, Action, ResetKeys,                      // settings, controls
  Retry, Next, ToMenu                                              // results
};

namespace {

constexpr int kControlRows = 13;  // rows of the controls and render lists on screen at once

std::string clock_text(double seconds) {
  char buf[32];
  const int minutes = int(seconds / 60.0);
  std::snprintf(buf, sizeof buf, "%d:%04.1f", minutes, seconds - minutes * 60.0);
  return buf;
}

std::string number_text(const char* format, double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string percent(double share) { return number_text("%.0f %%", share * 100.0); }
std::string on_off(bool v) { return v ? "on" : "off"; }

double stepped(double v, int step, double by, double lo, double hi) {
  return std::clamp(std::round((v + step * by) / by) * by, lo, hi);
}

std::string result_text(const MissionResult& r) {
  return std::string(r.victory ? "won in " : "lost after ") + clock_text(r.seconds) + ", " + std::to_string(r.kills) +
         (r.kills == 1 ? " kill" : " kills");
}

}  // namespace

MissionResult mission_result(const World& w) {
  MissionResult r;
  r.victory = w.outcome == Outcome::Victory;
  r.seconds = double(w.outcome != Outcome::Undecided ? w.outcome_tick : w.tick) * w.dt;
  if (!w.player) return r;
  const Ship& me = w.ship(w.player);
  r.kills = me.kills;
  r.damage_dealt = me.stats.damage_dealt;
  r.damage_taken = me.stats.damage_taken;
  r.beam_accuracy = accuracy(me.stats.beam_hit_ticks, me.stats.beam_ticks);
  r.missile_accuracy = accuracy(me.stats.missiles_hit, me.stats.missiles_fired);
  return r;
}

std::vector<UiInput> parse_ui_inputs(const std::string& text, const std::string& path) {
  std::vector<UiInput> out;
  std::istringstream lines(text);
  std::string line;
  for (int n = 1; std::getline(lines, line); ++n) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string w;
    auto fail = [&](const std::string& what) {
      const size_t col = line.find(w) + 1;
      throw InputError(path + ":" + std::to_string(n) + ":" + std::to_string(col) + ": " + what);
    };
    while (words >> w) {
      static const std::vector<std::pair<std::string, UiKey>> keys = {
          {"up", UiKey::Up}, {"down", UiKey::Down}, {"left", UiKey::Left}, {"right", UiKey::Right},
          {"accept", UiKey::Accept}, {"back", UiKey::Back}};
      auto k = std::find_if(keys.begin(), keys.end(), [&](const auto& p) { return p.first == w; });
      if (k != keys.end()) {
        out.push_back(UiInput::press(k->second));
        continue;
      }
      std::string arg;
      if ((w != "click" && w != "hover" && w != "bind") || !(words >> arg))
        fail("unknown UI input '" + w + "'; allowed: up, down, left, right, accept, back, click N, hover N, bind KEY");
      if (w == "bind") {
        if (code_of_label(arg) < 0) fail("'" + arg + "' is not a key name (A, SPACE, MOUSE_LEFT, PAD_A, ...)");
        out.push_back(UiInput::bind(code_of_label(arg)));
      } else {
        const int item = std::atoi(arg.c_str());
        out.push_back(w == "click" ? UiInput::click(item) : UiInput::hover(item));
      }
    }
  }
  return out;
}

std::string describe_page(const MenuPage& p) {
  std::string out = "title: " + p.title + "\n";
  if (!p.subtitle.empty()) out += "subtitle: " + p.subtitle + "\n";
  if (!p.paragraph.empty()) out += "paragraph: " + p.paragraph + "\n";
  for (const std::string& l : p.lines) out += "line: " + l + "\n";
  for (size_t i = 0; i < p.items.size(); ++i) out += (int(i) == p.selection ? "> " : "  ") + p.items[i] + "\n";
  if (!p.message.empty()) out += "message: " + p.message + "\n";
  return out;
}

const char* menu_screen_name(MenuScreen s) {
  switch (s) {
    case MenuScreen::Main: return "main";
    case MenuScreen::Missions: return "missions";
    case MenuScreen::Effects: return "effects";
    case MenuScreen::Briefing: return "briefing";
    case MenuScreen::Settings: return "settings";
    case MenuScreen::Render: return "render";
    case MenuScreen::Controls: return "controls";
    case MenuScreen::Results: return "results";
    case MenuScreen::Closed: return "closed";
  }
  return "?";
}

Menu::Menu(std::vector<MissionInfo> catalog, UserFiles files, Bindings bindings, Bindings default_bindings,
           const std::string& quality_file)
    : catalog_(std::move(catalog)),
      files_(std::move(files)),
      bindings_(std::move(bindings)),
      default_bindings_(std::move(default_bindings)),
      presets_(Settings::preset_names(quality_file)),
      quality_file_(quality_file),
      message_(files_.message) {
  // The quality file's presets come in name order; offer them from cheap to exact, with the
  // built-in settings ("default") after low.
  presets_.push_back(kDefaultQuality);
  const std::vector<std::string> known = {"low", kDefaultQuality, "medium", "high", "reference"};
  auto rank = [&](const std::string& p) { return std::find(known.begin(), known.end(), p) - known.begin(); };
  std::stable_sort(presets_.begin(), presets_.end(), [&](const auto& a, const auto& b) { return rank(a) < rank(b); });
  refresh_effective();
}

void Menu::refresh_effective() {
  try {
    effective_ = user_quality_settings(files_.settings, quality_file_);
  } catch (const InputError& e) {
    effective_ = all_settings();
    message_ = e.what();
  }
}

std::vector<const MissionInfo*> Menu::listed() const {
  const MissionCategory want = screen_ == MenuScreen::Effects ? MissionCategory::Effects : MissionCategory::Mission;
  std::vector<const MissionInfo*> out;
  for (const MissionInfo& m : catalog_)
    if (m.category == want) out.push_back(&m);
  return out;
}

std::vector<Menu::Item> Menu::items() const {
  switch (screen_) {
    case MenuScreen::Main: return {Item::Play, Item::Effects, Item::Settings, Item::Quit};
    case MenuScreen::Missions:
    case MenuScreen::Effects: {
      std::vector<Item> v(listed().size(), screen_ == MenuScreen::Missions ? Item::Mission : Item::Effect);
      if (screen_ == MenuScreen::Missions) v.push_back(Item::Difficulty);
      v.push_back(Item::Back);
      return v;
    }
    case MenuScreen::Briefing: return {Item::Launch, Item::Difficulty, Item::Back};
    case MenuScreen::Settings:
      return {Item::Quality,    Item::RenderSettings, Item::Sensitivity, Item::InvertY,       Item::Deadzone, Item::Fov,
              Item::Fullscreen, Item::Vsync,          Item::Controls,    Item::ResetProgress, Item::Back};
    case MenuScreen::Render: {
      std::vector<Item> v(effective_.all().size(), Item::RenderKey);
      v.push_back(Item::ResetRender);
      v.push_back(Item::Back);
      return v;
    }
    case MenuScreen::Controls: {
      std::vector<Item> v(remap_actions().size(), Item::Action);
      v.push_back(Item::ResetKeys);
      v.push_back(Item::Back);
      return v;
    }
    case MenuScreen::Results: {
      std::vector<Item> v{Item::Retry};
      if (next_mission(catalog_, chosen_)) v.push_back(Item::Next);
      v.push_back(Item::ToMenu);
      return v;
    }
    case MenuScreen::Closed: return {};
  }
  return {};
}

std::string Menu::best_text(const std::string& level) const {
  auto it = files_.progress.best.find(progress_key(level, difficulty_name(difficulty_)));
  return it == files_.progress.best.end() ? "no result yet" : result_text(it->second);
}

// Long: one label per kind of item, each a line; splitting it would scatter the screen's text.
std::string Menu::item_label(Item item, int index) const {
  const UserSettings& s = files_.settings;
  switch (item) {
    case Item::Play: return "Play";
    case Item::Effects: return "Effects";
    case Item::Settings: return "Settings";
    case Item::Quit: return "Quit";
    case Item::Mission: {
      const MissionInfo& m = *listed()[size_t(index)];
      std::string label = std::to_string(m.order) + ". " + m.title;
      label.resize(std::max<size_t>(label.size() + 2, 24), ' ');
      return label + "best: " + best_text(m.path);
    }
    case Item::Effect: return listed()[size_t(index)]->title;
    case Item::Difficulty: return std::string("Difficulty: < ") + difficulty_name(difficulty_) + " >";
    case Item::Launch: return "Launch";
    case Item::Back: return "Back";
    case Item::Quality: return "Quality preset: < " + s.quality + " >";
    case Item::RenderSettings:
      return "Render settings (" + std::to_string(s.render.size()) + " of yours over the preset)";
    case Item::RenderKey: {
      const SettingDef& d = effective_.all()[size_t(index)];
      std::string label = d.key;
      label.resize(std::max<size_t>(label.size() + 1, 30), ' ');
      return label + "< " + d.value + " >" + (s.render.count(d.key) ? "  *" : "");
    }
    case Item::ResetRender: return "Back to the preset's values";
    case Item::Sensitivity: return number_text("Mouse sensitivity: < %.2f > deg/px", s.mouse_sensitivity);
    case Item::InvertY: return "Invert Y: " + on_off(s.invert_y);
    case Item::Deadzone: return number_text("Gamepad dead zone: < %.2f >", s.pad_deadzone);
    case Item::Fov: return number_text("Field of view: < %.0f > deg", s.fov);
    case Item::Fullscreen: return "Fullscreen: " + on_off(s.fullscreen);
    case Item::Vsync: return "VSync: " + on_off(s.vsync);
    case Item::Controls: return "Controls (remap keys)";
    case Item::ResetProgress: return confirm_reset_ ? "Reset progress: press again to confirm" : "Reset progress";
    case Item::Action: {
      const RemapAction& a = remap_actions()[size_t(index)];
      std::string label = a.label;
      label.resize(24, ' ');
      const bool waiting = capturing_ && index == selection_;
      return label + (waiting ? "press a key..." : key_label(bound_key(bindings_, a.id)));
    }
    case Item::ResetKeys: return "Reset keys to defaults";
    case Item::Retry: return "Retry";
    case Item::Next: return "Next mission: " + next_mission(catalog_, chosen_)->title;
    case Item::ToMenu: return "Menu";
  }
  return "";
}

void Menu::fill_briefing_page(MenuPage& p) const {
  const MissionInfo* m = find_mission(catalog_, chosen_);
  if (!m) return;
  p.title = m->title;
  p.subtitle = "Objective: " + m->objective;
  p.paragraph = m->briefing;
  p.lines.push_back(std::string("Difficulty: ") + difficulty_name(difficulty_) + "   (Left/Right changes it)");
  p.lines.push_back(std::string("Best (") + difficulty_name(difficulty_) + "): " + best_text(m->path));
}

void Menu::fill_results_page(MenuPage& p) const {
  const MissionInfo* m = find_mission(catalog_, chosen_);
  const MissionResult& r = last_;
  p.title = r.victory ? "VICTORY" : "DEFEAT";
  p.title_tone = r.victory ? 1 : -1;
  p.subtitle = (m ? m->title : chosen_) + " (" + difficulty_name(difficulty_) + ")";
  p.lines = {"Time              " + clock_text(r.seconds),
             "Kills             " + std::to_string(r.kills),
             "Damage dealt      " + number_text("%.0f", r.damage_dealt),
             "Damage taken      " + number_text("%.0f", r.damage_taken),
             "Beam accuracy     " + percent(r.beam_accuracy),
             "Missile accuracy  " + percent(r.missile_accuracy),
             !last_is_best_ ? "Best so far: " + best_text(chosen_)
             : r.victory    ? "New best!"
                            : "Your best try yet (no win so far)"};
}

MenuPage Menu::page() const {
  MenuPage p;
  const std::vector<Item> list = items();
  for (size_t i = 0; i < list.size(); ++i) p.items.push_back(item_label(list[i], int(i)));
  p.selection = selection_;
  p.message = message_;
  p.hint = "Up/Down or mouse: choose   Enter / A: select   Esc / B: back";
  switch (screen_) {
    case MenuScreen::Main: p.title = "ARCFIRE"; p.subtitle = "space combat with lightning"; break;
    case MenuScreen::Missions: p.title = "MISSIONS"; p.subtitle = "Left/Right: difficulty"; break;
    case MenuScreen::Effects: p.title = "EFFECTS"; p.subtitle = "every particle effect, on its own"; break;
    case MenuScreen::Briefing: fill_briefing_page(p); break;
    case MenuScreen::Settings:
      p.title = "SETTINGS";
      p.hint = "Left/Right: change   Enter: toggle or open   Esc: back (saved as you go)";
      break;
    case MenuScreen::Render:
      p.title = "RENDER SETTINGS";
      p.subtitle = "quality preset " + files_.settings.quality + "; * marks your own values";
      p.hint = "Left/Right: change   Esc: back (saved as you go)";
      p.first = std::clamp(selection_ - kControlRows / 2, 0, std::max(0, int(p.items.size()) - kControlRows));
      p.rows = kControlRows;
      if (selection_ < int(effective_.all().size())) p.message = effective_.all()[size_t(selection_)].doc;
      break;
    case MenuScreen::Controls:
      p.title = "CONTROLS";
      p.hint = capturing_ ? "press the new key or mouse button   Esc: cancel" : "Enter: remap   Esc: back";
      p.first = std::clamp(selection_ - kControlRows / 2, 0, std::max(0, int(p.items.size()) - kControlRows));
      p.rows = kControlRows;
      break;
    case MenuScreen::Results: fill_results_page(p); break;
    case MenuScreen::Closed: break;
  }
  return p;
}

void Menu::go(MenuScreen s) {
  screen_ = s;
  selection_ = 0;
  confirm_reset_ = false;
  capturing_ = false;
}

void Menu::open_main() {
  go(MenuScreen::Main);
  message_.clear();
}

std::vector<MenuRequest> Menu::handle(const UiInput& in) {
  if (screen_ == MenuScreen::Closed) return {};
  if (capturing_) {
    if (in.kind == UiInput::Kind::Bind) return bind(in.code);
    if (in.kind == UiInput::Kind::Key && in.key == UiKey::Back) {
      capturing_ = false;
      message_ = "Remap cancelled";
    }
    return {};
  }
  const std::vector<Item> list = items();
  const int count = int(list.size());
  if (count == 0) return {};
  switch (in.kind) {
    case UiInput::Kind::Bind: return {};
    case UiInput::Kind::Hover:
      if (in.item >= 0 && in.item < count && in.item != selection_) selection_ = in.item, confirm_reset_ = false;
      return {};
    case UiInput::Kind::Click:
      if (in.item < 0 || in.item >= count) return {};
      if (in.item != selection_) confirm_reset_ = false;
      selection_ = in.item;
      return accept(list[size_t(selection_)], selection_);
    case UiInput::Kind::Key: break;
  }
  switch (in.key) {
    case UiKey::Up:
    case UiKey::Down:
      selection_ = (selection_ + (in.key == UiKey::Down ? 1 : -1) + count) % count;
      confirm_reset_ = false;
      return {};
    case UiKey::Left: return adjust(list[size_t(selection_)], -1);
    case UiKey::Right: return adjust(list[size_t(selection_)], 1);
    case UiKey::Accept: return accept(list[size_t(selection_)], selection_);
    case UiKey::Back: return back();
  }
  return {};
}

// Long: one case per kind of item, each a few lines of what Enter (or a click) does to it.
std::vector<MenuRequest> Menu::accept(Item item, int index) {
  using K = MenuRequest::Kind;
  UserSettings& s = files_.settings;
  switch (item) {
    case Item::Play: go(MenuScreen::Missions); return {};
    case Item::Effects: go(MenuScreen::Effects); return {};
    case Item::Settings: go(MenuScreen::Settings); return {};
    case Item::Quit: return {{K::Quit}};
    case Item::Mission:
      chosen_ = listed()[size_t(index)]->path;
      go(MenuScreen::Briefing);
      return {};
    case Item::Effect: {
      const std::string level = listed()[size_t(index)]->path;
      go(MenuScreen::Closed);
      return {{K::Launch, level, difficulty_}};
    }
    case Item::Launch:
      go(MenuScreen::Closed);
      return {{K::Launch, chosen_, difficulty_}};
    case Item::Back: return back();
    case Item::InvertY: s.invert_y = !s.invert_y; return {{K::SaveSettings}, {K::ApplyBindings}};
    case Item::Fullscreen: s.fullscreen = !s.fullscreen; return {{K::SaveSettings}};
    case Item::Vsync: s.vsync = !s.vsync; return {{K::SaveSettings}};
    case Item::Controls: go(MenuScreen::Controls); return {};
    case Item::RenderSettings: go(MenuScreen::Render); return {};
    case Item::ResetRender:
      s.render.clear();
      refresh_effective();
      message_ = "Render settings follow the " + s.quality + " preset again";
      return {{K::SaveSettings}};
    case Item::ResetProgress:
      if (!confirm_reset_) {
        confirm_reset_ = true;
        return {};
      }
      confirm_reset_ = false;
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
    case Item::Retry:
      go(MenuScreen::Closed);
      return {{K::Launch, chosen_, difficulty_}};
    case Item::Next: {
      const std::string level = next_mission(catalog_, chosen_)->path;
      go(MenuScreen::Closed);
      return {{K::Launch, level, difficulty_}};
    }
    case Item::ToMenu: open_main(); return {};
    default: return adjust(item, 1);  // values: Enter steps them up, like Right
  }
}

std::vector<MenuRequest> Menu::adjust(Item item, int step) {
  using K = MenuRequest::Kind;
  UserSettings& s = files_.settings;
  switch (item) {
    case Item::Mission:
    case Item::Launch:
    case Item::Difficulty: difficulty_ = Difficulty((int(difficulty_) + step + 3) % 3); return {};
    case Item::Quality: {
      if (presets_.empty()) return {};
      auto it = std::find(presets_.begin(), presets_.end(), s.quality);
      const int at = it == presets_.end() ? 0 : int(it - presets_.begin()), n = int(presets_.size());
      s.quality = presets_[size_t((at + step + n) % n)];
      refresh_effective();
      return {{K::SaveSettings}};
    }
    case Item::Sensitivity:
      s.mouse_sensitivity = stepped(s.mouse_sensitivity, step, 0.01, 0.01, 1.0);
      return {{K::SaveSettings}, {K::ApplyBindings}};
    case Item::Deadzone:
      s.pad_deadzone = stepped(s.pad_deadzone, step, 0.02, 0.0, 0.5);
      return {{K::SaveSettings}, {K::ApplyBindings}};
    case Item::Fov: s.fov = stepped(s.fov, step, 5.0, 40.0, 110.0); return {{K::SaveSettings}};
    case Item::InvertY:
    case Item::Fullscreen:
    case Item::Vsync: return accept(item, selection_);
    case Item::RenderKey: return adjust_render(selection_, step);
    default: return {};
  }
}

// One step of a render setting: the next choice, the flag flipped, a number by a twentieth of
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
  files_.settings.render[d.key] = value;
  refresh_effective();
  return {{MenuRequest::Kind::SaveSettings}};
}

std::vector<MenuRequest> Menu::back() {
  message_.clear();
  switch (screen_) {
    case MenuScreen::Briefing: {
      go(MenuScreen::Missions);
      const std::vector<const MissionInfo*> list = listed();
      for (size_t i = 0; i < list.size(); ++i)
        if (list[i]->path == chosen_) selection_ = int(i);
      break;
    }
    case MenuScreen::Controls: go(MenuScreen::Settings); selection_ = 8; break;
    case MenuScreen::Render: go(MenuScreen::Settings); selection_ = 1; break;
    case MenuScreen::Main: break;
    default: go(MenuScreen::Main); break;
  }
  return {};
}

std::vector<MenuRequest> Menu::bind(int code) {
  capturing_ = false;
  if (selection_ < 0 || selection_ >= int(remap_actions().size())) return {};
  const RemapOutcome r = remap_key(bindings_, remap_actions()[size_t(selection_)].id, code);
  message_ = r.message;
  if (!r.changed) return {};
  files_.settings.keys = key_overrides(bindings_, default_bindings_);
  return {{MenuRequest::Kind::SaveSettings}, {MenuRequest::Kind::ApplyBindings}};
}

std::vector<MenuRequest> Menu::show_results(const std::string& level, Difficulty d, const MissionResult& r) {
  go(MenuScreen::Results);
  chosen_ = level;
  difficulty_ = d;
  last_ = r;
  message_.clear();
  last_is_best_ = record_result(files_.progress, progress_key(level, difficulty_name(d)), r);
  if (!last_is_best_) return {};
  return {{MenuRequest::Kind::SaveProgress}};
}

}  // namespace arc
