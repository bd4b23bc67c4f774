// game/render/hud_net.cpp — pilots' names over ships, the scoreboard and the F3 net figures.
#include "game/render/hud_net.h"

#include <algorithm>

#include "game/render/hud_draw.h"
#include "game/render/hud_radar.h"
#include "game/render/screen_projection.h"
#include "game/render/team_colors.h"
#include "game/sim/world.h"

namespace arc {
namespace {

// The team's colour brightened to be read as text; the HUD's blue when the team has none.
glm::vec4 name_colour(const World& w, const Ship& s) {
  const glm::vec4 c = ship_team_color(w, s);
  if (c.a <= 0) return kHudBlue;
  const float top = std::max({c.r, c.g, c.b, 0.01f});
  auto lift = [&](float v) { return std::min(1.0f, 0.35f + 0.65f * v / top); };
  return {lift(c.r), lift(c.g), lift(c.b), 0.95f};
}

std::string pad(std::string s, size_t n) {
  if (s.size() > n) s.resize(n);
  s.resize(n, ' ');
  return s;
}

}  // namespace

void hud_net_names(const World& w, const NetHud& net, const Projector& pr, int width, int height, HudLayer& h) {
  for (const auto& [index, name] : net.names) {
    if (index >= w.ships.size() || name.empty()) continue;
    const Ship& s = w.ships[index];
    if (!s.alive || s.id == w.player) continue;  // one's own ship needs no name
    glm::dvec2 px;
    if (!pr.project(s.position + glm::dvec3(0, s.cls->shield_radius + 4.0, 0), px)) continue;
    if (px.x < 0 || px.x > width || px.y < 0 || px.y > height) continue;
    const double x = px.x - name.size() * kGlyphAdvance * 0.5;
    text(h, x, px.y - 32, 1.0, name_colour(w, s), name);  // above the target brackets (14 units at the least)
  }
}

void hud_scoreboard(const World& w, const NetHud& net, int width, int height, HudLayer& h) {
  if (net.rows.empty()) return;
  const std::string head = pad("Pilot", 26) + pad("Team", 8) + pad("Kills", 7) + pad("Deaths", 8) + pad("Damage", 8) + "Ping";
  const double row = 15, w_px = double(head.size()) * kGlyphAdvance + 24;
  const double h_px = (double(net.rows.size()) + 2) * row + 24;
  const double x0 = std::max(4.0, (width - w_px) / 2), y0 = std::max(4.0, (height - h_px) / 2);
  quad(h, x0, y0, std::min(w_px, width - 8.0), std::min(h_px, height - 8.0), {0, 0, 0, 0.7f});
  text(h, x0 + 12, y0 + 10, 1.0, kHudWhite, head);
  double y = y0 + 10 + row * 1.5;
  for (const NetHud::Row& r : net.rows) {
    if (r.ship >= w.ships.size()) continue;
    const Ship& s = w.ships[r.ship];
    const int deaths = !s.alive && s.death_tick >= 0 ? 1 : 0;
    const std::string ping = r.name.rfind("AI", 0) == 0 ? "-" : r.you && r.ping_ms <= 0 ? "-" : fmt("%.0f", r.ping_ms);
    const std::string line = pad((r.you ? "> " : "  ") + r.name, 26) + pad(w.team_name(s.team), 8) + pad(std::to_string(s.kills), 7) +
                             pad(std::to_string(deaths), 8) + pad(fmt("%.0f", s.stats.damage_dealt), 8) + ping;
    text(h, x0 + 12, y, 1.0, r.you ? kHudYellow : name_colour(w, s), line);
    y += row;
  }
}

// Right-aligned above the radar, clear of the top panels at every size.
void hud_net_stats(const NetHud& net, int width, int height, HudLayer& h) {
  if (net.stats.empty()) return;
  const double x = std::max(4.0, width - 12 - net.stats.size() * kGlyphAdvance);
  text(h, x, radar_rect(width, height).y - 36, 1.0, kHudWhite, net.stats);
}

}  // namespace arc
