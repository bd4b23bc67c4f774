// tests/unit/game/test_scene_work.cpp — "model only what a scene requires", on real levels.
//
// SceneWork.NoSoftParticleInViewNeverCopiesDepth: the gallery's first two seconds (every effect
// it has) drawn with soft edges off never copy the opaque pass's depth, and drawn with each
// effect's own soft edges copy it exactly on the frames where a particle reads it.
// SceneWork.CullDistanceSettingReachesTheParticleWorld: `--set particles.cull_distance=N` (as
// apply_simulation_settings copies it) makes the gallery's clusters beyond N skip their
// per-particle work, where the default distance animates them all.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/settings.h"
#include "game/app/all_settings.h"
#include "game/app/app_options.h"
#include "game/app/scene_resources.h"
#include "game/render/render_view_builder.h"
#include "game/sim/world.h"
#include "gfx/gl_features.h"
#include "gfx/renderer.h"
#include "gfx_test_util.h"
#include "test_helpers.h"
#include "core/data_root.h"

namespace arc {
namespace {

constexpr int kWidth = 320, kHeight = 180;

// How the frames' soft particles read the opaque depth: from a copy, or from the framebuffer
// where the driver offers it (RenderSettings::depth_fetch); at half resolution without a fetch
// they sample the scene's depth texture itself, with no copy.
struct DepthReads {
  int frames = 0, read = 0, needed = 0, mismatched = 0;
};

DepthReads gallery_depth_reads(const std::string& soft_edges) {
  Settings s = all_settings();
  s.set("render.soft_edges", soft_edges, "test");
  Game game = Game::load_level(test::repo("levels/gallery.json"), test::options());
  Renderer r(RendererDesc{.offscreen = true});
  r.apply_settings(s);
  const std::vector<ModelId> models = load_scene_resources(r, game.world(), arc::data_root());
  HudState no_hud;
  no_hud.show_hud = false;
  RenderView view;
  DepthReads out;
  const bool fetch = has_depth_fetch();
  for (int tick = 1; tick <= 120; ++tick) {
    game.step(InputFrame{});
    if (tick % 3) continue;
    build_render_view(game.world(), models, 1.0, CameraSettings{}, no_hud, kWidth, kHeight, view);
    r.render(view, kWidth, kHeight);
    const FrameStats st = r.last_stats();
    ++out.frames;
    out.read += st.reads_depth();
    out.needed += st.soft_shaded > 0;
    out.mismatched += st.depth_fetched != (st.soft_shaded > 0 && fetch);
    out.mismatched += st.depth_copied != (st.soft_shaded > 0 && !fetch && !st.particles_half_res);
  }
  return out;
}

TEST(SceneWork, NoSoftParticleInViewNeverCopiesDepth) {
  REQUIRE_CONTEXT();
  const DepthReads off = gallery_depth_reads("off");
  EXPECT_EQ(off.frames, 40);
  EXPECT_EQ(off.read, 0) << "frames without a soft particle copied or fetched the depth";
  EXPECT_EQ(off.needed, 0);
  const DepthReads on = gallery_depth_reads("effect");
  EXPECT_GT(on.read, 0) << "the gallery's soft particles never reached a hull: the test shows nothing";
  EXPECT_EQ(on.mismatched, 0) << "a frame copied depth no particle read, or a particle read a depth never copied";
}

uint64_t skipped_particles_in_gallery(const Settings& s) {
  GameOptions o = test::options();
  apply_simulation_settings(s, o);
  Game game = Game::load_level(test::repo("levels/gallery.json"), o);
  uint64_t skipped = 0;
  for (int tick = 1; tick <= 120; ++tick) {
    game.step(InputFrame{});
    skipped += game.world().particles->stats().skipped_particles;
  }
  return skipped;
}

TEST(SceneWork, CullDistanceSettingReachesTheParticleWorld) {
  Settings near = all_settings();
  near.set("particles.cull_distance", "100", "test");
  Settings far = all_settings();
  far.set("particles.cull_distance", "1e12", "test");
  GameOptions o;
  apply_simulation_settings(near, o);
  EXPECT_EQ(o.cull_distance, 100.0);
  const uint64_t skipped_near = skipped_particles_in_gallery(near);
  EXPECT_GT(skipped_near, skipped_particles_in_gallery(far));
  EXPECT_GT(skipped_near, 1000u) << "the gallery's far effects should be beyond 100 m";
}

}  // namespace
}  // namespace arc
