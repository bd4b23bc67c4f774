// game/render/team_colors.h — ships drawn in their team's colour (no GL).
//
// A level names its teams' colours (LevelDef::team_colors, defaults for blue and red). A ship
// of a team with a colour gets it on the model's team regions (hull stripes and engine nozzles:
// MeshInstance::team_color) and its engine exhaust particles are tinted toward it; a team
// without a colour keeps the models' and effects' own colours.
#pragma once
#include <vector>
#include <glm/vec4.hpp>

#include "gfx/render_view.h"

namespace arc {

class World;
struct Ship;

// rgb and strength for MeshInstance::team_color: strength 0 when the team has no colour.
glm::vec4 ship_team_color(const World& w, const Ship& s);
// Tints the particles of every live ship's exhaust clusters toward its team colour.
void tint_exhausts(const World& w, std::vector<ParticleInstance>& particles);

}  // namespace arc
