// game/app/scene_resources.h — loads what a level needs into a Renderer: only the models the
// level names (World::model_paths, in order, so MeshInstance::model indices match) and the
// particle sprites (in the layer order of particles/sprites.h).
#pragma once
#include <string>

namespace arc {

class Renderer;
class World;

void load_scene_resources(Renderer& renderer, const World& world, const std::string& root_dir);

}  // namespace arc
