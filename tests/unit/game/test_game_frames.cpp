// tests/unit/game/test_game_frames.cpp — game frames rendered headless through EGL.
//
// OwnView: the player's own effects stay out of their eyes: a ship under fire (and firing its
// beam) is rendered in the chase and cockpit cameras, once as build_render_view() makes the
// frame and once without any particle of the player's own clusters (shield, exhausts, beam);
// the pixels that differ around the crosshair are what the player's own effects cover there;
// the same in the lower half of the screen for the own shield and the hits around the own ship.
// TeamColors: a blue and a red Viper side by side show their team colour on stripes.
// ARCFIRE_GFX_DUMP=DIR saves the frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "assets/image.h"
#include "assets/model.h"
#include "game/app/all_settings.h"
#include "game/app/scene_resources.h"
#include "game/render/render_view_builder.h"
#include "game/sim/world.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "gfx_test_util.h"
#include "test_helpers.h"
#include "core/data_root.h"

namespace arc {
namespace {

constexpr int kWidth = 1280, kHeight = 720;  // as a player sees it

// The player between two red gunners that hold still and fire everything ahead: one in front
// (beams and missiles hit the front of the player's shield, the player's beam hits it) and one
// behind and above (its hits land between the chase camera and the ship).
std::string under_fire_level() {
  return test::write_level("own_view.json", test::level_text(R"(
    { "name": "Player", "class": "viper", "team": "blue", "player": true, "position": [0, 0, 0] },
    { "name": "Front", "class": "viper", "team": "red", "ai": "gunner", "position": [0, 0, -240], "orientation": [180, 0, 0] },
    { "name": "Rear", "class": "viper", "team": "red", "ai": "gunner", "position": [0, 40, 200], "orientation": [0, -11.3, 0] })"));
}

std::vector<uint32_t> own_clusters(const Ship& s) {
  std::vector<uint32_t> out;
  for (ClusterHandle h : s.shield_fx.clusters) out.push_back(h.index);
  for (const EffectHandle& e : s.exhaust_fx)
    for (ClusterHandle h : e.clusters) out.push_back(h.index);
  for (ClusterHandle h : s.beam_channels) out.push_back(h.index);
  return out;
}

// The frame with the own effects and without them (saved under ARCFIRE_GFX_DUMP when set).
std::pair<Image, Image> render_with_and_without(Renderer& renderer, const RenderView& view, const RenderView& without,
                                                const std::string& dump_name) {
  renderer.render(view, kWidth, kHeight);
  const Image with_own = renderer.read_pixels();
  renderer.render(without, kWidth, kHeight);
  const Image no_own = renderer.read_pixels();
  if (const char* dir = std::getenv("ARCFIRE_GFX_DUMP"); dir && *dir) {
    save_image(std::string(dir) + "/" + dump_name + ".png", with_own);
    save_image(std::string(dir) + "/" + dump_name + "_without_own.png", no_own);
  }
  return {with_own, no_own};
}

struct Coverage {
  double share = 0;  // of the box around the crosshair
  int own_particles = 0;
};

// Steps the scene until the player has just been hit while firing, renders it with and without
// the player's own clusters and returns the share of the crosshair box that differs.
Coverage own_effect_coverage(bool cockpit, const std::string& dump_name) {
  Game game = Game::load_level(under_fire_level(), test::options());
  InputFrame fire;
  fire.buttons = kFirePrimary;
  game.step(fire, cockpit ? std::vector<Command>{Command::CameraToggle} : std::vector<Command>{});
  const World& w = game.world();
  const Ship& me = w.ship(w.player);
  for (int i = 0; i < 150 || me.last_hit_tick != w.tick; ++i) game.step(fire);
  EXPECT_EQ(me.last_hit_tick, w.tick);
  EXPECT_TRUE(me.beam_firing);

  Renderer renderer(RendererDesc{.offscreen = true});
  renderer.apply_settings(all_settings());
  const std::vector<ModelId> models = load_scene_resources(renderer, w, arc::data_root());
  HudState no_hud;
  no_hud.show_hud = false;
  RenderView view;
  build_render_view(w, models, 1.0, CameraSettings{}, no_hud, kWidth, kHeight, view);
  RenderView without = view;
  const std::vector<uint32_t> own = own_clusters(me);
  std::erase_if(without.particles, [&](const ParticleInstance& p) {
    return std::find(own.begin(), own.end(), p.cluster) != own.end();
  });
  Coverage result;
  result.own_particles = int(view.particles.size() - without.particles.size());
  const auto [with_own, no_own] = render_with_and_without(renderer, view, without, dump_name);

  // The crosshair: where the guns converge, half the beam's range ahead of the nose.
  const glm::dvec3 aim = me.position + forward_of(me.orientation) * (me.cls->beam.range * 0.5);
  const glm::dvec3 v = glm::conjugate(view.camera.orientation) * (aim - view.camera.position);
  const double focal = 0.5 * kHeight / std::tan(0.5 * view.camera.fov_y_radians);
  const double cx = 0.5 * kWidth + v.x / -v.z * focal, cy = 0.5 * kHeight - v.y / -v.z * focal;
  // A box of a tenth of the screen's area around it.
  const double side = std::sqrt(0.1);
  const int x0 = std::max(0, int(cx - 0.5 * side * kWidth)), x1 = std::min(kWidth, int(cx + 0.5 * side * kWidth));
  const int y0 = std::max(0, int(cy - 0.5 * side * kHeight)), y1 = std::min(kHeight, int(cy + 0.5 * side * kHeight));
  int differing = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const size_t i = (size_t(y) * kWidth + x) * 4;
      int d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(with_own.rgba[i + c]) - int(no_own.rgba[i + c])));
      differing += d > 8 ? 1 : 0;
    }
  result.share = double(differing) / double(std::max(1, (x1 - x0) * (y1 - y0)));
  std::printf("%s: own effects cover %.2f%% of the crosshair box (%d own particles drawn)\n", dump_name.c_str(),
              100.0 * result.share, result.own_particles);
  return result;
}

TEST(OwnView, OwnEffectsStayOffTheCrosshairInTheChaseCamera) {
  std::string why;
  if (!test::headless(why)) GTEST_SKIP() << "no EGL context: " << why;
  const Coverage c = own_effect_coverage(false, "own_view_chase");
  EXPECT_LT(c.share, 0.05);
}

TEST(OwnView, OwnEffectsStayOffTheCrosshairInTheCockpit) {
  std::string why;
  if (!test::headless(why)) GTEST_SKIP() << "no EGL context: " << why;
  const Coverage c = own_effect_coverage(true, "own_view_cockpit");
  EXPECT_LT(c.share, 0.05);
  EXPECT_GT(c.own_particles, 0);  // the own beam is still drawn
}

// The share of the lower half of the screen that the player's own shield and the hits around
// the own ship (every particle but beams within 1.6 shield radii of its centre or 12 m of the
// eye) take in the chase camera under fire: the frame against the same frame without them.
// `plain` draws them untamed (the whole shield sphere, the hits at full size) from a low,
// close camera.
double own_glow_lower_half(bool plain, const std::string& dump_name) {
  Game game = Game::load_level(under_fire_level(), test::options());
  InputFrame fire;
  fire.buttons = kFirePrimary;
  game.step(fire);
  const World& w = game.world();
  const Ship& me = w.ship(w.player);
  for (int i = 0; i < 150 || me.last_hit_tick != w.tick; ++i) game.step(fire);
  HudState hud;
  hud.show_hud = false;
  if (plain) {
    World& m = game.world_mut();
    const double R = me.cls->collision_radius;
    m.camera.orientation = me.orientation;
    m.camera.position = me.position + me.orientation * glm::dvec3(0, 0.45 * R + 2.0, 2.6 * R + 8.0);
    m.prev_camera = m.camera;
    hud.rules.own_view.rim_facing = 2.0;
    hud.rules.own_view.near_own_radius = 0.0;
    hud.rules.own_view.near_eye_m = 0.0;
  }
  Renderer renderer(RendererDesc{.offscreen = true});
  renderer.apply_settings(all_settings());
  const std::vector<ModelId> models = load_scene_resources(renderer, w, arc::data_root());
  RenderView view;
  build_render_view(w, models, 1.0, CameraSettings{}, hud, kWidth, kHeight, view);
  std::vector<uint32_t> shield, beams;
  for (ClusterHandle h : me.shield_fx.clusters) shield.push_back(h.index);
  for (const Ship& s : w.ships)
    for (ClusterHandle h : s.beam_channels) beams.push_back(h.index);
  const glm::dvec3 centre = me.position - view.camera.position;
  const double near_ship = 1.6 * me.cls->shield_radius;
  RenderView without = view;
  std::erase_if(without.particles, [&](const ParticleInstance& p) {
    if (std::find(shield.begin(), shield.end(), p.cluster) != shield.end()) return true;
    if (std::find(beams.begin(), beams.end(), p.cluster) != beams.end()) return false;
    const glm::dvec3 at(p.pos[0], p.pos[1], p.pos[2]);
    return glm::length(at) < 12.0 || glm::length(at - centre) < near_ship;
  });
  const auto [with_own, no_own] = render_with_and_without(renderer, view, without, dump_name);
  int lower = 0;
  for (int y = kHeight / 2; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const size_t i = (size_t(y) * kWidth + x) * 4;
      int d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(with_own.rgba[i + c]) - int(no_own.rgba[i + c])));
      lower += d > 8 ? 1 : 0;
    }
  const double share = double(lower) / double(kWidth * (kHeight - kHeight / 2));
  std::printf("%s: the own shield and hits cover %.2f%% of the lower half (%zu particles)\n", dump_name.c_str(),
              100.0 * share, view.particles.size() - without.particles.size());
  return share;
}

// Under fire the own shield is a rim and the hits are flashes where they land, not a glow over
// the lower half of the screen (the radar's corner included).
TEST(OwnView, UnderFireTheOwnShieldIsARimNotAGlow) {
  std::string why;
  if (!test::headless(why)) GTEST_SKIP() << "no EGL context: " << why;
  const double plain = own_glow_lower_half(true, "own_glow_plain");
  const double framed = own_glow_lower_half(false, "own_glow_chase");
  EXPECT_LT(framed, 0.10);
  EXPECT_LT(framed, 0.4 * plain);
}

int pixels_where(const Image& img, int x0, int x1, bool (*test)(float r, float g, float b)) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = x0; x < x1; ++x) {
      const size_t i = (size_t(y) * img.width + x) * 4;
      n += test(img.rgba[i] / 255.0f, img.rgba[i + 1] / 255.0f, img.rgba[i + 2] / 255.0f) ? 1 : 0;
    }
  return n;
}

TEST(TeamColors, ShipModelsMarkTheirTeamRegions) {
  for (const char* name : {"viper", "dart", "warden"}) {
    const ModelData m = load_model(arc::data_root() + "/assets/models/" + name + ".glb");
    int team = 0;
    for (const Material& mat : m.materials) team += mat.team_color > 0.0f ? 1 : 0;
    EXPECT_EQ(team, 2) << name << ": stripes and engine glow";
  }
  for (const Material& mat : load_model(arc::data_root() + "/assets/models/asteroid.glb").materials)
    EXPECT_EQ(mat.team_color, 0.0f);
}

// A blue Viper on the left and a red one on the right, seen from above and behind: blue pixels
// on the left and red ones on the right appear only with the team colours on.
TEST(TeamColors, BlueAndRedVipersWearTheirColours) {
  std::string why;
  if (!test::headless(why)) GTEST_SKIP() << "no EGL context: " << why;
  const std::string level = test::write_level("team_frame.json", test::level_text(R"(
    { "name": "Blue", "class": "viper", "team": "blue", "ai": "none", "position": [-11, 0, 0] },
    { "name": "Red", "class": "viper", "team": "red", "ai": "none", "position": [11, 0, 0] })",
                                                                                   R"(
  "camera": { "mode": "fixed", "position": [0, 30, 32], "look_at": [0, 0, 0], "fov": 50 },)"));
  Game game = Game::load_level(level, test::options());
  game.step(InputFrame{});
  Renderer renderer(RendererDesc{.offscreen = true});
  renderer.apply_settings(all_settings());
  const std::vector<ModelId> models = load_scene_resources(renderer, game.world(), arc::data_root());
  HudState no_hud;
  no_hud.show_hud = false;
  RenderView view;
  build_render_view(game.world(), models, 1.0, CameraSettings{}, no_hud, kWidth, kHeight, view);
  // The hulls only: the exhaust particles are blue whatever the team, and in the linear-light
  // (HDR) scene their additive glow is bright and wide enough to outnumber the stripes.
  view.particles.clear();
  renderer.render(view, kWidth, kHeight);
  const Image coloured = renderer.read_pixels();
  for (MeshInstance& m : view.meshes) m.team_color.a = 0.0f;
  renderer.render(view, kWidth, kHeight);
  const Image plain = renderer.read_pixels();
  if (const char* dir = std::getenv("ARCFIRE_GFX_DUMP"); dir && *dir) {
    save_image(std::string(dir) + "/team_colors.png", coloured);
    save_image(std::string(dir) + "/team_colors_off.png", plain);
  }
  auto blue = [](float r, float, float b) { return b > r + 0.25f; };
  auto red = [](float r, float, float b) { return r > b + 0.25f; };
  const int blue_left = pixels_where(coloured, 0, kWidth / 2, blue), red_right = pixels_where(coloured, kWidth / 2, kWidth, red);
  std::printf("team colours: %d blue pixels on the left (%d without), %d red on the right (%d without)\n", blue_left,
              pixels_where(plain, 0, kWidth / 2, blue), red_right, pixels_where(plain, kWidth / 2, kWidth, red));
  EXPECT_GT(blue_left, 400);
  EXPECT_GT(red_right, 400);
  EXPECT_GT(blue_left, 4 * pixels_where(plain, 0, kWidth / 2, blue));
  EXPECT_GT(red_right, 4 * pixels_where(plain, kWidth / 2, kWidth, red) + 1);
  EXPECT_LT(pixels_where(coloured, kWidth / 2, kWidth, blue), blue_left / 4);  // the red ship is not blue
}

}  // namespace
}  // namespace arc
