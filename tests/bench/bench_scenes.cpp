#include "bench_scenes.h"

#include <cstdio>
#include <cstdlib>

#include "game/app/scene_resources.h"
#include "game/render/render_view_builder.h"
#include "game/sim/game.h"
#include "game/sim/input.h"
#include "core/data_root.h"

namespace arc::bench {

RenderView level_view(Renderer& r, const std::string& level, int ticks, int width, int height) {
  const std::string root = arc::data_root();
  GameOptions options;
  options.root_dir = root;
  Game game = Game::load_level(root + "/" + level, options);
  for (int t = 0; t < ticks; ++t) game.step(InputFrame{});
  const std::vector<ModelId> models = load_scene_resources(r, game.world(), root);
  HudState hud;
  hud.show_hud = false;
  RenderView view;
  build_render_view(game.world(), models, 1.0, CameraSettings{}, hud, width, height, view);
  return view;
}

std::unique_ptr<HeadlessContext> context_or_skip() {
  try {
    return create_headless_context();
  } catch (const std::exception& e) {
    std::printf("skipped: no EGL context (%s)\n", e.what());
    return nullptr;
  }
}

bool software_rasteriser(const std::string& gl) {
  return gl.find("llvmpipe") != std::string::npos || gl.find("softpipe") != std::string::npos;
}

int rounds_from_env(int fallback) {
  const char* v = std::getenv("ARCFIRE_BENCH_ROUNDS");
  if (!v) return fallback;
  char* end = nullptr;
  const long n = std::strtol(v, &end, 10);
  if (end == v || *end != '\0' || n < 1 || n > 10000) {
    std::fprintf(stderr, "arcfire-bench: ARCFIRE_BENCH_ROUNDS='%s' is not allowed; use a whole number from 1 to 10000\n", v);
    std::exit(2);
  }
  return int(n);
}

}  // namespace arc::bench
