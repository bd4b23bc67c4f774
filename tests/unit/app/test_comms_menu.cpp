// The comms menu: its key opens it, 1..4 give the wing orders as commands (recorded like the
// order keys), and its key again or Escape closes it without pausing the game.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/data_root.h"
#include "game/app/input_bindings.h"
#include "game/app/key_remap.h"

namespace {

const std::string kDefaultBindings = arc::data_root() + "/assets/settings/bindings.json";

// Presses `key` (one frame down, the next up) and returns the commands of those frames.
std::vector<arc::Command> tap(arc::LiveInput& in, const char* key) {
  arc::InputState s;
  s.keys[size_t(arc::key_code(key))] = true;
  in.sample(s);
  in.sample(arc::InputState{});
  return in.take_commands();
}

bool paused_by(arc::LiveInput& in) {
  const std::vector<arc::AppAction> a = in.take_actions();
  return std::count(a.begin(), a.end(), arc::AppAction::TogglePause) > 0;
}

TEST(CommsMenu, NumberKeysGiveTheOrdersInTheMenusOrder) {
  arc::LiveInput in(arc::load_bindings(kDefaultBindings));
  in.sample(arc::InputState{});
  const arc::Command orders[] = {arc::Command::OrderAttack, arc::Command::OrderCover, arc::Command::OrderFormUp,
                                 arc::Command::OrderEngage};
  const char* keys[] = {"1", "2", "3", "4"};
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(tap(in, keys[i]).empty()) << "closed: " << keys[i] << " is no order";
    EXPECT_TRUE(tap(in, "B").empty());
    EXPECT_TRUE(in.comms_open());
    EXPECT_EQ(tap(in, keys[i]), std::vector<arc::Command>{orders[i]}) << keys[i];
    EXPECT_FALSE(in.comms_open());
  }
}

TEST(CommsMenu, ItsKeyOrEscapeClosesItWithoutPausing) {
  arc::LiveInput in(arc::load_bindings(kDefaultBindings));
  in.sample(arc::InputState{});
  tap(in, "B");
  tap(in, "B");
  EXPECT_FALSE(in.comms_open());
  tap(in, "B");
  in.take_actions();
  EXPECT_TRUE(tap(in, "ESCAPE").empty());
  EXPECT_FALSE(in.comms_open());
  EXPECT_FALSE(paused_by(in));
  tap(in, "ESCAPE");
  EXPECT_TRUE(paused_by(in));  // closed, Escape is the pause key again
}

TEST(CommsMenu, ItsKeyIsRemappable) {
  arc::Bindings b = arc::load_bindings(kDefaultBindings);
  EXPECT_EQ(arc::bound_key(b, "comms"), arc::key_code("B"));
  b.comms = arc::key_code("K");
  arc::LiveInput in(b);
  in.sample(arc::InputState{});
  tap(in, "B");
  EXPECT_FALSE(in.comms_open());
  tap(in, "K");
  EXPECT_TRUE(in.comms_open());
}

}  // namespace
