// game/render/hud_comms.cpp — the comms menu: a dark box on the left with the wing orders.
#include "game/render/hud_comms.h"

#include <string>

#include "game/render/hud_draw.h"
#include "game/sim/world.h"

namespace arc {

void hud_comms_menu(const World& w, int width, int height, HudLayer& h) {
  const double x = 20.0, row = 18.0, box_w = 220.0;
  const double top = height * 0.45;
  const Wingman* lead = nullptr;  // the first live wingman's order is the wing's
  int alive = 0;
  for (const Wingman& m : w.wing)
    if (w.ship(m.ship).alive && alive++ == 0) lead = &m;
  quad(h, x - 8, top - 8, box_w, row * 6 + 16, {0.02f, 0.06f, 0.12f, 0.8f});
  text(h, x, top, 1.0, kHudWhite, alive ? "COMMS: wing orders" : "COMMS: no wingmen");
  for (int i = 0; i < 4; ++i) {
    const bool current = lead && static_cast<int>(lead->order) == (i + 1) % 4;
    const std::string line = std::string(kCommsOrders[i]) + (current ? "  <" : "");
    text(h, x, top + row * (i + 1), 1.0, alive ? kHudBlue : faded(kHudBlue, 0.5), line);
  }
  text(h, x, top + row * 5, 1.0, faded(kHudWhite, 0.7), "Esc  close");
  (void)width;
}

}  // namespace arc
