// game/app/menu_input.h — keyboard, mouse and gamepad to the menu's UiInputs (no GL).
//
// Arrows move, Enter or Space accepts, Esc or Backspace goes back; the mouse hovers and clicks
// the items it is over (hit-tested against the boxes layout_menu() drew); a gamepad's D-pad or
// left stick moves, A accepts and B goes back. While a remap waits for a key, the next key or
// mouse button pressed (Esc excepted: it cancels) is sent as UiInput::bind.
//
// Example, compiled as AppExamples.MenuInputs in tests/unit/app/test_app_examples.cpp:
//   std::vector<UiInput> in = menu_inputs(previous, now, menu.capturing(), boxes);
#pragma once
#include <vector>

#include "game/app/menu.h"
#include "game/render/hud_layout.h"
#include "platform/platform.h"

namespace arc {

std::vector<UiInput> menu_inputs(const InputState& before, const InputState& now, bool capturing,
                                 const std::vector<HudBox>& item_boxes);

}  // namespace arc
