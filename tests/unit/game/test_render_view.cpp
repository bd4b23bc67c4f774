#include <gtest/gtest.h>

#include "game/render/render_view_builder.h"
#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

bool has_text(const RenderView& v, const std::string& s) {
  for (const HudText& t : v.hud.texts)
    if (t.text.find(s) != std::string::npos) return true;
  return false;
}

// The usage example of game/render/render_view_builder.h, word for word.
TEST(RenderViewBuilder, BannerExample) {
  const GameOptions options = test::options();
  Game game = Game::load_level("levels/duel.json", options);
  game.step(InputFrame{});
  RenderView view;
  // The renderer's id of each required_models(game.world()) entry, as load_scene_resources returns them:
  const std::vector<ModelId> models{ModelId{1u}, ModelId{2u}};
  build_render_view(game.world(), models, 0.5, CameraSettings{}, HudState{}, 1280, 720, view);
  // every view.meshes[i].model is one of `models`; Renderer::render(view, 1280, 720)

  ASSERT_FALSE(view.meshes.empty());
  ASSERT_EQ(models.size(), required_models(game.world()).size());
  for (const MeshInstance& m : view.meshes) EXPECT_TRUE(m.model == models[0] || m.model == models[1]);
  EXPECT_FALSE(view.hud.texts.empty());
}

TEST(RenderView, MeshesForLiveShipsAndPropsWithLevelModelTable) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  const World& w = g.world();
  const auto& models = required_models(w);
  ASSERT_EQ(models.size(), 2u);  // viper and the asteroid
  EXPECT_EQ(models[0], "assets/models/viper.glb");
  // Slots map through the app's table, whatever ids the renderer gave; no table, no models.
  const std::vector<ModelId> ids{ModelId{7u}, ModelId{3u}};
  RenderView v, unloaded;
  build_render_view(w, ids, 1.0, CameraSettings{}, HudState{}, 1280, 720, v);
  ASSERT_EQ(v.meshes.size(), 3u);
  EXPECT_EQ(v.meshes[0].model, ModelId{7u});  // the player's viper
  EXPECT_EQ(v.meshes[2].model, ModelId{3u});  // the asteroid
  build_render_view(w, {}, 1.0, CameraSettings{}, HudState{}, 1280, 720, unloaded);
  for (const MeshInstance& m : unloaded.meshes) EXPECT_FALSE(m.model);
  EXPECT_TRUE(has_text(v, w.level.objective));
  EXPECT_FALSE(v.hud.lines.empty());  // crosshair
}

TEST(RenderView, InterpolatesBetweenPreviousAndCurrentTick) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  InputFrame f;
  f.throttle = 127;
  for (int i = 0; i < 30; ++i) g.step(f);
  const Ship& s = g.world().ships[0];
  RenderView a, b, c;
  build_render_view(g.world(), {}, 0.0, CameraSettings{}, HudState{}, 640, 360, a);
  build_render_view(g.world(), {}, 0.5, CameraSettings{}, HudState{}, 640, 360, b);
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, HudState{}, 640, 360, c);
  EXPECT_DOUBLE_EQ(a.meshes[0].position.z, s.prev_position.z);
  EXPECT_DOUBLE_EQ(c.meshes[0].position.z, s.position.z);
  EXPECT_NEAR(b.meshes[0].position.z, 0.5 * (s.prev_position.z + s.position.z), 1e-9);
  EXPECT_NE(a.camera.position.z, c.camera.position.z);
}

TEST(RenderView, TargetGetsBracketsOrAnArrowAndBars) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  g.step(InputFrame{}, {Command::TargetNextHostile});
  RenderView v;
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, HudState{}, 1280, 720, v);
  EXPECT_TRUE(has_text(v, "Red Leader"));
  const size_t lines_with_target = v.hud.lines.size();
  g.step(InputFrame{}, {Command::TargetNext});  // only one other ship: stays targeted
  RenderView none;
  World& w = g.world_mut();
  w.ships[0].target = ShipId{};
  build_render_view(w, {}, 1.0, CameraSettings{}, HudState{}, 1280, 720, none);
  EXPECT_GT(lines_with_target, none.hud.lines.size());
}

TEST(RenderView, PauseMenuFpsAndOutcomeMessages) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  g.step(InputFrame{}, {Command::Pause});
  HudState hud;
  hud.show_fps = true;
  hud.fps = 59.7;
  hud.pause_selection = 1;
  RenderView v;
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, hud, 1280, 720, v);
  EXPECT_TRUE(has_text(v, "PAUSED"));
  EXPECT_TRUE(has_text(v, "Restart"));
  EXPECT_TRUE(has_text(v, "60 fps"));
  g.step(InputFrame{}, {Command::Resume});
  g.world_mut().ships[1].hull = -1;
  g.step(InputFrame{});
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, HudState{}, 1280, 720, v);
  EXPECT_TRUE(has_text(v, "VICTORY"));
  EXPECT_FALSE(has_text(v, "PAUSED"));
}

TEST(RenderView, CameraSettingsOverrideTheWorldsModeAndFov) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  g.step(InputFrame{});
  RenderView chase, cockpit;
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, HudState{}, 1280, 720, chase);
  CameraSettings camera;
  camera.mode = CameraMode::Cockpit;
  camera.fov_deg = 90;
  build_render_view(g.world(), {}, 1.0, camera, HudState{}, 1280, 720, cockpit);
  EXPECT_EQ(cockpit.meshes.size() + 1, chase.meshes.size());  // the own ship is not drawn
  EXPECT_NEAR(cockpit.camera.fov_y_radians, 3.14159265358979323846 / 2, 1e-12);
  EXPECT_NE(chase.camera.fov_y_radians, cockpit.camera.fov_y_radians);
}

TEST(RenderView, HudOffLeavesOnlyThePauseMenu) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  g.step(InputFrame{}, {Command::Pause});
  HudState hud;
  hud.show_hud = false;
  HudLayer layer;
  RenderView v;
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, hud, 1280, 720, v);
  layout_hud(g.world(), v.camera, hud, 1.0, 1280, 720, layer);
  EXPECT_TRUE(v.hud.lines.empty());  // no crosshair, brackets or radar
  EXPECT_TRUE(has_text(v, "PAUSED"));
  EXPECT_EQ(layer.texts.size(), v.hud.texts.size());
}

TEST(RenderView, CockpitHidesOwnShipAndGalleryLabelsEverything) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  g.step(InputFrame{}, {Command::CameraToggle});
  RenderView v;
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, HudState{}, 1280, 720, v);
  EXPECT_EQ(v.meshes.size(), 2u);
  Game gal = Game::load_level(test::repo("levels/gallery.json"), test::options());
  for (int i = 0; i < 10; ++i) gal.step(InputFrame{});
  build_render_view(gal.world(), {}, 1.0, CameraSettings{}, HudState{}, 1280, 720, v);
  EXPECT_TRUE(has_text(v, "wall.glb"));
  EXPECT_TRUE(has_text(v, "lightning_beam"));
  EXPECT_TRUE(has_text(v, "Hull target"));
  EXPECT_FALSE(v.particles.empty());
}

}  // namespace
}  // namespace arc
