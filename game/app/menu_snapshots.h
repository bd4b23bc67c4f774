// game/app/menu_snapshots.h — the menu's screens as text and a script of UI inputs, and
// `arcfire --headless --menu-script FILE --out DIR`: the menu driven by such a script without a
// window, a snapshot of every screen.
//
// The script is parse_ui_inputs() text: words like `accept down right back`,
// `click N`, `bind KEY`. The attract demo runs behind the menu as in the window. After each
// input the screen is written as DIR/NN_SCREEN.png and its text as DIR/NN_SCREEN.txt
// (describe_page). A launched level is fought without input until it is decided (at most
// --ticks, default 2 minutes of game time) and the results screen opens over it, as in the
// window; the player's settings and progress are read and written in user_config_dir().
// Without --out only the texts are printed, and no GL context is made. SIGINT or SIGTERM stops
// it at the end of the tick (the screens written so far stay), with exit code 130 or 143.
#pragma once
#include <string>
#include <vector>

#include "game/app/app_options.h"
#include "game/app/menu.h"

namespace arc {

// A scripted sequence of UI inputs, one per word or "click N" / "hover N" / "bind KEY" pair:
// up down left right accept back. InputError "path:line:col: ..." for anything else.
std::vector<UiInput> parse_ui_inputs(const std::string& text, const std::string& path);

// A screen as text, one line per element ("title: ...", "> item" for the selected one): the
// snapshots of the menu test and of `arcfire --menu-script`.
std::string describe_page(const MenuPage& p);

int run_menu_script(const AppOptions& options);

}  // namespace arc
