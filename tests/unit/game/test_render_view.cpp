#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/error.h"
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

// Paused, the HUD keeps the FPS counter; the pause screen is the menu's page (menu_layout.h).
TEST(RenderView, PausedFpsAndOutcomeMessages) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  g.step(InputFrame{}, {Command::Pause});
  HudState hud;
  hud.show_fps = true;
  hud.fps = 59.7;
  RenderView v;
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, hud, 1280, 720, v);
  EXPECT_FALSE(has_text(v, "PAUSED"));
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

// The pause screen is drawn over it by the menu (menu_layout.h).
TEST(RenderView, HudOffDrawsNoFlightHudWhilePaused) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  g.step(InputFrame{}, {Command::Pause});
  HudState hud;
  hud.show_hud = false;
  HudLayer layer;
  RenderView v;
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, hud, 1280, 720, v);
  layout_hud(g.world(), v.camera, hud, 1.0, 1280, 720, layer);
  EXPECT_TRUE(v.hud.lines.empty());  // no crosshair, brackets or radar
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
  EXPECT_TRUE(has_text(v, "explosion through wall"));
  EXPECT_TRUE(has_text(v, "lightning_beam"));
  EXPECT_FALSE(has_text(v, "Beam target"));  // its ships are a cell's backdrop, labelled ""
  EXPECT_FALSE(v.particles.empty());
}

// The own shield and exhausts are gone from the cockpit; the own beam is thin on screen and
// faded toward the eye; the chase camera keeps the shield only away from the crosshair.
TEST(RenderView, OwnEffectsLeaveThePilotsView) {
  for (bool cockpit : {true, false}) {
    Game g = Game::load_level(test::repo("tests/replays/levels/range.json"), test::options());
    InputFrame fire;
    fire.buttons = kFirePrimary;
    g.step(fire, cockpit ? std::vector<Command>{Command::CameraToggle} : std::vector<Command>{});
    g.world_mut().ships[0].shield_flash_tick = 0;  // a hit just now: the whole sphere lit
    for (int i = 0; i < 20; ++i) g.step(fire);
    const Ship& me = g.world().ships[0];
    ASSERT_TRUE(me.beam_firing);
    RenderView v;
    build_render_view(g.world(), {}, 1.0, CameraSettings{}, HudState{}, 1280, 720, v);
    auto owned_by = [](const std::vector<ClusterHandle>& handles, const ParticleInstance& p) {
      for (ClusterHandle h : handles)
        if (h.index == p.cluster) return true;
      return false;
    };
    const double focal = 360.0 / std::tan(0.5 * v.camera.fov_y_radians);
    int beam = 0, shield = 0;
    for (const ParticleInstance& p : v.particles) {
      const glm::dvec3 at = glm::conjugate(v.camera.orientation) * glm::dvec3(p.pos[0], p.pos[1], p.pos[2]);
      if (owned_by(me.shield_fx.clusters, p)) {
        ++shield;
        const double dx = at.x / -at.z * focal, dy = at.y / -at.z * focal;  // from the screen centre
        EXPECT_GT(std::sqrt(dx * dx + dy * dy), 0.2 * 720) << "own shield near the crosshair";
      }
      if (!owned_by(me.beam_channels, p)) continue;
      ++beam;
      EXPECT_LE(p.size / -at.z * focal, 0.0051 * 720) << "own beam wider than its limit on screen";
      if (glm::length(at) < 1.0) {
        EXPECT_EQ(p.color[3], 0.0f);
      }
    }
    EXPECT_GT(beam, 0);
    EXPECT_EQ(shield > 0, !cockpit) << shield << " own shield particles drawn";
  }
}

// An enemy beam striking the own shield in the cockpit ends a few metres from the eye: it is
// kept to its on-screen width limit rather than filling the view.
TEST(RenderView, OtherShipsBeamsStayBoltsNearTheEye) {
  const std::string level = test::write_level("beam_at_eye.json", test::level_text(R"(
    { "name": "Player", "class": "viper", "team": "blue", "player": true },
    { "name": "Gunner", "class": "viper", "team": "red", "ai": "gunner", "position": [0, 0, -200], "orientation": [180, 0, 0] })"));
  Game g = Game::load_level(level, test::options());
  g.step(InputFrame{}, {Command::CameraToggle});
  for (int i = 0; i < 30; ++i) g.step(InputFrame{});
  const Ship& gunner = g.world().ships[1];
  ASSERT_TRUE(gunner.beam_firing);
  RenderView v;
  build_render_view(g.world(), {}, 1.0, CameraSettings{}, HudState{}, 1280, 720, v);
  const double focal = 360.0 / std::tan(0.5 * v.camera.fov_y_radians);
  int near_eye = 0;
  for (const ParticleInstance& p : v.particles) {
    bool beam = false;
    for (ClusterHandle h : gunner.beam_channels) beam = beam || h.index == p.cluster;
    if (!beam) continue;
    const glm::dvec3 at = glm::conjugate(v.camera.orientation) * glm::dvec3(p.pos[0], p.pos[1], p.pos[2]);
    EXPECT_LE(p.size / -at.z * focal, 0.0201 * 720);
    near_eye += glm::length(at) < 20.0 ? 1 : 0;
  }
  EXPECT_GT(near_eye, 0);  // the beam does reach the own shield
}

// Blue and red have default colours, a level may add teams (and recolour those two), and a
// team without a colour keeps the models' own (strength 0).
TEST(TeamColors, FromTheLevelTableOnShipMeshes) {
  const std::string level = test::write_level("teams.json", test::level_text(R"(
    { "name": "A", "class": "viper", "team": "blue", "player": true },
    { "name": "B", "class": "viper", "team": "red", "position": [0, 0, -100] },
    { "name": "C", "class": "dart", "team": "green", "position": [50, 0, -100] },
    { "name": "D", "class": "dart", "team": "neutral", "position": [-50, 0, -100] })",
                                                                                 R"(
  "team_colors": { "green": [0.2, 0.9, 0.3], "red": [0.9, 0.1, 0.1] },)"));
  Game g = Game::load_level(level, test::options());
  g.step(InputFrame{});
  RenderView v;
  std::vector<ModelId> ids;  // a renderer id for each of the level's model slots
  for (size_t i = 0; i < required_models(g.world()).size(); ++i) ids.push_back(ModelId::from_index(i));
  build_render_view(g.world(), ids, 1.0, CameraSettings{}, HudState{}, 640, 360, v);
  ASSERT_GE(v.meshes.size(), 4u);
  EXPECT_GT(v.meshes[0].team_color.b, 0.9f);  // the default blue
  EXPECT_EQ(v.meshes[0].team_color.a, 1.0f);
  EXPECT_EQ(glm::vec3(v.meshes[1].team_color), glm::vec3(0.9f, 0.1f, 0.1f));
  EXPECT_EQ(glm::vec3(v.meshes[2].team_color), glm::vec3(0.2f, 0.9f, 0.3f));
  EXPECT_EQ(v.meshes[3].team_color.a, 0.0f);
}

TEST(TeamColors, BadColourNamesItsPlace) {
  const std::string level = test::write_level("bad_teams.json", test::level_text(R"(
    { "name": "A", "class": "viper", "team": "blue", "player": true })",
                                                                                 R"(
  "team_colors": { "green": [0.2, 1.5, 0.3] },)"));
  try {
    Game::load_level(level, test::options());
    FAIL() << "a colour channel above 1 loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad_teams.json:7:"), std::string::npos) << e.what();
  }
}

// Exhaust particles move toward the team colour (about as bright as they were), alpha unchanged.
TEST(TeamColors, ExhaustsTintedTowardTheTeam) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  InputFrame full;
  full.throttle = 127;
  for (int i = 0; i < 30; ++i) g.step(full);
  const World& w = g.world();
  RenderView v;
  build_render_view(w, {}, 1.0, CameraSettings{}, HudState{}, 640, 360, v);
  std::vector<ParticleInstance> raw;
  ParticleCamera pc;
  pc.position = v.camera.position;
  pc.orientation = v.camera.orientation;
  pc.fov_y_radians = v.camera.fov_y_radians;
  pc.aspect = 640.0 / 360.0;
  w.particles->collect(pc, raw);
  std::vector<uint32_t> exhaust;
  for (const EffectHandle& e : w.ships[0].exhaust_fx)
    for (ClusterHandle h : e.clusters) exhaust.push_back(h.index);
  int tinted = 0;
  size_t j = 0;
  for (const ParticleInstance& p : raw) {
    const bool is_exhaust = std::find(exhaust.begin(), exhaust.end(), p.cluster) != exhaust.end();
    if (!is_exhaust) continue;
    while (j < v.particles.size() && v.particles[j].cluster != p.cluster) ++j;
    ASSERT_LT(j, v.particles.size());
    const ParticleInstance& q = v.particles[j++];
    EXPECT_EQ(q.color[3], p.color[3]);
    const float before = std::max({p.color[0], p.color[1], p.color[2]}), after = std::max({q.color[0], q.color[1], q.color[2]});
    EXPECT_LE(after, before + 1e-6f);
    EXPECT_GE(after, 0.7f * before);
    tinted += q.color[0] < p.color[0] || q.color[2] > p.color[2] ? 1 : 0;  // toward blue
  }
  EXPECT_GT(tinted, 0);
}

}  // namespace
}  // namespace arc
