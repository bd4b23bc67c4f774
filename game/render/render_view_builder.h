// game/render/render_view_builder.h — turns the simulated World into a RenderView (no GL).
//
// The renderer never sees the game: build_render_view() interpolates ship and camera
// transforms between the previous and the current tick by `alpha`, lists meshes by model
// index (ships with their team colour, game/render/team_colors.h), collects the visible
// particles (ParticleWorld::collect, exhausts tinted by team), keeps the followed ship's own
// shield, exhausts and beam out of its pilot's eyes (game/render/own_view.h) and lays out the
// HUD (layout_hud, game/render/hud_layout.h). The camera's mode and field of view come from
// the World unless CameraSettings (game/render/camera_settings.h) overrides them.
//
// Model indices are positions in World::model_paths (required_models()): the app loads
// exactly those files, in that order, into its renderer's model table
// (load_scene_resources, game/app/scene_resources.h).
//
// Example, compiled as RenderViewBuilder.BannerExample in tests/unit/game/test_render_view.cpp:
//   Game game = Game::load_level("levels/duel.json", options);
//   game.step(InputFrame{});
//   RenderView view;
//   build_render_view(game.world(), 0.5, CameraSettings{}, HudState{}, 1280, 720, view);
//   // view.meshes[i].model indexes required_models(game.world()); Renderer::render(view, 1280, 720)
#pragma once
#include <string>
#include <vector>

#include "game/render/camera_settings.h"
#include "game/render/hud_layout.h"
#include "gfx/render_view.h"

namespace arc {

class World;

const std::vector<std::string>& required_models(const World& world);

void build_render_view(const World& world, double alpha, const CameraSettings& camera, const HudState& hud, int width,
                       int height, RenderView& out);

}  // namespace arc
