// tools/assetgen/main.cpp — arcfire-assetgen: regenerates assets/models/*.glb,
// assets/textures/sprite_*.png and the application icon packaging/arcfire.png. Output is a pure function of this source: no clock, no
// system randomness, so re-running it must reproduce the committed bytes exactly.
//
//   build/arcfire-assetgen --out .        (from the repo root)
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <CLI/CLI.hpp>
#include "core/error.h"
#include "icon.h"
#include "models.h"
#include "sprites.h"

int main(int argc, char** argv) {
  CLI::App app{"Arcfire asset generator: writes assets/models/*.glb, assets/textures/sprite_*.png and packaging/arcfire.png"};
  std::string out = ".";
  app.add_option("--out", out, "Root directory to write assets/ and packaging/ under (the repo root to regenerate the committed files)");
  CLI11_PARSE(app, argc, argv);
  try {
    const std::filesystem::path root(out);
    const auto models = root / "assets" / "models";
    const auto textures = root / "assets" / "textures";
    std::filesystem::create_directories(models);
    std::filesystem::create_directories(textures);
    std::filesystem::create_directories(root / "packaging");
    arc::assetgen::write_icon((root / "packaging" / "arcfire.png").string());
    const int n = arc::assetgen::write_models(models.string(), textures.string()) + arc::assetgen::write_sprites(textures.string()) + 1;
    std::printf("arcfire-assetgen: wrote %d files under %s\n", n, root.string().c_str());
    return arc::kExitOk;
  } catch (const arc::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return arc::kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "arcfire-assetgen: %s\n", e.what());
    return arc::kExitCheckFailed;
  }
}
