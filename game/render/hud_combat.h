// game/render/hud_combat.h — the HUD's combat cues, derived each frame from the World (no GL).
//
// Nothing here is remembered between frames; every cue is a function of simulated state:
//   hit marker      an X around the crosshair while a weapon of `me` hits a hostile (a ship whose
//                   last attacker is `me`, hit within HudRules::hit_marker_seconds); red and
//                   larger on a kill;
//   damage          for the ship that last hit `me` (within damage_seconds) and every hostile
//                   whose beam is on `me` now: a red wedge on a ring around the screen centre
//                   and a glow on the screen edge toward it, fading with the hit's age;
//   missile warning "MISSILE 420 m" blinking above the crosshair and a marker on the ring
//                   toward each missile homing on `me` (not one a flare has pulled away);
//   range cue       above the target's brackets, "IN RANGE" while the beam reaches it;
//   kill feed       the last kills (killer and victim, from the dead ships' death tick and last
//                   attacker) and the World's messages (wing replies in blue, reinforcements),
//                   newest first, under the objective, each for kill_feed_seconds.
// Sizes are in canvas units (hud_draw.h).
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>
#include <glm/vec2.hpp>

#include "game/render/hud_rules.h"
#include "game/render/screen_projection.h"
#include "gfx/render_view.h"

namespace arc {

class World;
struct Ship;

// The warnings layout_combat_cues draws for `me`, as screen directions from the centre (+y
// down): each attacker's (strength 1 while its beam is on `me`, fading after its last hit; in
// view or not), and the missiles homing on `me` with the nearest one's distance (-1: none).
struct ThreatCue {
  glm::dvec2 dir{0.0};
  double strength = 0;
  bool in_view = false;
};
struct ThreatCues {
  std::vector<ThreatCue> attackers;
  double missile_m = -1;
  std::vector<glm::dvec2> missiles;
};
ThreatCues threat_cues(const World& w, const Ship& me, const Projector& pr, const HudRules& rules, double alpha,
                       double canvas_w, double canvas_h);

// Above the target's brackets (centre c, half-size r): "IN RANGE" when the target is within the
// beam's range (the brackets are drawn bolder then); the distance is under the brackets
// (hud_aim.h).
void layout_range_cue(HudLayer& h, glm::dvec2 c, double r, bool in_range, const glm::vec4& col);
void layout_combat_cues(const World& w, const Ship& me, const Projector& pr, const HudRules& rules, double alpha,
                        double canvas_w, double canvas_h, HudLayer& h);
// `me` (may be null) colours the entries: green for its side's kills, red for its losses.
// `names` (ship index → pilot), when given, names the pilots' ships in a network match.
// `right`, when above 0, cuts each line short of that x (room kept for the F3 figures).
void layout_kill_feed(const World& w, const Ship* me, const HudRules& rules, double x, double y, HudLayer& h,
                      const std::map<uint32_t, std::string>* names = nullptr, double right = 0);

}  // namespace arc
