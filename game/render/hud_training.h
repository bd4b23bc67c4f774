// game/render/hud_training.h — a training level's prompt on the HUD (game/render/hud_training.cpp).
//
// The step under way (World::training) is drawn near the top centre in place of the objective:
// "TRAINING 3/9" and the step's prompt, large, on a dark backing. The prompt's {action}
// placeholders become the keys bound to those actions, from HudState::key_names, which the app
// fills from the live bindings (headless frames: the default bindings file), so a remapped key
// shows as remapped.
#pragma once
#include <map>
#include <string>

#include "gfx/render_view.h"

namespace arc {

class World;

// `prompt` with each {action} replaced by "[KEY]": the key's name in `key_names` (action id →
// key name as settings.json spells it), underscores shown as spaces; an action without a key is
// "[no key: action]".
std::string training_prompt(const std::string& prompt, const std::map<std::string, std::string>& key_names);

// Draws the step under way between x0 and x1 (canvas units; the room the top panels leave),
// centred on the screen where it fits. Returns the bottom of what it drew (y0 when nothing).
double hud_training_prompt(const World& w, const std::map<std::string, std::string>& key_names, double x0, double x1,
                           double y0, int width, HudLayer& h);

// Whether a training step is under way (its prompt replaces the objective).
bool training_prompt_shown(const World& w);

}  // namespace arc
