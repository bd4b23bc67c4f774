// game/render/hud_comms.h — the comms menu on the HUD: the four wing orders under keys 1..4,
// the wing's current order marked (game/render/hud_comms.cpp; no GL).
#pragma once
#include "gfx/render_view.h"

namespace arc {

class World;

// The menu's lines, top to bottom (tests read them).
inline constexpr const char* kCommsOrders[4] = {"1  Attack my target", "2  Cover me", "3  Form up", "4  Engage at will"};

// Draws the menu on the left, below the middle of a width × height canvas (hud_draw.h units).
void hud_comms_menu(const World& w, int width, int height, HudLayer& h);

}  // namespace arc
