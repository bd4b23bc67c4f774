// Quality presets (assets/settings/quality.json) against the reference preset, in one run:
//  - rendering: the gallery level at tick 240 (simulated once, with the default settings) drawn
//    at 1280×720 with each preset's render settings; the fastest frame of interleaved rounds
//    and the image's distance from the reference preset's image of the same world:
//      preset_frame_ms_NAME, preset_frame_ratio_NAME (frame ÷ reference's frame, same-round
//      median), preset_image_error_NAME (mean absolute channel difference in 1/255 steps) and
//      preset_pixels_off_NAME (fraction of pixels more than 5/255 off in some channel, the
//      golden-image tolerance);
//  - simulation: the arena battle's first 600 ticks with each preset's simulation settings
//    (particle budget, lightning interval, sub-steps): preset_sim_ms_per_tick_NAME.
// Each preset is applied to the default settings, as `arcfire --quality NAME` does.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "bench_registry.h"
#include "bench_scenes.h"
#include "core/settings.h"
#include "game/app/all_settings.h"
#include "game/app/app_options.h"
#include "game/sim/game.h"
#include "game/sim/input.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "core/data_root.h"

namespace arc {
namespace {

constexpr int kWidth = 1280, kHeight = 720;
const char* const kPresets[] = {"low", "medium", "high", "reference"};
constexpr size_t kReference = 3;

Settings preset(const std::string& name) {
  Settings s = all_settings();
  s.apply_preset_file(arc::data_root() + "/assets/settings/quality.json", name);
  return s;
}

GameOptions game_options(const Settings& s) {
  GameOptions o;
  o.root_dir = arc::data_root();
  apply_simulation_settings(s, o);
  return o;
}

// Mean absolute channel difference (RGB, in 1/255 steps) and the fraction of pixels beyond
// the golden tolerance.
void image_error(const Image& want, const Image& got, double* mean, double* off) {
  double sum = 0;
  size_t beyond = 0, n = size_t(want.width) * size_t(want.height);
  for (size_t i = 0; i < n; ++i) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int(want.rgba[i * 4 + size_t(c)]) - int(got.rgba[i * 4 + size_t(c)]));
      sum += d;
      worst = std::max(worst, d);
    }
    beyond += worst > 5;
  }
  *mean = sum / double(n * 3);
  *off = double(beyond) / double(n);
}

}  // namespace

ARCFIRE_SCENE(quality_presets) {
  const std::string root = arc::data_root();
  std::vector<Settings> settings;
  for (const char* name : kPresets) settings.push_back(preset(name));

  // Simulation first: it needs no GL.
  std::printf(" simulation: levels/arena.json, 600 ticks, per preset\n");
  double sim_ms[4] = {};
  for (size_t i = 0; i < 4; ++i) {
    Game game = Game::load_level(root + "/levels/arena.json", game_options(settings[i]));
    const double t0 = bench::now_seconds();
    for (int t = 0; t < 600; ++t) game.step(InputFrame{});
    sim_ms[i] = (bench::now_seconds() - t0) * 1000.0 / 600.0;
    std::printf("  %-10s %.3f ms per tick\n", kPresets[i], sim_ms[i]);
  }

  std::unique_ptr<HeadlessContext> ctx;
  try {
    ctx = create_headless_context();
  } catch (const std::exception& e) {
    std::printf("skipped rendering: no EGL context (%s)\n", e.what());
    for (size_t i = 0; i < 4; ++i) bench::report_metric(std::string("preset_sim_ms_per_tick_") + kPresets[i], sim_ms[i]);
    return;
  }
  RendererDesc desc;
  desc.offscreen = true;
  desc.shader_dir = root + "/shaders";
  Renderer r(desc);
  const RenderView view = bench::level_view(r, "levels/gallery.json", 240, kWidth, kHeight);

  std::printf(" rendering: levels/gallery.json at tick 240, %d×%d, per preset's render settings\n", kWidth, kHeight);
  std::vector<Image> images(4);
  for (size_t i = 0; i < 4; ++i) {  // warm-up and the images compared
    r.apply_settings(settings[i]);
    r.render(view, kWidth, kHeight);
    images[i] = r.read_pixels();
  }
  const int rounds = 12;
  std::vector<std::vector<double>> ms(4);
  for (int round = 0; round < rounds; ++round)
    for (size_t k = 0; k < 4; ++k) {
      const size_t i = round % 2 ? 3 - k : k;  // odd rounds backwards
      r.apply_settings(settings[i]);
      r.finish();
      const double t0 = bench::now_seconds();
      r.render(view, kWidth, kHeight);
      r.finish();
      ms[i].push_back((bench::now_seconds() - t0) * 1000.0);
    }
  for (size_t i = 0; i < 4; ++i) {
    std::vector<double> ratio;
    for (int k = 0; k < rounds; ++k) ratio.push_back(ms[i][size_t(k)] / ms[kReference][size_t(k)]);
    double mean = 0, off = 0;
    image_error(images[kReference], images[i], &mean, &off);
    const double best = *std::min_element(ms[i].begin(), ms[i].end());
    std::printf("  %-10s %7.2f ms/frame, x%.3f of reference; image %.3f/255 mean error, %.4f of pixels beyond 5/255\n",
                kPresets[i], best, bench::median(ratio), mean, off);
    const std::string n = kPresets[i];
    bench::report_metric("preset_frame_ms_" + n, best);
    bench::report_metric("preset_frame_ratio_" + n, bench::median(ratio));
    if (i != kReference) {
      bench::report_metric("preset_image_error_" + n, mean);
      bench::report_metric("preset_pixels_off_" + n, off);
    }
    bench::report_metric("preset_sim_ms_per_tick_" + n, sim_ms[i]);
  }
}

}  // namespace arc
