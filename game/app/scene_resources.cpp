// The models and sprites a level needs, loaded into a Renderer; the models' ids by slot.
#include "game/app/scene_resources.h"

#include <filesystem>
#include <vector>

#include "assets/model.h"
#include "core/data_layers.h"
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

void load_sprites(Renderer& renderer, const std::string& root_dir) {
  std::vector<Image> sprites;
  for (std::string_view name : kSpriteNames)
    // Straight alpha as stored: the renderer premultiplies in the colour space it draws in.
    sprites.push_back(load_image(data_file(root_dir, "assets/textures/sprite_" + std::string(name) + ".png")));
  renderer.set_sprites(sprites);
}

}  // namespace arc
