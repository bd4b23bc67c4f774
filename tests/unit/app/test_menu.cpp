// The menu (game/app/menu.h) driven headless by scripted UI inputs: main menu → mission select
// → briefing with a difficulty → launch → the fight → results → next mission; the settings
// pages (graphics, sound, controls with key remapping, advanced) and their no-silent-change
// rule; the developer panel's F1 gate; mouse hovering and clicking on the laid-out items; the
// pause screen over a game, with and without the main menu. Each screen is checked as text (describe_page,
// menu_snapshots.h), the snapshot of what it shows.
#include <filesystem>
#include <gtest/gtest.h>

#include "game/app/dev_panel_gate.h"
#include "game/app/key_remap.h"
#include "game/app/menu.h"
#include "menu_script.h"
#include "game/app/menu_input.h"
#include "game/app/menu_snapshots.h"
#include "game/render/menu_layout.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "platform/platform.h"
#include "core/data_root.h"

namespace arc {
namespace {

using menu_test::run;
using menu_test::has_line;
const std::string kRoot = arc::data_root();

Menu make_menu() { return menu_test::shipped_menu(); }

// The fight a Launch request starts, run headless without input until decided (at most 2 min).
MissionResult fight(const MenuRequest& launch) {
  GameOptions o;
  o.root_dir = kRoot;
  o.difficulty = launch.difficulty;
  o.difficulty_override = true;
  Game g = Game::load_level(launch.level, o);
  for (int i = 0; i < 7200 && g.world().outcome == Outcome::Undecided; ++i) g.step(InputFrame{});
  return mission_result(g.world());
}

TEST(Menu, CatalogListsMissionsInOrderAndTheGalleryUnderEffects) {
  const auto all = load_mission_catalog(kRoot + "/levels", kRoot);
  std::vector<std::string> titles;
  for (const MissionInfo& m : all) titles.push_back(m.title);
  EXPECT_EQ(titles, (std::vector<std::string>{"Training", "Duel", "Skirmish", "Arena", "Effect gallery", "Attract demo"}));
  EXPECT_EQ(all[4].category, MissionCategory::Effects);
  ASSERT_NE(next_mission(all, all[0].path), nullptr);
  EXPECT_EQ(next_mission(all, all[0].path)->title, "Duel");
  EXPECT_EQ(next_mission(all, all[1].path)->title, "Skirmish");
  EXPECT_EQ(next_mission(all, all[3].path), nullptr);
}

TEST(Menu, ADuplicateOrderIsAnErrorAtItsPosition) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("arcfire_catalog_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::copy_file(kRoot + "/levels/duel.json", dir / "a.json", fs::copy_options::overwrite_existing);
  fs::copy_file(kRoot + "/levels/duel.json", dir / "b.json", fs::copy_options::overwrite_existing);
  try {
    load_mission_catalog(dir.string(), kRoot);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("b.json:12:14: 'order' 2 is already taken by"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// Long: one scripted session through every screen, checked screen by screen.
TEST(Menu, ScriptedSessionReachesTheResultsAndGoesOn) {
  Menu m = make_menu();
  EXPECT_EQ(describe_page(m.page()),
            "title: ARCFIRE\nsubtitle: space combat with lightning\n> Play\n  Effects\n  Settings\n  Multiplayer\n  Quit\n");
  run(m, "accept");
  ASSERT_EQ(m.screen(), MenuScreen::Missions);
  EXPECT_TRUE(has_line(m.page(), "> 1. Training"));
  EXPECT_TRUE(has_line(m.page(), "  2. Duel"));
  EXPECT_TRUE(has_line(m.page(), "  4. Arena"));
  EXPECT_TRUE(has_line(m.page(), "best: no result yet"));
  EXPECT_TRUE(has_line(m.page(), "  Difficulty: < normal >"));
  run(m, "down down accept");  // Skirmish's briefing
  ASSERT_EQ(m.screen(), MenuScreen::Briefing);
  EXPECT_EQ(m.page().title, "Skirmish");
  EXPECT_NE(m.page().paragraph.find("Alpha 2"), std::string::npos);
  EXPECT_TRUE(has_line(m.page(), "subtitle: Objective: With your wing, destroy the red patrol and its reinforcements."));
  run(m, "right");  // hard
  EXPECT_TRUE(has_line(m.page(), "line: Difficulty: hard"));
  run(m, "back left accept");  // back in the list, easy there, the briefing again
  EXPECT_EQ(m.page().title, "Skirmish");
  EXPECT_EQ(m.difficulty(), Difficulty::Normal);
  std::vector<MenuRequest> launch = run(m, "left accept");  // easy, Launch
  ASSERT_EQ(launch.size(), 1u);
  EXPECT_EQ(launch[0].kind, MenuRequest::Kind::Launch);
  EXPECT_EQ(launch[0].level, kRoot + "/levels/skirmish.json");
  EXPECT_EQ(launch[0].difficulty, Difficulty::Easy);
  EXPECT_FALSE(m.open());

  const MissionResult r = fight(launch[0]);
  std::vector<MenuRequest> saved = m.show_results(launch[0].level, launch[0].difficulty, r);
  ASSERT_EQ(saved.size(), 1u);
  EXPECT_EQ(saved[0].kind, MenuRequest::Kind::SaveProgress);
  ASSERT_EQ(m.screen(), MenuScreen::Results);
  const MenuPage res = m.page();
  EXPECT_EQ(res.title, r.victory ? "VICTORY" : "DEFEAT");
  EXPECT_EQ(res.subtitle, "Skirmish (easy)");
  EXPECT_TRUE(has_line(res, "line: Kills             " + std::to_string(r.kills)));
  EXPECT_TRUE(has_line(res, r.victory ? "line: New best!" : "line: Your best try yet (no win so far)"));
  EXPECT_EQ(res.title_tone, r.victory ? 1 : -1);
  EXPECT_EQ(res.items, (std::vector<std::string>{"Retry", "Next mission: Arena", "Menu"}));
  EXPECT_EQ(m.progress().best.count("skirmish/easy"), 1u);

  std::vector<MenuRequest> next = run(m, "down accept");
  ASSERT_EQ(next.size(), 1u);
  EXPECT_EQ(next[0].level, kRoot + "/levels/arena.json");
  EXPECT_EQ(next[0].difficulty, Difficulty::Easy);
  // A worse result later keeps the best, and Menu leads back to the main menu.
  MissionResult worse = r;
  worse.victory = false;
  worse.damage_dealt = -1;
  EXPECT_TRUE(m.show_results(launch[0].level, Difficulty::Easy, worse).empty());
  EXPECT_TRUE(has_line(m.page(), "line: Best so far: "));
  run(m, "up accept");
  EXPECT_EQ(m.screen(), MenuScreen::Main);
  run(m, "accept");
  EXPECT_TRUE(has_line(m.page(), "3. Skirmish"));
  EXPECT_FALSE(has_line(m.page(), "3. Skirmish              best: no result yet"));
}

TEST(Menu, EffectsListTheGalleryAndLaunchIt) {
  Menu m = make_menu();
  run(m, "down accept");
  ASSERT_EQ(m.screen(), MenuScreen::Effects);
  EXPECT_EQ(m.page().items, (std::vector<std::string>{"Effect gallery", "Back"}));
  std::vector<MenuRequest> r = run(m, "accept");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].level, kRoot + "/levels/gallery.json");
}

int saves(const std::vector<MenuRequest>& r) {
  int n = 0;
  for (const MenuRequest& q : r) n += q.kind == MenuRequest::Kind::SaveSettings ? 1 : 0;
  return n;
}

// The settings screen leads to pages for players; the raw keys are under Advanced.
TEST(Menu, SettingsScreenListsItsPages) {
  Menu m = make_menu();
  run(m, "down down accept");
  ASSERT_EQ(m.screen(), MenuScreen::Settings);
  EXPECT_EQ(describe_page(m.page()),
            "title: SETTINGS\n> Graphics\n  Sound\n  Controls\n"
            "  Advanced: raw settings (0 of yours over the preset)\n  Reset progress\n  Back\n");
  const std::vector<MenuScreen> pages = {MenuScreen::Graphics, MenuScreen::Sound, MenuScreen::Controls,
                                         MenuScreen::Advanced};
  for (int row = 0; row < 4; ++row) {
    run(m, "accept");
    EXPECT_EQ(m.screen(), pages[size_t(row)]) << row;
    run(m, "back");
    EXPECT_EQ(m.screen(), MenuScreen::Settings);
    EXPECT_EQ(m.page().selection, row) << "back on the row that opened it";
    run(m, "down");
  }
}

// Graphics: the preset rated for the machine that draws, resolution scale, window, view.
TEST(Menu, GraphicsPageRatesThePresetForThisMachine) {
  Menu m = make_menu();
  m.set_machine("llvmpipe (LLVM 15.0.7, 256 bits)");
  run(m, "down down accept accept");
  ASSERT_EQ(m.screen(), MenuScreen::Graphics);
  EXPECT_EQ(describe_page(m.page()),
            "title: GRAPHICS\n"
            "subtitle: this machine: llvmpipe, a software rasteriser\n"
            "> Quality preset: < default >  light here\n"
            "  Resolution scale: < 1.00 >\n  Fullscreen: < off >\n  VSync: < on >\n  Field of view: < 60 > deg\n"
            "  Back\n"
            "message: default: made for a software rasteriser. Here: low light, default light, medium heavy, "
            "high too heavy, reference far too heavy\n");
  EXPECT_EQ(saves(run(m, "right")), 1);
  EXPECT_EQ(m.settings().quality, "medium");
  EXPECT_TRUE(has_line(m.page(), "> Quality preset: < medium >  heavy here\n"));
  EXPECT_TRUE(run(m, "right right right").size() == 2u) << "stops at reference";
  EXPECT_EQ(m.settings().quality, "reference");
  run(m, "left left left left left left");
  EXPECT_EQ(m.settings().quality, "low") << "stops at low: Left never wraps to reference";
  m.set_machine("NVIDIA H200/PCIe/SSE2");
  run(m, "right right");
  EXPECT_TRUE(has_line(m.page(), "< medium >  moderate here\n"));
  m.set_machine("");
  EXPECT_TRUE(has_line(m.page(), "< medium >  heavy on software, moderate on a GPU\n"));
  run(m, "left");
  EXPECT_TRUE(has_line(m.page(), "< default >  light anywhere\n"));
  run(m, "right");
  run(m, "down right");  // resolution scale over medium's 1.0
  EXPECT_EQ(m.settings().render.at("render.scale"), "1.25");
  EXPECT_TRUE(has_line(m.page(), "> Resolution scale: < 1.25 >"));
  EXPECT_EQ(saves(run(m, "down right down left down left")), 3);
  EXPECT_TRUE(m.settings().fullscreen);
  EXPECT_FALSE(m.settings().vsync);
  EXPECT_DOUBLE_EQ(m.settings().fov, 55);
}

// Sound: the master and effects volumes, mute, each group's volume and the radio subtitles,
// kept as the player's own audio.* values.
TEST(Menu, SoundPageSetsTheVolumes) {
  Menu m = make_menu();
  run(m, "down down accept down accept");
  ASSERT_EQ(m.screen(), MenuScreen::Sound);
  EXPECT_EQ(describe_page(m.page()),
            "title: SOUND\n> Master volume: < 80 % >\n  Effects volume: < 100 % >\n  Mute (M in the game): < off >\n"
            "  Music volume: < 100 % >\n  Weapons volume: < 100 % >\n  Hits and explosions volume: < 100 % >\n"
            "  Engines volume: < 100 % >\n  Interface and warnings volume: < 100 % >\n  Radio voices volume: < 100 % >\n"
            "  Radio subtitles: < on >\n  Back\n");
  EXPECT_EQ(saves(run(m, "right down left left down right")), 4);
  EXPECT_EQ(m.settings().render.at("audio.volume"), "0.9");
  EXPECT_EQ(m.settings().render.at("audio.effects_volume"), "0.8");
  EXPECT_EQ(m.settings().render.at("audio.mute"), "true");
  const Settings s = user_quality_settings(m.settings(), kRoot + "/assets/settings/quality.json");
  EXPECT_DOUBLE_EQ(s.number("audio.volume"), 0.9);
  EXPECT_TRUE(s.flag("audio.mute"));
  run(m, "up up right right");
  EXPECT_TRUE(has_line(m.page(), "> Master volume: < 100 % >")) << "no louder than full";
  EXPECT_EQ(saves(run(m, "down down down left down down down down down down right")), 2);
  EXPECT_EQ(m.settings().render.at("audio.music_volume"), "0.9");
  EXPECT_EQ(m.settings().render.at("audio.subtitles"), "false");
}

// Controls: mouse and gamepad, and the key remapping (a key another action has is swapped).
TEST(Menu, ControlsPageAndKeyRemapping) {
  Menu m = make_menu();
  run(m, "down down accept down down accept");
  ASSERT_EQ(m.screen(), MenuScreen::Controls);
  EXPECT_EQ(describe_page(m.page()),
            "title: CONTROLS\n> Mouse sensitivity: < 0.12 > deg/px\n  Invert Y: < off >\n"
            "  Gamepad dead zone: < 0.12 >\n  Remap keys\n  Back\n");
  std::vector<MenuRequest> r = run(m, "right right right down right down left");
  EXPECT_DOUBLE_EQ(m.settings().mouse_sensitivity, 0.15);
  EXPECT_TRUE(m.settings().invert_y);
  EXPECT_DOUBLE_EQ(m.settings().pad_deadzone, 0.10);
  EXPECT_EQ(saves(r), 5);
  run(m, "down accept");  // Remap keys
  ASSERT_EQ(m.screen(), MenuScreen::Keys);
  EXPECT_TRUE(has_line(m.page(), "> Fire beam               MOUSE_LEFT"));
  run(m, "accept");
  EXPECT_TRUE(m.capturing());
  EXPECT_TRUE(has_line(m.page(), "> Fire beam               press a key..."));
  run(m, "back");  // Esc cancels
  EXPECT_FALSE(m.capturing());
  EXPECT_EQ(m.page().message, "Remap cancelled");
  r = run(m, "accept bind SPACE");
  EXPECT_EQ(bound_key(m.bindings(), "fire_primary"), key_code("SPACE"));
  EXPECT_EQ(bound_key(m.bindings(), "strafe_up"), key_code("MOUSE_LEFT"));
  EXPECT_EQ(m.page().message, "SPACE was on Strafe up: Strafe up now uses MOUSE_LEFT");
  EXPECT_EQ(m.settings().keys.size(), 2u);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[1].kind, MenuRequest::Kind::ApplyBindings);
  run(m, "up accept");  // Back (the list wraps)
  EXPECT_EQ(m.screen(), MenuScreen::Controls);
  EXPECT_TRUE(has_line(m.page(), "> Remap keys"));
  run(m, "accept up up accept");  // Remap keys, Reset keys
  EXPECT_TRUE(m.settings().keys.empty());
  EXPECT_EQ(bound_key(m.bindings(), "fire_primary"), key_code("MOUSE_LEFT"));
}

// Advanced: the developer panel's switch, then every raw setting over the preset, stepped,
// marked as the player's, saved, reset.
TEST(Menu, AdvancedPageHoldsTheRawSettings) {
  Menu m = make_menu();
  run(m, "down down accept up up up accept");  // Settings, Advanced
  ASSERT_EQ(m.screen(), MenuScreen::Advanced);
  EXPECT_EQ(m.page().title, "ADVANCED");
  EXPECT_NE(m.page().subtitle.find("raw settings for developers"), std::string::npos);
  EXPECT_TRUE(has_line(m.page(), "> Developer panel (F1): < off >"));
  EXPECT_EQ(saves(run(m, "right")), 1);
  EXPECT_TRUE(m.settings().developer_panel);
  run(m, "down");
  EXPECT_TRUE(has_line(m.page(), "> render.soft_edges"));
  EXPECT_FALSE(m.page().message.empty()) << "the selected setting's doc line";
  std::vector<MenuRequest> r = run(m, "right");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].kind, MenuRequest::Kind::SaveSettings);
  ASSERT_EQ(m.settings().render.size(), 1u);
  const std::string chosen = m.settings().render.at("render.soft_edges");
  EXPECT_TRUE(has_line(m.page(), "< " + chosen + " >  *"));
  EXPECT_EQ(user_quality_settings(m.settings(), kRoot + "/assets/settings/quality.json").choice("render.soft_edges"),
            chosen);
  run(m, "up up up accept");  // Back to the preset's values
  EXPECT_TRUE(m.settings().render.empty());
  run(m, "back");
  EXPECT_TRUE(has_line(m.page(), "> Advanced: raw settings (0 of yours over the preset)"));
}

// No value changes by Enter or a click alone: the first asks, a second confirms, and any
// other input in between takes the question back. Every value row of every settings page.
TEST(Menu, NoSettingChangesWithoutLeftRightOrAConfirmation) {
  const std::vector<std::pair<std::string, int>> pages = {
      {"accept", 5}, {"down accept", 3}, {"down down accept", 3}, {"up up up accept", 2}};
  for (const auto& [open, values] : pages) {
    for (int row = 0; row < values; ++row) {
      Menu m = make_menu();
      run(m, "down down accept " + open);
      for (int i = 0; i < row; ++i) run(m, "down");
      const std::string where = open + " row " + std::to_string(row);
      const UserSettings before = m.settings();
      EXPECT_TRUE(run(m, "accept").empty()) << where;
      EXPECT_EQ(m.settings(), before) << where << ": Enter alone changed it";
      EXPECT_NE(describe_page(m.page()).find("Enter again to change it"), std::string::npos) << where;
      EXPECT_TRUE(run(m, "down up accept").empty()) << where << ": moving away takes the question back";
      EXPECT_EQ(m.settings(), before) << where;
      run(m, "down up");
      EXPECT_TRUE(m.handle(UiInput::click(row)).empty()) << where << ": a click asks too";
      EXPECT_EQ(m.settings(), before) << where;
      EXPECT_GE(saves(m.handle(UiInput::click(row))), 1) << where << ": the second click confirms";
      EXPECT_NE(m.settings(), before) << where;
    }
  }
}

TEST(Menu, ResettingProgressAsksTwice) {
  Menu m = make_menu();
  m.show_results(kRoot + "/levels/duel.json", Difficulty::Normal, {true, 40, 1});
  run(m, "down down accept");  // Results: Retry, Next, Menu
  run(m, "down down accept");  // Settings
  run(m, "up up");
  EXPECT_TRUE(has_line(m.page(), "> Reset progress"));
  EXPECT_TRUE(run(m, "accept").empty());
  EXPECT_TRUE(has_line(m.page(), "> Reset progress: press again to confirm"));
  EXPECT_EQ(m.progress().best.size(), 1u);
  std::vector<MenuRequest> r = run(m, "accept");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].kind, MenuRequest::Kind::SaveProgress);
  EXPECT_TRUE(m.progress().best.empty());
}

// F1: the developer panel only with --dev or the player's setting; it pauses a fight while
// open and resumes what it paused.
TEST(DevPanel, F1NeedsDevOrTheSettingAndPausesTheFight) {
  EXPECT_FALSE(f1_toggles_panel(false, false, false)) << "a player's game: F1 does nothing";
  EXPECT_TRUE(f1_toggles_panel(true, false, false));
  EXPECT_TRUE(f1_toggles_panel(false, true, false));
  EXPECT_TRUE(f1_toggles_panel(false, false, true)) << "an open panel always closes";
  DevPanelGate gate;
  EXPECT_EQ(gate.follow(false, true, false), std::nullopt);
  EXPECT_EQ(gate.follow(true, true, false), Command::Pause);
  EXPECT_EQ(gate.follow(true, true, true), std::nullopt);
  EXPECT_EQ(gate.follow(false, true, true), Command::Resume);
  // Over a game the player had paused, or over the menu: nothing to pause, nothing to resume.
  EXPECT_EQ(gate.follow(true, true, true), std::nullopt);
  EXPECT_EQ(gate.follow(false, true, true), std::nullopt);
  EXPECT_EQ(gate.follow(true, false, false), std::nullopt);
  EXPECT_EQ(gate.follow(false, false, false), std::nullopt);
}

// The mouse: items are hit-tested against the boxes the layout drew.
TEST(Menu, MouseHoverAndClickFollowTheLayout) {
  Menu m = make_menu();
  HudLayer layer;
  std::vector<HudBox> boxes;
  layout_menu(m.page(), 1920, 1080, layer, &boxes);
  ASSERT_EQ(boxes.size(), 5u);
  EXPECT_FALSE(layer.texts.empty());
  const HudBox& settings = boxes[2];
  const double x = (settings.x0 + settings.x1) / 2, y = (settings.y0 + settings.y1) / 2;
  EXPECT_EQ(menu_item_at(boxes, x, y), 2);
  EXPECT_EQ(menu_item_at(boxes, 1, 1), -1);
  m.handle(UiInput::hover(menu_item_at(boxes, x, y)));
  EXPECT_TRUE(has_line(m.page(), "> Settings"));
  m.handle(UiInput::click(2));
  EXPECT_EQ(m.screen(), MenuScreen::Settings);
  // The long controls list scrolls: only the rows on screen get boxes.
  run(m, "down down accept down down down accept");  // Controls, Remap keys
  ASSERT_EQ(m.screen(), MenuScreen::Keys);
  layout_menu(m.page(), 1280, 720, layer, &boxes);
  EXPECT_GT(boxes.size(), 20u);
  EXPECT_GE(boxes[0].x1, 0);
  EXPECT_LT(boxes.back().x1, 0);
}

// Devices to menu inputs: keys by their presses, the gamepad by its edges, the mouse by the boxes.
TEST(MenuInput, KeysGamepadAndMouseBecomeUiInputs) {
  InputState before, now;
  now.keys[size_t(key_code("DOWN"))] = true;
  now.key_presses[size_t(key_code("DOWN"))] = 2;  // two taps within the frame
  now.keys[size_t(key_code("ENTER"))] = true;
  now.gamepad_present = true;
  now.gamepad_buttons[size_t(gamepad_button_code("B"))] = true;
  now.gamepad_axes[size_t(gamepad_axis_code("LEFT_Y"))] = -0.9f;  // stick up
  const std::vector<HudBox> boxes = {{0, 0, 100, 20}, {0, 30, 100, 50}};
  now.mouse_x = 50;
  now.mouse_y = 40;
  now.mouse_buttons[0] = true;
  std::vector<UiInput> in = menu_inputs(before, now, false, boxes);
  std::vector<std::string> seen;
  for (const UiInput& i : in)
    seen.push_back(i.kind == UiInput::Kind::Key     ? "key " + std::to_string(int(i.key))
                   : i.kind == UiInput::Kind::Hover ? "hover " + std::to_string(i.item)
                   : i.kind == UiInput::Kind::Click ? "click " + std::to_string(i.item)
                                                    : "bind");
  EXPECT_EQ(seen, (std::vector<std::string>{"key 1", "key 1", "key 4", "key 5", "key 0", "hover 1", "click 1"}));
  // Held, nothing new: no input. While a remap waits, a key is a bind and Esc cancels.
  InputState held = now;
  held.key_presses = {};
  held.mouse_presses = {};
  EXPECT_TRUE(menu_inputs(now, held, false, boxes).empty());
  InputState space = before;
  space.keys[size_t(key_code("SPACE"))] = true;
  in = menu_inputs(before, space, true, boxes);
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].kind, UiInput::Kind::Bind);
  EXPECT_EQ(in[0].code, key_code("SPACE"));
  InputState pad = before;
  pad.gamepad_present = true;
  pad.gamepad_buttons[size_t(gamepad_button_code("X"))] = true;
  in = menu_inputs(before, pad, true, boxes);
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].code, kPadButtonBase + gamepad_button_code("X"));
  InputState esc = before;
  esc.keys[size_t(key_code("ESCAPE"))] = true;
  in = menu_inputs(before, esc, true, boxes);
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].key, UiKey::Back);
}

// The pause screen, as a game started with --level has it: no main menu behind.
PauseState undecided_pause() {
  PauseState s;
  s.playing = s.next = Difficulty::Normal;
  s.volume = 0.7;
  return s;
}

std::vector<MenuRequest::Kind> kinds(const std::vector<MenuRequest>& r) {
  std::vector<MenuRequest::Kind> out;
  for (const MenuRequest& q : r) out.push_back(q.kind);
  return out;
}

TEST(PauseMenu, OpensWithThePauseAndListsItsItems) {
  Menu m{UserFiles{}};
  EXPECT_FALSE(m.open());
  EXPECT_FALSE(m.has_main());
  EXPECT_TRUE(run(m, "accept down back").empty()) << "closed: no input acts";
  m.pause(undecided_pause());
  ASSERT_EQ(m.screen(), MenuScreen::Pause);
  EXPECT_TRUE(m.open());
  EXPECT_FALSE(m.over_game()) << "the ship keeps its devices' state, the game is paused";
  EXPECT_EQ(describe_page(m.page()),
            "title: PAUSED\n"
            "> Resume\n  Restart\n  Difficulty: < normal >\n  Sound: on (M)\n  Volume: < 70% >\n  Quit\n");
  EXPECT_NE(m.page().hint.find("Esc: resume"), std::string::npos);
  run(m, "down down");
  m.pause(undecided_pause());  // shown again each frame: the selection stays
  EXPECT_TRUE(has_line(m.page(), "> Difficulty"));
  m.close_pause();
  EXPECT_FALSE(m.open());
  m.pause(undecided_pause());  // paused again: from the top
  EXPECT_TRUE(has_line(m.page(), "> Resume"));
}

TEST(PauseMenu, LabelsFollowTheRecordingTheOutcomeAndTheNextDifficulty) {
  Menu m{UserFiles{}};
  PauseState s = undecided_pause();
  s.recording = true;
  s.next = Difficulty::Hard;
  s.muted = true;
  m.pause(s);
  EXPECT_EQ(m.page().items, (std::vector<std::string>{"Resume", "Restart (ends the recording)",
                                                      "Difficulty: < hard > (applies on restart)", "Sound: muted (M)",
                                                      "Volume: < 70% >", "Quit"}));
  m.close_pause();
  s.outcome = "DEFEAT";
  s.outcome_tone = -1;
  s.recording = false;
  m.pause(s);
  const MenuPage p = m.page();
  EXPECT_EQ(p.title, "DEFEAT");
  EXPECT_EQ(p.title_tone, -1);
  EXPECT_EQ(p.items[0], "Retry");
  EXPECT_EQ(p.items[1], "Resume");
  EXPECT_EQ(p.items[2], "Difficulty: < hard > (applies on retry)");
  EXPECT_EQ(p.selection, 0);
  EXPECT_EQ(kinds(run(m, "accept")), std::vector<MenuRequest::Kind>{MenuRequest::Kind::Restart});
}

TEST(PauseMenu, ItemsAskForWhatTheyDo) {
  using K = MenuRequest::Kind;
  Menu m{UserFiles{}};
  PauseState s = undecided_pause();
  m.pause(s);
  EXPECT_EQ(kinds(run(m, "accept")), std::vector<K>{K::Resume});
  EXPECT_EQ(kinds(run(m, "back")), std::vector<K>{K::Resume}) << "Esc resumes";
  EXPECT_EQ(kinds(run(m, "down accept")), std::vector<K>{K::Restart});
  EXPECT_EQ(kinds(run(m, "up up accept")), std::vector<K>{K::Quit}) << "the list wraps";
  // Difficulty: Left/Right step it, Enter steps it up and wraps; it is the next restart's.
  std::vector<MenuRequest> r = run(m, "down down down right");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].kind, K::SetDifficulty);
  EXPECT_EQ(r[0].difficulty, Difficulty::Hard);
  EXPECT_EQ(run(m, "left")[0].difficulty, Difficulty::Easy);
  s.next = Difficulty::Hard;
  m.pause(s);
  EXPECT_EQ(run(m, "accept")[0].difficulty, Difficulty::Easy);
  EXPECT_EQ(kinds(run(m, "down accept")), std::vector<K>{K::ToggleMute});
  EXPECT_TRUE(run(m, "left right").empty()) << "Sound has no steps";
  // Volume: tenths by Left/Right; Enter one up, from full back to silent.
  r = run(m, "down left right right");
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0].kind, K::StepVolume);
  EXPECT_EQ(r[0].steps, -1);
  EXPECT_EQ(r[2].steps, 1);
  EXPECT_EQ(run(m, "accept")[0].steps, 1);
  s.volume = 1.0;
  m.pause(s);
  EXPECT_EQ(run(m, "accept")[0].steps, -10);
  EXPECT_EQ(kinds(run(m, "down accept")), std::vector<K>{K::Quit}) << "no main menu behind --level";
}

// Started from the main menu the pause screen leads back there; it never covers another screen.
TEST(PauseMenu, FromTheMainMenuItLeadsBack) {
  Menu m = make_menu();
  m.pause(undecided_pause());
  EXPECT_EQ(m.screen(), MenuScreen::Main) << "the menu is not a paused game";
  const std::vector<MenuRequest> launch = run(m, "accept accept accept");  // Play, Duel, Launch
  ASSERT_EQ(kinds(launch), std::vector<MenuRequest::Kind>{MenuRequest::Kind::Launch});
  PauseState s = undecided_pause();
  s.recording = true;
  m.pause(s);
  ASSERT_EQ(m.screen(), MenuScreen::Pause);
  EXPECT_TRUE(has_line(m.page(), "  Main menu (ends the recording)\n  Quit\n"));
  EXPECT_EQ(kinds(run(m, "up up accept")), std::vector<MenuRequest::Kind>{MenuRequest::Kind::MainMenu});
  m.open_main();
  EXPECT_EQ(m.screen(), MenuScreen::Main);
  // The fight decided while paused: the results replace the pause screen.
  run(m, "accept accept accept");
  m.pause(s);
  ASSERT_EQ(m.screen(), MenuScreen::Pause);
  m.show_results(launch[0].level, Difficulty::Normal, {true, 40, 1});
  EXPECT_EQ(m.screen(), MenuScreen::Results);
  m.close_pause();
  m.pause(s);
  EXPECT_EQ(m.screen(), MenuScreen::Results);
}

TEST(PauseMenu, StateOfADecidedWorld) {
  GameOptions o;
  o.root_dir = kRoot;
  o.difficulty = Difficulty::Hard;
  o.difficulty_override = true;
  Game g = Game::load_level(kRoot + "/levels/duel.json", o);
  EXPECT_EQ(pause_state_of(g.world()).outcome, "");
  EXPECT_EQ(pause_state_of(g.world()).playing, Difficulty::Hard);
  g.world_mut().outcome = Outcome::Victory;
  EXPECT_EQ(pause_state_of(g.world()).outcome, "VICTORY");
  EXPECT_EQ(pause_state_of(g.world()).outcome_tone, 1);
  g.world_mut().outcome = Outcome::Defeat;
  EXPECT_EQ(pause_state_of(g.world()).outcome_tone, -1);
}

// Drawn by layout_menu: the verdict above the items, every label on screen, and the mouse
// hovers and clicks the items.
TEST(PauseMenu, LaidOutWithTheVerdictAboveAndMouseBoxes) {
  Menu m = make_menu();
  run(m, "accept accept accept");
  PauseState s = undecided_pause();
  s.outcome = "DEFEAT";
  s.outcome_tone = -1;
  s.next = Difficulty::Hard;
  s.recording = true;
  m.pause(s);
  HudLayer layer;
  std::vector<HudBox> boxes;
  layout_menu(m.page(), 1280, 720, layer, &boxes);
  ASSERT_EQ(boxes.size(), 7u);
  const HudText* title = nullptr;
  for (const HudText& t : layer.texts) {
    if (t.text == "DEFEAT") title = &t;
    const HudBox b = text_box(t);
    EXPECT_GE(b.x0, 0.0) << t.text;
    EXPECT_LE(b.x1, 1280.0) << t.text;
  }
  ASSERT_NE(title, nullptr);
  EXPECT_LT(text_box(*title).y1, boxes[0].y0);
  m.handle(UiInput::hover(menu_item_at(boxes, (boxes[1].x0 + boxes[1].x1) / 2, (boxes[1].y0 + boxes[1].y1) / 2)));
  EXPECT_TRUE(has_line(m.page(), "> Resume"));
  EXPECT_EQ(kinds(m.handle(UiInput::click(5))), std::vector<MenuRequest::Kind>{MenuRequest::Kind::MainMenu});
}

TEST(Menu, BadScriptWordsArePositioned) {
  try {
    parse_ui_inputs("accept\ndown jump\n", "s.ui");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("s.ui:2:6: unknown UI input 'jump'", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace arc
