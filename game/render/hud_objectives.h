// game/render/hud_objectives.h — a mission's objectives on the HUD with their state (game/render/hud_objectives.cpp).
//
// Under the objective line, one row per objective the player may see (hidden ones once an event
// has revealed them): "[ ]" pending in white, "[+]" done in green, "[x]" failed in red;
// secondary objectives are marked "(bonus)".
#pragma once
#include <string>

#include "gfx/render_view.h"

namespace arc {

class World;

// Draws the rows from y0 at x (canvas units). Returns the bottom of what it drew (y0 when nothing).
double hud_objectives(const World& w, double x, double y0, HudLayer& h);
// One row's text, as drawn: "[+] Escort the Hauler", "[ ] (bonus) Down the scout".
std::string objective_row(const World& w, size_t index);

}  // namespace arc
