// The usage examples of the renderer's passes and GL helpers as tests, in the headless EGL
// context (HeaderExamples.MatchTheirTests keeps each banner and its test the same text).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/data_root.h"
#include "gfx/bloom_pass.h"
#include "gfx/gpu_timers.h"
#include "gfx/hud_pass.h"
#include "gfx/mesh_pass.h"
#include "gfx/particle_batch.h"
#include "gfx/particle_pass.h"
#include "gfx/particle_target.h"
#include "gfx/post_pass.h"
#include "gfx/render_targets.h"
#include "gfx/shader_programs.h"
#include "gfx/sky_pass.h"
#include "gfx/view_projection.h"
#include "gfx_test_util.h"

namespace arc {
namespace {

// What the pass examples take as given: a view with a few particles, the settings, the
// programs and the scene targets of a 1280x720 frame.
struct Frame {
  RenderView view = test::dark_view();
  RenderSettings settings = test::plain_settings();
  int scene_w = 1280, scene_h = 720;
  ViewProjection vp = make_view_projection(view.camera, 1280.0 / 720.0, true, true);
  Frame() {
    for (int i = 0; i < 4; ++i)
      view.particles.push_back(scenes::particle({float(i), 0.0f, -10.0f}, 1.0f, {1, 0.5f, 0.2f}, 0.5f, 0.0f,
                                                SoftEdge::Linear));
    view.hud.texts.push_back({8, 8, 1.0f, {1, 1, 1, 1}, "SHIELD 100"});
  }
};

TEST(GlExamples, ShaderPrograms) {
  REQUIRE_CONTEXT();
  ShaderPrograms programs(data_root() + "/shaders");  // throws when a shader fails
  glUseProgram(programs.mesh.id);
  glUniform1i(programs.mesh.loc("u_base_tex"), 0);
  std::string error = programs.reload();              // empty on success
  EXPECT_EQ(error, "");
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(GlExamples, RenderTargets) {
  REQUIRE_CONTEXT();
  ShaderPrograms programs(arc::data_root() + "/shaders");
  RenderTargets targets(/*offscreen=*/true, /*float_scene=*/false);
  targets.ensure(1280, 720, 1.0, {});  // (re)allocates on a size or format change
  targets.bind_opaque();               // ... opaque passes ...
  targets.resolve_opaque(programs.msaa_resolve);  // no-op without MSAA
  targets.copy_depth();                // ... particles sample depth_copy() ...
  targets.resolve(1280, 720);          // ... HUD ...
  Image frame = targets.read_pixels();
  EXPECT_EQ(frame.width, 1280);
  EXPECT_EQ(frame.height, 720);
}

TEST(GlExamples, BloomPass) {
  REQUIRE_CONTEXT();
  const Frame f;
  const int scene_w = f.scene_w, scene_h = f.scene_h;
  ShaderPrograms programs(arc::data_root() + "/shaders");
  RenderTargets targets(true, false);
  targets.ensure(scene_w, scene_h, 1.0, {.hdr = true});
  BloomPass bloom;
  GLuint glow = bloom.run(targets.scene_color(), scene_w, scene_h, programs);
  // glow: (scene_w / 4) × (scene_h / 4), the sum of levels 1 to 5
  EXPECT_NE(glow, 0u);
  EXPECT_EQ(bloom.summed_levels(), 5);
}

TEST(GlExamples, GpuTimers) {
  REQUIRE_CONTEXT();
  RenderTargets targets(true, false);
  targets.ensure(64, 64, 1.0, {});
  targets.bind_opaque();
  GpuTimers timers;
  timers.collect_finished();                 // at the start of a frame
  timers.begin_particle_pass();
  targets.copy_depth();                      // and the particle draws
  double ms = timers.end_particle_pass();    // −1 unless time_passes is on
  EXPECT_EQ(ms, -1.0);
}

TEST(GlExamples, HudPass) {
  REQUIRE_CONTEXT();
  const Frame f;
  const RenderView& view = f.view;
  ShaderPrograms programs(arc::data_root() + "/shaders");
  RenderTargets targets(true, false);
  targets.ensure(1280, 720, 1.0, {});
  targets.resolve(1280, 720);
  HudPass hud;
  int draw_calls = hud.draw(view.hud, programs.hud, 1280, 720);
  EXPECT_GE(draw_calls, 1);
}

TEST(GlExamples, MeshPass) {
  REQUIRE_CONTEXT();
  Frame f;
  RenderView& view = f.view;
  const RenderSettings& settings = f.settings;
  const ViewProjection& vp = f.vp;
  ShaderPrograms programs(arc::data_root() + "/shaders");
  RenderTargets targets(true, false);
  targets.ensure(1280, 720, 1.0, {});
  targets.bind_opaque();
  MeshPass meshes;
  int ship = meshes.add_model(load_model("assets/models/viper.glb"), settings.filter);
  view.meshes.push_back({.model = ModelId::from_index(size_t(ship)), .position = {0.0, 0.0, -20.0}});
  int draw_calls = meshes.draw(view, programs.mesh, vp.view_proj, settings.reversed_z, settings.hdr);
  EXPECT_GE(draw_calls, 1);
}

TEST(GlExamples, ParticlePass) {
  REQUIRE_CONTEXT();
  const Frame f;
  const RenderSettings& settings = f.settings;
  ShaderPrograms programs(arc::data_root() + "/shaders");
  RenderTargets targets(true, false);
  targets.ensure(f.scene_w, f.scene_h, 1.0, {});
  targets.bind_opaque();
  ParticleBatch batch;
  batch.prepare(f.view, f.vp, {}, {});
  ParticleFrame frame;
  frame.vp = f.vp;
  frame.depth_copy = targets.depth_copy();
  frame.scene_width = f.scene_w;
  frame.scene_height = f.scene_h;
  targets.bind_scene();
  ParticlePass particles(0);
  particles.set_sprites({load_sprite("assets/textures/sprite_smoke.png")}, settings.filter);
  particles.upload(batch);  // its particles, or an indexed batch's source and order
  if (batch.any_soft) targets.copy_depth();
  particles.draw(batch, programs, settings, frame);  // one draw per run
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(GlExamples, ParticleTarget) {
  REQUIRE_CONTEXT();
  const Frame f;
  const int scene_w = f.scene_w, scene_h = f.scene_h;
  const RenderSettings& settings = f.settings;
  ShaderPrograms programs(arc::data_root() + "/shaders");
  RenderTargets targets(true, false);
  targets.ensure(scene_w, scene_h, 1.0, {});
  ParticleBatch batch;
  batch.prepare(f.view, f.vp, {}, {});
  ParticlePass particles(0);
  particles.set_sprites({load_sprite("assets/textures/sprite_smoke.png")}, settings.filter);
  particles.upload(batch.particles);
  ParticleFrame frame;
  frame.vp = f.vp;
  frame.transmittance_alpha = true;
  const std::vector<PixelRect> rects{{0, 0, scene_w, scene_h}};
  ParticleTarget half;
  half.begin(targets.scene_fbo(), scene_w, scene_h, targets.scene_internal_format());
  frame.scene_width = half.width();
  frame.scene_height = half.height();
  particles.draw(batch, programs, settings, frame);  // frame.transmittance_alpha = true
  half.composite(programs.particle_composite, targets.scene_color_fbo(), scene_w, scene_h, rects);
  EXPECT_EQ(half.width(), scene_w / 2);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(GlExamples, PostPass) {
  REQUIRE_CONTEXT();
  const int scene_w = 1280, scene_h = 720;
  const GLuint bloom_tex = 0;
  ShaderPrograms programs(arc::data_root() + "/shaders");
  RenderTargets targets(true, false);
  targets.ensure(scene_w, scene_h, 1.0, {.hdr = true});
  PostPass post;
  post.run({targets.scene_color(), scene_w, scene_h, bloom_tex, 0.1f, 1.0f, true, true}, programs, targets,
           1280, 720);
  EXPECT_EQ(targets.read_pixels().width, 1280);
}

TEST(GlExamples, SkyPass) {
  REQUIRE_CONTEXT();
  const Frame f;
  const RenderView& view = f.view;
  const RenderSettings& settings = f.settings;
  const ViewProjection& vp = f.vp;
  const int scene_w = f.scene_w, scene_h = f.scene_h;
  ShaderPrograms programs(arc::data_root() + "/shaders");
  RenderTargets targets(true, false);
  targets.ensure(scene_w, scene_h, 1.0, {});
  targets.bind_opaque();
  SkyPass sky;
  int draw_calls = sky.draw_nebula(view, programs, vp, settings, scene_w, scene_h);
  draw_calls += sky.draw_stars(view, programs, vp, settings, scene_h);
  EXPECT_GE(draw_calls, 2);
}

}  // namespace
}  // namespace arc
