// game/render/hud_objectives.cpp — the objectives' rows under the objective line.
#include "game/render/hud_objectives.h"

#include "game/render/hud_draw.h"
#include "game/sim/world.h"

namespace arc {

std::string objective_row(const World& w, size_t index) {
  const ObjectiveDef& d = w.level.events.objectives[index];
  const ObjectiveStatus st = w.mission->objectives[index].status;
  std::string row = st == ObjectiveStatus::Done ? "[+] " : st == ObjectiveStatus::Failed ? "[x] " : "[ ] ";
  if (d.kind == ObjectiveKind::Secondary) row += "(bonus) ";
  return row + d.text;
}

double hud_objectives(const World& w, double x, double y0, HudLayer& h) {
  if (!w.mission) return y0;
  double y = y0;
  for (size_t i = 0; i < w.mission->objectives.size(); ++i) {
    const ObjectiveProgress& o = w.mission->objectives[i];
    if (!o.revealed) continue;
    const glm::vec4 col = o.status == ObjectiveStatus::Done     ? kHudGreen
                          : o.status == ObjectiveStatus::Failed ? kHudRed
                                                                : kHudWhite;
    text(h, x, y, 1.0, col, objective_row(w, i));
    y += 16;
  }
  return y == y0 ? y0 : y + 4;
}

}  // namespace arc
