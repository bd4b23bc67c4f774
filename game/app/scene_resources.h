// game/app/scene_resources.h — loads what a level needs into a Renderer: only the models the
// level names (World::model_paths) and the particle sprites (in the layer order of
// particles/sprites.h). Returns the renderer's ModelId for each model slot, in slot order: the
// table build_render_view() maps ships' and props' ModelSlots through.
//
// SceneModels keeps the models one Renderer holds by path, so a launch loads only the models the
// renderer lacks and keeps the renderer (its compiled shaders); warm() loads the models of the
// levels the menu can launch before any is launched.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "gfx/render_view.h"

namespace arc {

class Renderer;
class World;

std::vector<ModelId> load_scene_resources(Renderer& renderer, const World& world, const std::string& root_dir);
// Only the particle sprites (the effect preview has no level).
void load_sprites(Renderer& renderer, const std::string& root_dir);

class SceneModels {
 public:
  // The renderer's id of each of the world's model slots, loading the models it lacks.
  std::vector<ModelId> of(Renderer& renderer, const World& world, const std::string& root_dir);
  // Loads the models of each level (its ships' classes and props); a level that fails to load
  // is left for its launch to report.
  void warm(Renderer& renderer, const std::vector<std::string>& level_paths, const std::string& root_dir);

 private:
  ModelId id_of(Renderer& renderer, const std::string& path, const std::string& root_dir);
  std::map<std::string, ModelId> ids_;  // by the path as levels name it
};

}  // namespace arc
