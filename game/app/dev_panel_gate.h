// game/app/dev_panel_gate.h — when F1 opens the developer panel, and the pause it brings.
//
// The tweak panel (game/workbench/game_panel.h) is for developers: F1 opens it only with
// `--dev` or the player's "developer panel" setting (Settings → Advanced), and always closes
// it. Opened over a fight it pauses the game, and closing it (F1 or its own close button)
// resumes what it paused; a game paused before stays paused. No GL: tested without a window.
// On F1 the window asks f1_toggles_panel() with --dev, the setting and whether the panel is
// open; each frame it tells DevPanelGate::follow() the panel's state, whether a fight is shown
// and whether the game is paused, and sends the Command it returns (pause or resume) to the
// game's next tick. DevPanel.* in tests/unit/app/test_menu.cpp drives both.
#pragma once
#include <optional>

#include "game/sim/input.h"

namespace arc {

inline bool f1_toggles_panel(bool dev_flag, bool setting, bool panel_open) {
  return dev_flag || setting || panel_open;
}

class DevPanelGate {
 public:
  // Called once a frame with the panel's state: Pause when it has just opened over a running
  // fight, Resume when the panel that paused it has just closed.
  std::optional<Command> follow(bool panel_open, bool in_fight, bool game_paused) {
    const bool opened = panel_open && !was_open_, closed = !panel_open && was_open_;
    was_open_ = panel_open;
    if (opened && in_fight && !game_paused) {
      paused_ = true;
      return Command::Pause;
    }
    if (closed && paused_) {
      paused_ = false;
      return Command::Resume;
    }
    return std::nullopt;
  }

 private:
  bool was_open_ = false;
  bool paused_ = false;  // this panel paused the game
};

}  // namespace arc
