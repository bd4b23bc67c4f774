// tests/unit/app/test_menu_net.cpp — the menu's Multiplayer pages driven by scripted key presses
// (game/app/menu_net.cpp): Host asks for the chosen mission, difficulty and port; Join takes an
// address typed key by key, remembers it among the recent hosts and offers it next time; the
// pilot's name is edited and validated; the lobby lists the slots, lets a pilot pick a free one,
// gives the host Launch, and Esc leaves.
#include <gtest/gtest.h>

#include "core/data_root.h"
#include "game/app/menu.h"
#include "menu_script.h"
#include "game/app/menu_snapshots.h"

namespace arc {
namespace {

using menu_test::run;
using menu_test::has_line;
const std::string kRoot = arc::data_root();

Menu make_menu(UserFiles files = {}) {
  Menu m = menu_test::shipped_menu(std::move(files));
  m.set_net_missions({{kRoot + "/levels/duel.json", "Duel"}, {kRoot + "/levels/arena.json", "Arena"}});
  return m;
}

TEST(MenuNet, HostAsksForTheMissionDifficultyAndPort) {
  Menu m = make_menu();
  run(m, "down down down accept");  // Multiplayer
  ASSERT_EQ(m.screen(), MenuScreen::Multiplayer);
  EXPECT_EQ(m.page().items, (std::vector<std::string>{"Host a match", "Join a match", "Pilot name: Pilot", "Back"}));
  run(m, "accept");  // Host a match
  ASSERT_EQ(m.screen(), MenuScreen::NetHost);
  EXPECT_TRUE(has_line(m.page(), "> Mission: < Duel >"));
  run(m, "right down right down right right");  // Arena, hard, port 27962
  EXPECT_TRUE(has_line(m.page(), "Difficulty: < hard >"));
  EXPECT_TRUE(has_line(m.page(), "Port: < 27962 >"));
  std::vector<MenuRequest> r = run(m, "down accept");  // Open the lobby
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].kind, MenuRequest::Kind::NetHost);
  EXPECT_EQ(r[0].level, kRoot + "/levels/arena.json");
  EXPECT_EQ(r[0].difficulty, Difficulty::Hard);
  EXPECT_EQ(r[0].steps, 27962);
  run(m, "back back");
  EXPECT_EQ(m.screen(), MenuScreen::Main);
  EXPECT_EQ(m.page().selection, 3) << "back on Multiplayer";
}

TEST(MenuNet, JoinTakesATypedAddressAndRemembersIt) {
  Menu m = make_menu();
  run(m, "down down down accept down accept");  // Multiplayer, Join a match
  ASSERT_EQ(m.screen(), MenuScreen::NetJoin);
  EXPECT_TRUE(run(m, "down accept").size() == 0u) << "Join without an address says so";
  EXPECT_TRUE(has_line(m.page(), "message: Type the host's address first"));
  run(m, "up accept bind 1 bind 0 bind PERIOD bind 0 bind PERIOD bind 0 bind PERIOD bind 2 bind SEMICOLON bind 2 bind 7 "
         "bind 9 bind 6 bind 1 bind BACKSPACE bind 2");
  EXPECT_TRUE(m.editing());
  EXPECT_TRUE(has_line(m.page(), "> Address: 10.0.0.2:27962_"));
  run(m, "bind ENTER");
  EXPECT_FALSE(m.editing());
  std::vector<MenuRequest> r = run(m, "down accept");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].kind, MenuRequest::Kind::SaveSettings);
  EXPECT_EQ(r[1].kind, MenuRequest::Kind::NetJoin);
  EXPECT_EQ(r[1].level, "10.0.0.2:27962");
  ASSERT_EQ(m.settings().recent_hosts, (std::vector<std::string>{"10.0.0.2:27962"}));
  // A new start with the saved settings offers the host under the address.
  UserFiles files;
  files.settings = m.settings();
  Menu again = make_menu(files);
  run(again, "down down down accept down accept");
  EXPECT_TRUE(has_line(again.page(), "  Recent: 10.0.0.2:27962"));
  r = run(again, "down down accept");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[1].level, "10.0.0.2:27962");
}

TEST(MenuNet, ThePilotNameIsEditedAndAnEmptyOneRefused) {
  Menu m = make_menu();
  run(m, "down down down accept down down accept");  // Pilot name
  for (int i = 0; i < 5; ++i) run(m, "bind BACKSPACE");
  run(m, "bind A bind N bind N bind ENTER");
  EXPECT_EQ(m.settings().net_name, "ann");
  run(m, "accept bind BACKSPACE bind BACKSPACE bind BACKSPACE");
  std::vector<MenuRequest> r = run(m, "bind ENTER");
  EXPECT_EQ(m.settings().net_name, "Pilot");
  EXPECT_TRUE(has_line(m.page(), "message: A pilot name has 1 to 24 printable characters"));
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].kind, MenuRequest::Kind::SaveSettings);
}

TEST(MenuNet, TheLobbyListsSlotsPicksLaunchesAndLeaves) {
  Menu m = make_menu();
  NetLobbyView v;
  v.status = "In the lobby of 10.0.0.2:27960 (levels/arena.json); waiting for the host's launch";
  v.rows = {"0    blue  Alpha 1       Host                     host", "1    blue  Alpha 2       Ann (you)                12 ms",
            "2    red   Red 1         (AI)"};
  v.free = {false, false, true};
  m.open_lobby(v);
  ASSERT_EQ(m.screen(), MenuScreen::Lobby);
  EXPECT_EQ(m.page().items.back(), "Leave");
  EXPECT_TRUE(has_line(m.page(), "line: Slot Team   Ship            Pilot                        Ping"));
  EXPECT_TRUE(has_line(m.page(), "  2    red   Red 1         (AI)"));
  EXPECT_TRUE(run(m, "up up accept").empty()) << "a taken slot is not picked";
  std::vector<MenuRequest> r = run(m, "down accept");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].kind, MenuRequest::Kind::NetPick);
  EXPECT_EQ(r[0].steps, 2);
  v.host = true;
  m.open_lobby(v);
  EXPECT_EQ(m.page().items[3], "Launch");
  r = run(m, "accept");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].kind, MenuRequest::Kind::NetLaunch);
  r = run(m, "back");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].kind, MenuRequest::Kind::NetLeave);
  EXPECT_EQ(m.screen(), MenuScreen::Multiplayer);
  // Started from the command line, leaving the lobby closes the game.
  v.standalone = true;
  m.open_lobby(v);
  r = run(m, "back");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[1].kind, MenuRequest::Kind::Quit);
}

}  // namespace
}  // namespace arc
