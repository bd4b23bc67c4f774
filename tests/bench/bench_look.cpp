// The look's costs and effect, in one run at 1280×720 through EGL:
//  - hdr_bloom_frame_ratio(_battle): the gallery (tick 240) and the arena battle (tick 600)
//    with the HDR scene, tone map and bloom (low) against the plain 8-bit scene, both
//    without anti-aliasing; hdr_format_frame_ratio(_battle): the HDR frame with an
//    R11F_G11F_B10F scene against RGBA16F (the format the renderer uses, being the cheaper);
//  - antialias_frame_ratio_<mode>(_battle): fxaa, msaa2 and msaa4 against off, HDR and bloom on;
//  - clipped_pixel_share_hdr_off / _hdr_on: the share of pixels with any channel at 255 in the
//    gallery's brightest explosion frame, with the 8-bit scene and with the high preset's look (the tick with the most clipped pixels of the first
//    second, found with HDR off), before and after tone mapping;
//  - render_battle_frame_ms_default_preset: the battle frame with all_settings()
//    (8-bit scene, no bloom, no edge filter), fastest and median of the rounds (a 60 Hz frame
//    is 16.7 ms); render_battle_frame_ms_high_preset: the same with the high preset's look
//    (hdr, bloom high, FXAA).
// Frames are timed one glFinish-bracketed frame at a time, every configuration once per round,
// odd rounds backwards, over ARCFIRE_BENCH_ROUNDS rounds (default 32); ratios are medians of
// same-round pairs, as in bench_render.cpp.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "bench_registry.h"
#include "bench_scenes.h"
#include "game/app/all_settings.h"
#include "game/app/scene_resources.h"
#include "game/render/render_view_builder.h"
#include "game/sim/game.h"
#include "game/sim/input.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "core/data_root.h"

namespace arc {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

struct Config {
  std::string name;
  Renderer* renderer;
  RenderSettings settings;
  std::vector<double> ms;
};

// Times every configuration once per round, interleaved, and returns nothing: the frames are in
// each config's `ms`.
void time_rounds(std::vector<Config>& configs, const RenderView& view, int rounds) {
  for (Config& c : configs) {  // warm-up: programs, targets and the linear sprites made
    c.renderer->set_render_settings(c.settings);
    c.renderer->render(view, kWidth, kHeight);
    c.renderer->finish();
  }
  for (int round = 0; round < rounds; ++round)
    for (size_t k = 0; k < configs.size(); ++k) {
      Config& c = configs[round % 2 ? configs.size() - 1 - k : k];
      c.renderer->set_render_settings(c.settings);
      const double t0 = bench::now_seconds();
      c.renderer->render(view, kWidth, kHeight);
      c.renderer->finish();
      c.ms.push_back((bench::now_seconds() - t0) * 1000.0);
    }
}

double paired(const Config& a, const Config& b) {
  std::vector<double> q;
  for (size_t i = 0; i < a.ms.size(); ++i) q.push_back(a.ms[i] / b.ms[i]);
  return bench::median(q);
}

double fastest(const Config& c) { return *std::min_element(c.ms.begin(), c.ms.end()); }

RenderSettings look(bool hdr, float bloom, RenderSettings::Antialias aa) {
  RenderSettings s;
  s.hdr = hdr;
  s.bloom = bloom;
  s.antialias = aa;
  return s;
}

// The renderer settings of a quality preset ("" for all_settings()).
RenderSettings preset_look(const std::string& preset) {
  Settings s = all_settings();
  if (!preset.empty()) s.apply_preset_file(arc::data_root() + "/assets/settings/quality.json", preset);
  Renderer probe(RendererDesc{.offscreen = true});
  probe.apply_settings(s);
  return probe.render_settings();
}

// One scene: the cost of HDR + bloom, of the HDR formats and of each anti-aliasing mode, and
// the frame with the settings of all_settings() and of the high preset.
void measure_scene(Renderer& r, Renderer& r11, const RenderView& view, const std::string& suffix, int rounds) {
  using AA = RenderSettings::Antialias;
  const float bloom = RenderSettings::kBloomLow;
  RenderSettings high = preset_look("high");
  high.scale = 1.0;  // the same frame size as the others
  std::vector<Config> c = {{"8-bit scene (hdr off)", &r, look(false, 0, AA::Off), {}},
                           {"hdr + bloom (RGBA16F)", &r, look(true, bloom, AA::Off), {}},
                           {"hdr + bloom, R11F_G11F_B10F", &r11, look(true, bloom, AA::Off), {}},
                           {"hdr + bloom + fxaa", &r, look(true, bloom, AA::Fxaa), {}},
                           {"hdr + bloom + msaa2", &r, look(true, bloom, AA::Msaa2), {}},
                           {"hdr + bloom + msaa4", &r, look(true, bloom, AA::Msaa4), {}},
                           {"default settings", &r, preset_look(""), {}},
                           {"high preset", &r, high, {}}};
  time_rounds(c, view, rounds);
  for (const Config& k : c)
    std::printf("  %-30s fastest %6.2f ms, median %6.2f ms, x%.3f of hdr off\n", k.name.c_str(), fastest(k),
                bench::median(k.ms), paired(k, c[0]));
  bench::report_metric("hdr_bloom_frame_ratio" + suffix, paired(c[1], c[0]));
  bench::report_metric("hdr_format_frame_ratio" + suffix, paired(c[2], c[1]));
  bench::report_metric("antialias_frame_ratio_fxaa" + suffix, paired(c[3], c[1]));
  bench::report_metric("antialias_frame_ratio_msaa2" + suffix, paired(c[4], c[1]));
  bench::report_metric("antialias_frame_ratio_msaa4" + suffix, paired(c[5], c[1]));
  for (AA aa : {AA::Msaa2, AA::Msaa4}) {
    r.set_render_settings(look(true, bloom, aa));
    r.render(view, kWidth, kHeight);
    std::printf("  msaa%d: the context gave %d samples\n", aa == AA::Msaa2 ? 2 : 4, r.last_stats().msaa_samples);
  }
  if (suffix == "_battle") {
    bench::report_metric("render_battle_frame_ms_default_preset", fastest(c[6]));
    bench::report_metric("render_battle_frame_ms_default_preset_median", bench::median(c[6].ms));
    bench::report_metric("render_battle_frame_ms_high_preset", fastest(c[7]));
  }
}

double clipped_share(const Image& img) {
  size_t clipped = 0;
  for (size_t i = 0; i + 3 < img.rgba.size(); i += 4)
    clipped += img.rgba[i] == 255 || img.rgba[i + 1] == 255 || img.rgba[i + 2] == 255;
  return double(clipped) / double(size_t(img.width) * img.height);
}

// The gallery's first second, every fourth tick; the frame with the most clipped pixels with
// HDR off is the explosion's brightest, and both figures are taken there.
void measure_clipping(Renderer& r) {
  const std::string root = arc::data_root();
  GameOptions options;
  options.root_dir = root;
  Game game = Game::load_level(root + "/levels/gallery.json", options);
  const std::vector<ModelId> models = load_scene_resources(r, game.world(), root);
  HudState hud;
  hud.show_hud = false;
  double worst_off = -1, on_there = 0;
  int worst_tick = 0;
  Image worst_off_img, on_img;
  for (int tick = 1; tick <= 60; ++tick) {
    game.step(InputFrame{});
    if (tick % 4) continue;
    RenderView view;
    build_render_view(game.world(), models, 1.0, CameraSettings{}, hud, kWidth, kHeight, view);
    r.set_render_settings(look(false, 0, RenderSettings::Antialias::Off));
    r.render(view, kWidth, kHeight);
    Image off = r.read_pixels();
    const double share = clipped_share(off);
    if (share <= worst_off) continue;
    worst_off = share;
    worst_tick = tick;
    r.set_render_settings(preset_look("high"));
    r.render(view, kWidth, kHeight);
    on_img = r.read_pixels();
    on_there = clipped_share(on_img);
    worst_off_img = off;
  }
  std::printf(" gallery explosion at tick %d: %.3f %% of pixels clipped with hdr off, %.3f %% with the high preset's look\n",
              worst_tick, worst_off * 100, on_there * 100);
  if (const char* dir = std::getenv("ARCFIRE_GFX_DUMP")) {
    save_image(std::string(dir) + "/look_explosion_hdr_off.png", worst_off_img);
    save_image(std::string(dir) + "/look_explosion_hdr_on.png", on_img);
  }
  bench::report_metric("clipped_pixel_share_hdr_off", worst_off);
  bench::report_metric("clipped_pixel_share_hdr_on", on_there);
}

}  // namespace

ARCFIRE_SCENE(render_look) {
  const int rounds = bench::rounds_from_env(32);
  const std::unique_ptr<HeadlessContext> ctx = bench::context_or_skip();
  if (!ctx) return;
  RendererDesc desc{.offscreen = true};
  RendererDesc desc11 = desc;
  desc11.hdr_format = HdrFormat::R11fG11fB10f;
  std::printf("context: %s\n", ctx->description().c_str());
  {
    Renderer r(desc), r11(desc11);
    const RenderView gallery = bench::level_view(r, "levels/gallery.json", 240, kWidth, kHeight);
    bench::level_view(r11, "levels/gallery.json", 0, kWidth, kHeight);
    std::printf(" gallery (levels/gallery.json at tick 240):\n");
    measure_scene(r, r11, gallery, "", rounds);
  }
  {
    Renderer r(desc), r11(desc11);
    const RenderView arena = bench::level_view(r, "levels/arena.json", 600, kWidth, kHeight);
    bench::level_view(r11, "levels/arena.json", 0, kWidth, kHeight);
    std::printf(" arena battle (levels/arena.json at tick 600, chase camera):\n");
    measure_scene(r, r11, arena, "_battle", rounds);
  }
  Renderer r(desc);
  measure_clipping(r);
}

}  // namespace arc
