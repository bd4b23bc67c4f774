// game/render/menu_layout.h — the main menu, mission select, briefing, settings and results
// screens drawn as HUD quads and text (no GL), over whatever the game shows behind them.
//
// MenuPage is what one screen shows, as plain text: the menu logic (game/app/menu.h) fills it,
// layout_menu() places it on the 720-unit HUD canvas (hud_draw.h) and scales it to the
// window. The boxes of the items come back in window pixels, so the app can hit-test the
// mouse against exactly what was drawn.
//
// Example, compiled as AppExamples.LayOutAMenu in tests/unit/app/test_app_examples.cpp:
//   MenuPage page = menu.page();
//   std::vector<HudBox> boxes;
//   layout_menu(page, 1280, 720, view.hud, &boxes);   // appended to the frame's HUD layer
#pragma once
#include <string>
#include <vector>

#include "game/render/hud_layout.h"
#include "gfx/render_view.h"

namespace arc {

struct MenuPage {
  std::string title;               // large, at the top
  int title_tone = 0;              // 1: good news (green, a victory), -1: bad (red, a defeat), 0: plain
  std::string subtitle;            // under it (a mission's objective, a results verdict)
  std::string paragraph;           // wrapped text (a briefing); "" for none
  std::vector<std::string> lines;  // a table of plain lines (results, best so far)
  std::vector<std::string> items;  // the selectable rows
  int selection = 0;
  int first = 0, rows = 0;         // a long list shows `rows` items from `first` (0 rows: all)
  std::string message;             // a notice or an error at the bottom (a corrupt settings file, a remap conflict)
  std::string hint;                // the keys that work here
};

// Appends the page to `out` (a full-screen dim behind it); `item_boxes`, when given, receives
// one box per item in window pixels (empty boxes for the items scrolled out of view).
void layout_menu(const MenuPage& page, int width, int height, HudLayer& out, std::vector<HudBox>* item_boxes);

// The item under a point in window pixels, or −1.
int menu_item_at(const std::vector<HudBox>& boxes, double x, double y);

}  // namespace arc
