// game/app/menu.h — the game around the fight: main menu, mission select, briefing, effects,
// settings, key remapping and the results screen, as a state machine over plain UI inputs.
//
// No GL and no window: the window loop turns keys, mouse and gamepad into UiInputs, feeds
// them to handle(), carries out the MenuRequests it returns (launch a level, save settings,
// quit) and draws page() with layout_menu() (game/render/menu_layout.h). Tests drive the same
// machine with a scripted list of inputs (tests/unit/app/test_menu.cpp).
//
//   Menu menu(load_mission_catalog("levels", "."), files, bindings, default_bindings, "assets/settings/quality.json");
//   for (MenuRequest r : menu.handle(UiInput::key(UiKey::Accept))) ...   // Play
//   menu.show_results(level, Difficulty::Normal, result);                 // after the fight
#pragma once
#include <string>
#include <vector>

#include "game/app/input_bindings.h"
#include "game/app/mission_catalog.h"
#include "game/app/user_settings.h"
#include "game/render/menu_layout.h"
#include "game/sim/game.h"

namespace arc {

class World;

enum class UiKey { Up, Down, Left, Right, Accept, Back };

struct UiInput {
  enum class Kind { Key, Hover, Click, Bind };
  Kind kind = Kind::Key;
  UiKey key = UiKey::Accept;  // Key
  int item = -1;              // Hover, Click: the item under the mouse
  int code = -1;              // Bind: the key_code() pressed while a remap waits for one
  static UiInput press(UiKey k) { return {Kind::Key, k, -1, -1}; }
  static UiInput hover(int item) { return {Kind::Hover, UiKey::Accept, item, -1}; }
  static UiInput click(int item) { return {Kind::Click, UiKey::Accept, item, -1}; }
  static UiInput bind(int code) { return {Kind::Bind, UiKey::Accept, -1, code}; }
};

// The results of the player's fight from the simulation's own counters (time to the outcome,
// the player ship's kills, damage and accuracy).
MissionResult mission_result(const World& w);

// A scripted sequence of UI inputs, one per word or "click N" / "hover N" / "bind KEY" pair:
// up down left right accept back. InputError "path:line:col: ..." for anything else.
std::vector<UiInput> parse_ui_inputs(const std::string& text, const std::string& path);

// A screen as text, one line per element ("title: ...", "> item" for the selected one): the
// snapshots of the menu test and of `arcfire --menu-script`.
std::string describe_page(const MenuPage& p);

enum class MenuScreen { Main, Missions, Effects, Briefing, Settings, Render, Controls, Results, Closed };
const char* menu_screen_name(MenuScreen s);

struct MenuRequest {
  enum class Kind { Launch, Quit, SaveSettings, SaveProgress, ApplyBindings };
  MenuRequest(Kind k, std::string level_path = {}, Difficulty d = Difficulty::Normal)
      : kind(k), level(std::move(level_path)), difficulty(d) {}
  Kind kind;
  std::string level;      // Launch
  Difficulty difficulty;  // Launch
};

class Menu {
 public:
  // `quality_file`: the presets (assets/settings/quality.json) the settings screen offers.
  Menu(std::vector<MissionInfo> catalog, UserFiles files, Bindings bindings, Bindings default_bindings,
       const std::string& quality_file);

  MenuScreen screen() const { return screen_; }
  bool open() const { return screen_ != MenuScreen::Closed; }
  // Waiting for the key to bind (the window sends the next key or button as UiInput::bind).
  bool capturing() const { return capturing_; }
  MenuPage page() const;
  std::vector<MenuRequest> handle(const UiInput& in);

  // The fight ended: the results screen for it, the best kept (SaveProgress requested when it
  // changed). Retry and Next mission launch at the same difficulty.
  std::vector<MenuRequest> show_results(const std::string& level, Difficulty d, const MissionResult& r);
  void open_main();
  void set_message(std::string m) { message_ = std::move(m); }

  const UserSettings& settings() const { return files_.settings; }
  const Progress& progress() const { return files_.progress; }
  const Bindings& bindings() const { return bindings_; }
  Difficulty difficulty() const { return difficulty_; }

 private:
  enum class Item;
  std::vector<Item> items() const;
  std::string item_label(Item item, int index) const;
  void go(MenuScreen s);
  std::vector<MenuRequest> accept(Item item, int index);
  std::vector<MenuRequest> adjust(Item item, int step);
  std::vector<MenuRequest> back();
  std::vector<MenuRequest> bind(int code);
  std::vector<const MissionInfo*> listed() const;  // the missions or effects on screen
  std::string best_text(const std::string& level) const;
  void fill_results_page(MenuPage& p) const;
  void fill_briefing_page(MenuPage& p) const;

  std::vector<MissionInfo> catalog_;
  UserFiles files_;
  Bindings bindings_, default_bindings_;
  std::vector<std::string> presets_;
  std::string quality_file_;
  Settings effective_;  // the render settings as they apply: the preset, then the user's values
  void refresh_effective();
  std::vector<MenuRequest> adjust_render(int index, int step);
  MenuScreen screen_ = MenuScreen::Main;
  int selection_ = 0;
  Difficulty difficulty_ = Difficulty::Normal;
  std::string chosen_;  // the briefing's level, then the results' level
  MissionResult last_;
  bool last_is_best_ = false;
  bool capturing_ = false;
  bool confirm_reset_ = false;
  std::string message_;
};

}  // namespace arc
