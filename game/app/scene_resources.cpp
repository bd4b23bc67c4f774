// The models and sprites a level needs, loaded into a Renderer; the models' ids by slot.
#include "game/app/scene_resources.h"

#include <filesystem>
#include <vector>

#include "assets/model.h"
#include "core/data_layers.h"
#include "core/error.h"
#include "game/sim/defs.h"
#include "gfx/renderer.h"
#include "game/sim/world.h"
#include "particles/sprites.h"

namespace arc {

std::vector<ModelId> load_scene_resources(Renderer& renderer, const World& world, const std::string& root_dir) {
  namespace fs = std::filesystem;
  auto resolve = [&](const std::string& p) {
    return fs::path(p).is_absolute() ? p : data_file(root_dir, p);
  };
  std::vector<ModelId> models;
  for (const std::string& path : world.model_paths) models.push_back(renderer.add_model(load_model(resolve(path))));
  load_sprites(renderer, root_dir);
  return models;
}

ModelId SceneModels::id_of(Renderer& renderer, const std::string& path, const std::string& root_dir) {
  if (auto it = ids_.find(path); it != ids_.end()) return it->second;
  const std::string file = std::filesystem::path(path).is_absolute() ? path : data_file(root_dir, path);
  return ids_[path] = renderer.add_model(load_model(file));
}

std::vector<ModelId> SceneModels::of(Renderer& renderer, const World& world, const std::string& root_dir) {
  std::vector<ModelId> models;
  for (const std::string& path : world.model_paths) models.push_back(id_of(renderer, path, root_dir));
  return models;
}

void SceneModels::warm(Renderer& renderer, const std::vector<std::string>& level_paths, const std::string& root_dir) {
  for (const std::string& level : level_paths) {
    try {
      const LevelDef def = load_level_def(level, root_dir);
      for (const auto& [name, cls] : def.classes) id_of(renderer, cls->model, root_dir);
      for (const PropDef& p : def.props) id_of(renderer, p.model, root_dir);
    } catch (const InputError&) {
      continue;  // reported when it is launched
    }
  }
}

void load_sprites(Renderer& renderer, const std::string& root_dir) {
  std::vector<Image> sprites;
  for (std::string_view name : kSpriteNames)
    // Straight alpha as stored: the renderer premultiplies in the colour space it draws in.
    sprites.push_back(load_image(data_file(root_dir, "assets/textures/sprite_" + std::string(name) + ".png")));
  renderer.set_sprites(sprites);
}

}  // namespace arc
