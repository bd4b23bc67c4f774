// tests/unit/app/menu_script.h — what the menu tests share: a menu over the shipped data, a
// script of UI inputs fed to it, and a line looked up in the page it shows.
#pragma once
#include <string>
#include <vector>

#include "core/data_root.h"
#include "game/app/menu.h"
#include "game/app/menu_input.h"
#include "game/app/menu_snapshots.h"

namespace arc::menu_test {

// The menu over the shipped levels, bindings and quality presets, with `files` as the player's.
inline Menu shipped_menu(UserFiles files = {}) {
  const std::string root = data_root();
  Bindings b = load_bindings(root + "/assets/settings/bindings.json");
  return Menu(load_mission_catalog(root + "/levels", root), std::move(files), b, b,
              root + "/assets/settings/quality.json");
}

// Feeds the script's inputs; returns every request they made.
inline std::vector<MenuRequest> run(Menu& m, const std::string& script) {
  std::vector<MenuRequest> all;
  for (const UiInput& in : parse_ui_inputs(script, "script")) {
    std::vector<MenuRequest> r = m.handle(in);
    all.insert(all.end(), r.begin(), r.end());
  }
  return all;
}

inline bool has_line(const MenuPage& p, const std::string& text) {
  return describe_page(p).find(text) != std::string::npos;
}

}  // namespace arc::menu_test
