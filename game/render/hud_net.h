// game/render/hud_net.h — what a network match adds to the HUD (no GL): each pilot's name over
// its ship in its team's colour, the connection figures above the radar (F3), and the
// scoreboard while its key is held: kills, deaths, damage dealt and ping per slot, in place of
// the flight panels, the F3 figures and the error banner (the notice stays).
//
// The app fills NetHud from the match (game/app/net_match.h); layout_hud() draws it. The kill
// feed names ships by their pilots too (layout_kill_feed's `names`).
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "gfx/render_view.h"

namespace arc {

class World;
struct Projector;

struct NetHud {
  bool on = false;                         // a network match: the rest is drawn
  std::map<uint32_t, std::string> names;   // ship index → its pilot's name
  std::string stats;                       // F3: "ping 42 ms  rollbacks 3.1/s"
  bool scoreboard = false;                 // its key is held
  struct Row {
    uint32_t ship = 0;                     // the slot's ship (index)
    std::string name;                      // the pilot's, or "AI (ship name)"
    double ping_ms = 0;
    bool you = false;
  };
  std::vector<Row> rows;                   // one per slot
};

// Names over the named ships on screen, in their team's colour (canvas units).
void hud_net_names(const World& w, const NetHud& net, const Projector& pr, int width, int height, HudLayer& h);
// The scoreboard panel, centred; its text rows use the bitmap font at its own size.
void hud_scoreboard(const World& w, const NetHud& net, int width, int height, HudLayer& h);
// The connection figures (F3), right-aligned above the radar.
void hud_net_stats(const NetHud& net, int width, int height, HudLayer& h);

}  // namespace arc
