#include "game/sim/effects.h"

#include <filesystem>

#include "particles/effect_library.h"

namespace arc {

std::shared_ptr<const EffectLibrary> load_effect_library(const std::string& root_dir) {
  auto lib = std::make_shared<EffectLibrary>();
  lib->load_directory((std::filesystem::path(root_dir) / "assets/effects").string());
  return lib;
}

}  // namespace arc
