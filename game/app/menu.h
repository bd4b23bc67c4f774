// game/app/menu.h — the game around the fight: main menu, mission select, briefing, effects,
// settings, key remapping, the results screen and the pause screen, as a state machine over
// plain UI inputs.
//
// Settings holds Graphics, Sound, Controls (with key remapping), Advanced (every raw setting
// and the developer panel's switch) and Reset progress. A value changes only by Left/Right;
// Enter or a click on a value row asks first and changes it on a second Enter or click.
//
// No GL and no window: the window loop turns keys, mouse and gamepad into UiInputs, feeds
// them to handle(), carries out the MenuRequests it returns (launch a level, save settings,
// resume, quit) and draws page() with layout_menu() (game/render/menu_layout.h). Tests drive
// the same machine with a scripted list of inputs (tests/unit/app/test_menu.cpp). A game
// started with --level has no main menu: Menu(files) holds only the pause screen.
//
// Example, compiled as BannerExample.Menu in tests/unit/app/test_banner_examples.cpp:
//   Menu menu(load_mission_catalog("levels", "."), files, bindings, bindings, "assets/settings/quality.json");
//   menu.handle(UiInput::press(UiKey::Accept));  // Play: mission select
//   menu.handle(UiInput::press(UiKey::Accept));  // the first mission's briefing
//   std::vector<MenuRequest> go = menu.handle(UiInput::press(UiKey::Accept));  // Launch
//   menu.pause(paused);                          // the game paused: Resume, Restart, ... Quit
//   std::vector<MenuRequest> resume = menu.handle(UiInput::press(UiKey::Back));  // Esc: Resume
//   menu.show_results(go[0].level, go[0].difficulty, result);  // the fight decided
#pragma once
#include <string>
#include <vector>

#include "game/app/input_bindings.h"
#include "game/app/mission_catalog.h"
#include "game/app/quick_battle.h"
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

enum class MenuScreen {
  Main, Missions, Effects, Briefing,
  Settings, Graphics, Sound, Controls, Keys, Advanced,  // Settings and its pages
  Results, Pause, Closed,
  QuickBattle,  // game/app/menu_quick.cpp
  Multiplayer, NetHost, NetJoin, Lobby  // game/app/menu_net.cpp
};
const char* menu_screen_name(MenuScreen s);

// What the pause screen shows of the game behind it; the window fills it while the game is
// paused. The AI's difficulty is fixed when a game starts, so a change waits for the restart.
struct PauseState {
  std::string outcome;      // "" while the fight is undecided, else its verdict ("VICTORY", "DEFEAT", ...)
  int outcome_tone = 0;     // as MenuPage::title_tone
  Difficulty playing = Difficulty::Normal;  // the running game's
  Difficulty next = Difficulty::Normal;     // what Restart (Retry) starts
  bool recording = false;   // Restart and Main menu end the recording: their labels say so
  bool muted = false;
  double volume = 1.0;      // 0..1, in steps of a tenth
};

// The verdict of a decided fight as PauseState::outcome and its tone, the rest left default.
PauseState pause_state_of(const World& w);

struct MenuRequest {
  enum class Kind {
    Launch, Quit, SaveSettings, SaveProgress, ApplyBindings,   // main menu, results
    Resume, Restart, SetDifficulty, ToggleMute, StepVolume, MainMenu,  // pause screen
    SaveQuickBattle,  // the quick battle setup changed: Menu::quick_setup() to keep
    // Multiplayer (menu_net.cpp): host `level` at `difficulty` on port `steps`; join the address
    // in `level`; ask for slot `steps`; the host's launch; leave the lobby or the match.
    NetHost, NetJoin, NetPick, NetLaunch, NetLeave
  };
  MenuRequest(Kind k, std::string level_path = {}, Difficulty d = Difficulty::Normal, int step_count = 0)
      : kind(k), level(std::move(level_path)), difficulty(d), steps(step_count) {}
  Kind kind;
  std::string level;      // Launch
  Difficulty difficulty;  // Launch, SetDifficulty (for the next restart)
  std::string ship, loadout;  // Launch: the briefing's choice ("": the level's own)
  int steps;              // StepVolume: tenths of full volume, + louder
  // Launch of a quick battle: the level text to write at `level` (made if missing) before it starts.
  std::string generated;
};

// The lobby as the window shows it (from game/app/net_match.h): one row per slot.
struct NetLobbyView {
  std::string title = "LOBBY";    // "RESULTS" when the match is decided
  std::string status;             // whom it waits for, or why the match could not start
  std::vector<std::string> rows;  // "1  blue  Red Leader   Ann   42 ms"
  std::vector<bool> free;         // per row: no pilot flies the slot (a pilot may pick it)
  bool host = false;              // Launch is offered
  bool standalone = false;        // started from the command line: leaving closes the game
};

// A mission a network match may be hosted on (a level with two or more slots).
struct NetMission {
  std::string path, title;
};

class Menu {
 public:
  // `quality_file`: the presets (assets/settings/quality.json) the settings screen offers.
  Menu(std::vector<MissionInfo> catalog, UserFiles files, Bindings bindings, Bindings default_bindings,
       const std::string& quality_file);
  // No main menu (a game started with --level): closed until pause() opens the pause screen.
  explicit Menu(UserFiles files);

  MenuScreen screen() const { return screen_; }
  bool open() const { return screen_ != MenuScreen::Closed; }
  bool has_main() const { return has_main_; }
  // A screen over a running game (main menu, results): the menu has the devices, not the ship.
  bool over_game() const { return open() && screen_ != MenuScreen::Pause; }
  // Waiting for the key to bind (the window sends the next key or button as UiInput::bind).
  bool capturing() const { return capturing_; }
  MenuPage page() const;
  std::vector<MenuRequest> handle(const UiInput& in);

  // The fight ended: the results screen for it, the best kept (SaveProgress requested when it
  // changed). Retry and Next mission launch at the same difficulty.
  std::vector<MenuRequest> show_results(const std::string& level, Difficulty d, const MissionResult& r);
  void open_main();
  // The game is paused: opens the pause screen on its first item, or shows `s` on it while it
  // is open. Another screen open (the results over a paused fight): nothing.
  void pause(const PauseState& s);
  // The game runs again: the pause screen closes.
  void close_pause();
  void set_message(std::string m) { message_ = std::move(m); }
  // What draws the frames (the GL renderer's name, "" if unknown): the Graphics page rates the
  // quality presets for it (a software rasteriser or a GPU).
  void set_machine(std::string gl_renderer) { machine_ = std::move(gl_renderer); }
  // The preset a first start chose for the device (device_look.h), and why: shown on the
  // Graphics page while that preset is the one in use.
  void adopt_device_quality(const std::string& preset, std::string why) {
    files_.settings.quality = preset;
    device_preset_ = preset;
    device_why_ = std::move(why);
    refresh_effective();
  }

  const UserSettings& settings() const { return files_.settings; }
  const Progress& progress() const { return files_.progress; }
  const Bindings& bindings() const { return bindings_; }
  Difficulty difficulty() const { return difficulty_; }
  // Offers "Quick battle" on the main menu with these classes, starting from `setup`.
  void set_quick_battle(QuickClasses classes, QuickSetup setup);
  const QuickSetup& quick_setup() const { return quick_; }
  // The level whose briefing is on screen ("" on any other screen): what Launch would start.
  std::string briefing_level() const { return screen_ == MenuScreen::Briefing ? chosen_ : ""; }
  // The ships the player may fly. By default the campaign's unlocks decide from the progress
  // file (campaign.h: ship_locked_by); a list set here replaces them (empty: back to the unlocks).
  void set_unlocked_ships(std::vector<std::string> ships) { unlocked_ships_ = std::move(ships); }
  bool ship_open(const std::string& ship) const;
  // The briefing's ship and loadout ("" where the level offers no choice).
  std::string chosen_ship() const;
  std::string chosen_loadout() const;

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
  std::string campaign_label(const MissionInfo& m) const;
  void fill_results_page(MenuPage& p) const;
  void fill_briefing_page(MenuPage& p) const;
  std::string pause_label(Item item) const;
  std::vector<MenuRequest> pause_accept(Item item);
  // menu_loadout.cpp: the briefing's ship and loadout choice.
  std::vector<Item> briefing_items() const;
  std::vector<ShipChoice> offered_ships() const;
  void reset_choice();
  std::string choice_label(Item item) const;
  void adjust_choice(Item item, int step);
  void fill_choice_lines(MenuPage& p) const;
  MenuRequest launch_request(const std::string& level) const;
  // "Locked: dart (win Campaign 3. Cargo Run)" for those of `ships` still locked ("" for none).
  std::string locked_line(const std::vector<std::string>& ships) const;
  std::string quick_player() const;  // the quick battle's ship: the setup's if open, else an open one
  std::vector<std::string> unlocked_ships_;
  std::vector<std::string> new_ships_;  // unlocked by the result on the results screen
  // menu_net.cpp: Multiplayer, Host, Join and the lobby.
 public:
  void set_net_missions(std::vector<NetMission> m) { net_missions_ = std::move(m); }
  // The lobby screen (opened once, then refreshed by the window each frame).
  void open_lobby(NetLobbyView v);
  void set_lobby(NetLobbyView v) { lobby_ = std::move(v); }
  void close_lobby();  // the match launched
  // Editing a text row (the name, the address): keys arrive as UiInput::bind like a remap.
  bool editing() const { return editing_; }

 private:
  std::vector<Item> net_items() const;
  std::string net_label(Item item, int index) const;
  void fill_net_page(MenuPage& p) const;
  std::vector<MenuRequest> net_accept(Item item, int index);
  std::vector<MenuRequest> net_adjust(Item item, int step);
  std::vector<MenuRequest> net_type(int code);
  bool net_back(std::vector<MenuRequest>& out);
  std::vector<NetMission> net_missions_;
  NetLobbyView lobby_;
  int net_mission_ = 0, net_port_ = 27960;
  std::string net_address_;
  bool editing_ = false;
  int ship_choice_ = 0, loadout_choice_ = 0;

  std::vector<MissionInfo> catalog_;
  UserFiles files_;
  Bindings bindings_, default_bindings_;
  std::vector<std::string> presets_;
  std::string quality_file_;
  Settings effective_;  // the render settings as they apply: the preset, then the user's values
  void refresh_effective();
  std::vector<MenuRequest> adjust_render(int index, int step);
  // menu_settings.cpp: the settings screen and its pages.
  std::vector<Item> settings_items() const;
  std::string settings_label(Item item, int index) const;
  void fill_settings_page(MenuPage& p) const;
  std::string quality_note() const;
  std::vector<MenuRequest> settings_accept(Item item);
  std::vector<MenuRequest> settings_adjust(Item item, int step);
  std::vector<MenuRequest> set_user_value(const std::string& key, const std::string& value);
  std::vector<MenuRequest> step_user_number(const std::string& key, int step, double by);
  bool settings_back();
  // menu_quick.cpp: the quick battle's setup page.
  std::vector<Item> quick_items() const;
  std::string quick_label(Item item) const;
  void fill_quick_page(MenuPage& p) const;
  std::vector<MenuRequest> quick_accept(Item item);
  std::vector<MenuRequest> quick_adjust(Item item, int step);
  QuickClasses quick_classes_;
  QuickSetup quick_;
  bool has_quick_ = false;
  std::string machine_;
  std::string device_preset_, device_why_;  // adopt_device_quality()
  int confirm_ = -1;  // the value row whose change waits for a second Enter (or click)
  MenuScreen screen_ = MenuScreen::Main;
  int selection_ = 0;
  Difficulty difficulty_ = Difficulty::Normal;
  std::string chosen_;  // the briefing's level, then the results' level
  MissionResult last_;
  bool last_is_best_ = false;
  bool capturing_ = false;
  std::string message_;
  bool has_main_ = true;
  PauseState pause_;
};

}  // namespace arc
