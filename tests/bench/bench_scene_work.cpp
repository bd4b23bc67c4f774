// scene_work: "model only what a scene requires", frame by frame. The arena
// battle from tick 420 to 600, every third tick drawn at 1280×720 with the default settings
// from the chase camera; each frame prints the work done beside the work skipped:
//   clusters  animated / culled (outside the view or beyond particles.cull_distance: their
//             particles are not evaluated) / caught up (culled before, evaluated again: over
//             the ticks since the previous frame)
//   particles evaluated / skipped with their clusters; drawn / culled off screen (quad wholly
//             outside the frustum's sides, never uploaded)
//   soft      particles that read the depth copy / drawn ones that skipped that read
//   depth     how the frame's soft particles read the opaque depth (only when one needs it): from
//             a copy, or from the framebuffer (RenderSettings::depth_fetch), or not at all
// Metrics: scene_work_skipped_particle_share (particle evaluations skipped ÷ all live),
// scene_work_offscreen_share (collected particles culled off screen), scene_work_depth_read_
// skipped_share (drawn particles that did not read depth), scene_work_frames_without_depth_read.
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
#include "game/sim/input.h"
#include "game/sim/world.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "core/data_root.h"

namespace arc {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

struct Totals {
  long long evaluated = 0, skipped = 0, collected = 0, offscreen = 0, drawn = 0, soft = 0;
  int frames = 0, no_read = 0, caught_up = 0;
};

void print_frame(uint64_t tick, const ParticleStats& ps, uint32_t caught_up, const FrameStats& fs, Totals& t) {
  std::printf("  %4llu  clusters %3u animated %3u culled %2u caught up | particles %6u evaluated %6u skipped;"
              " %6d drawn %6d off screen | soft %6d read depth %6d skipped it | depth read %s\n",
              static_cast<unsigned long long>(tick), ps.live_clusters - ps.skipped_clusters, ps.skipped_clusters,
              caught_up, ps.animated_particles, ps.skipped_particles, fs.particles_drawn,
              fs.culled_offscreen, fs.soft_shaded, fs.particles_drawn - fs.soft_shaded,
              fs.depth_copied ? "from a copy" : fs.depth_fetched ? "from the framebuffer" : "none");
  t.evaluated += ps.animated_particles;
  t.skipped += ps.skipped_particles;
  t.collected += fs.particles_in;
  t.offscreen += fs.culled_offscreen;
  t.drawn += fs.particles_drawn;
  t.soft += fs.soft_shaded;
  t.caught_up += int(caught_up);
  t.no_read += fs.reads_depth() ? 0 : 1;
  ++t.frames;
}

double share(long long part, long long whole) { return whole > 0 ? double(part) / double(whole) : 0.0; }

}  // namespace

ARCFIRE_SCENE(scene_work) {
  const std::unique_ptr<HeadlessContext> ctx = bench::context_or_skip();
  if (!ctx) return;
  const std::string root = arc::data_root();
  GameOptions options;
  options.root_dir = root;
  Game game = Game::load_level(root + "/levels/arena.json", options);
  Renderer r(RendererDesc{.offscreen = true});
  r.apply_settings(all_settings());
  const std::vector<ModelId> models = load_scene_resources(r, game.world(), root);
  HudState hud;
  hud.show_hud = false;
  RenderView view;
  Totals t;
  std::printf(" levels/arena.json ticks 420-600, default settings, chase camera (tick: work done | work skipped)\n");
  uint32_t caught_up = 0;
  for (uint64_t tick = 1; tick <= 600; ++tick) {
    game.step(InputFrame{});
    caught_up += game.world().particles->stats().caught_up_clusters;
    if (tick < 420 || tick % 3) continue;
    build_render_view(game.world(), models, 1.0, CameraSettings{}, hud, kWidth, kHeight, view);
    r.render(view, kWidth, kHeight);
    print_frame(tick, game.world().particles->stats(), caught_up, r.last_stats(), t);
    caught_up = 0;
  }
  std::printf("  %d frames: %.1f %% of particle evaluations skipped, %d clusters caught up, %.1f %% of collected particles"
              " culled off screen, %.1f %% of drawn particles skipped the depth read, %d frames without a depth read\n",
              t.frames, 100 * share(t.skipped, t.skipped + t.evaluated), t.caught_up, 100 * share(t.offscreen, t.collected),
              100 * share(t.drawn - t.soft, t.drawn), t.no_read);
  bench::report_metric("scene_work_skipped_particle_share", share(t.skipped, t.skipped + t.evaluated));
  bench::report_metric("scene_work_offscreen_share", share(t.offscreen, t.collected));
  bench::report_metric("scene_work_depth_read_skipped_share", share(t.drawn - t.soft, t.drawn));
  bench::report_metric("scene_work_frames_without_depth_read", t.no_read);
  bench::report_metric("scene_work_clusters_caught_up", t.caught_up);
}

}  // namespace arc
