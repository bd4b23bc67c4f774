// game/app/scene_resources.h — loads what a level needs into a Renderer: only the models the
// level names (World::model_paths) and the particle sprites (in the layer order of
// particles/sprites.h). Returns the renderer's ModelId for each model slot, in slot order: the
// table build_render_view() maps ships' and props' ModelSlots through.
#pragma once
#include <string>
#include <vector>

#include "gfx/render_view.h"

namespace arc {

class Renderer;
class World;

std::vector<ModelId> load_scene_resources(Renderer& renderer, const World& world, const std::string& root_dir);
// Only the particle sprites (the effect preview has no level).
void load_sprites(Renderer& renderer, const std::string& root_dir);

}  // namespace arc
