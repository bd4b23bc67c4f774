// game/app/menu_snapshots.h — `arcfire --headless --menu-script FILE --out DIR`: the menu driven
// by a script of UI inputs without a window, a snapshot of every screen.
//
// The script is parse_ui_inputs() text (menu.h): words like `accept down right back`,
// `click N`, `bind KEY`. The attract demo runs behind the menu as in the window. After each
// input the screen is written as DIR/NN_SCREEN.png and its text as DIR/NN_SCREEN.txt
// (describe_page). A launched level is fought without input until it is decided (at most
// --ticks, default 2 minutes of game time) and the results screen opens over it, as in the
// window; the player's settings and progress are read and written in user_config_dir().
// Without --out only the texts are printed, and no GL context is made. SIGINT or SIGTERM stops
// it at the end of the tick (the screens written so far stay), with exit code 130 or 143.
#pragma once
#include "game/app/app_options.h"

namespace arc {

int run_menu_script(const AppOptions& options);

}  // namespace arc
