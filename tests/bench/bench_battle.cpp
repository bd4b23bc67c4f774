// battle_frames: hitches, not only medians. Thirty seconds of the arena battle (ticks 600 to
// 2400, the fight in full swing), the player at half throttle with the beam held, rendered at
// 1280×720 with the default settings and the HUD from the chase camera, every second tick; each
// frame is timed alone (render + glFinish).
//   battle_frame_p50_ms, battle_frame_p99_ms   frame time percentiles over the flight
//   battle_frame_max_ms                        the slowest frame
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench_registry.h"
#include "bench_scenes.h"
#include "core/settings.h"
#include "game/app/all_settings.h"
#include "game/app/scene_resources.h"
#include "game/render/render_view_builder.h"
#include "game/sim/game.h"
#include "gfx/renderer.h"
#include "core/data_root.h"

namespace arc {
namespace {

constexpr int kWidth = 1280, kHeight = 720;
constexpr int kStart = 600, kTicks = 1800, kEvery = 2;

// The value below which a share p of the samples lie (nearest rank).
double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t rank = size_t(std::ceil(p * double(v.size())));
  return v[std::min(v.size() - 1, rank == 0 ? 0 : rank - 1)];
}

ARCFIRE_SCENE(battle_frames) {
  const std::unique_ptr<HeadlessContext> ctx = bench::context_or_skip();
  if (!ctx) return;
  const std::string root = arc::data_root();
  GameOptions options;
  options.root_dir = root;
  Game game = Game::load_level(root + "/levels/arena.json", options);
  InputFrame in{};
  in.throttle = 64;
  in.buttons = kFirePrimary;
  for (int t = 0; t < kStart; ++t) game.step(in);
  RendererDesc desc;
  desc.offscreen = true;
  desc.shader_dir = root + "/shaders";
  Renderer renderer(desc);
  renderer.apply_settings(all_settings());
  const std::vector<ModelId> models = load_scene_resources(renderer, game.world(), root);
  HudState hud;
  RenderView view;
  std::vector<double> ms;
  for (int t = 0; t < kTicks; ++t) {
    game.step(in);
    if ((t + 1) % kEvery) continue;
    build_render_view(game.world(), models, 1.0, CameraSettings{}, hud, kWidth, kHeight, view);
    const double t0 = bench::now_seconds();
    renderer.render(view, kWidth, kHeight);
    renderer.finish();
    ms.push_back((bench::now_seconds() - t0) * 1000.0);
  }
  std::printf("  levels/arena.json ticks %d-%d, %zu frames at %dx%d, %s\n", kStart, kStart + kTicks, ms.size(), kWidth, kHeight,
              ctx->description().c_str());
  bench::report_metric("battle_frame_p50_ms", percentile(ms, 0.5));
  bench::report_metric("battle_frame_p99_ms", percentile(ms, 0.99));
  bench::report_metric("battle_frame_max_ms", ms.empty() ? 0.0 : *std::max_element(ms.begin(), ms.end()));
}

}  // namespace
}  // namespace arc
