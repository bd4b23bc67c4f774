// game/render/render_view_builder.h — turns the simulated World into a RenderView (no GL).
//
// The renderer never sees the game: build_render_view() interpolates ship and camera
// transforms between the previous and the current tick by `alpha`, lists meshes by model
// index, collects the visible particles (ParticleWorld::collect) and lays out the HUD in
// pixels: crosshair, target brackets, off-screen arrow, lead indicator, own and target bars,
// radar, kills, objective, victory/defeat, FPS counter, pause menu, and gallery labels.
//
// Model indices are positions in World::model_paths (required_models()): the app loads
// exactly those files, in that order, into its renderer's model table.
//
//   for (auto& path : required_models(game.world())) renderer.load_model(path);
//   RenderView view;
//   build_render_view(game.world(), clock.alpha(), CameraSettings{}, width, height, view);
//   renderer.draw(view);
#pragma once
#include <string>
#include <vector>

#include "gfx/render_view.h"

namespace arc {

class World;

struct CameraSettings {
  bool use_world_mode = true;  // false: `mode` below overrides the World's camera mode
  int mode = 0;                // CameraMode: 0 chase, 1 cockpit, 2 fixed (level's camera hint)
  double fov_deg = 0;          // 0 = the level's camera hint
  bool show_hud = true;
  bool show_fps = false;
  double fps = 0;              // shown when show_fps
  int pause_selection = 0;     // highlighted pause-menu item while the game is paused
  std::vector<std::string> pause_items{"Resume", "Restart", "Difficulty: normal", "Quit"};
};

const std::vector<std::string>& required_models(const World& world);

void build_render_view(const World& world, double alpha, const CameraSettings& settings, int width, int height,
                       RenderView& out);

}  // namespace arc
