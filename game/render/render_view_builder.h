// game/render/render_view_builder.h — turns the simulated World into a RenderView (no GL).
//
// The renderer never sees the game: build_render_view() interpolates ship and camera
// transforms between the previous and the current tick by `alpha`, lists meshes with the
// renderer's ModelIds (ships with their team colour, game/render/team_colors.h), collects the
// visible particles (ParticleWorld::collect, exhausts tinted by team), keeps the followed
// ship's own shield, exhausts and beam out of its pilot's eyes (game/render/own_view.h) and
// lays out the HUD (layout_hud, game/render/hud_layout.h). The camera's mode and field of view
// come from the World unless CameraSettings (game/render/camera_settings.h) overrides them.
//
// Ships and props name their models by ModelSlot, a position in World::model_paths
// (required_models()). The app loads exactly those files into its renderer and passes the
// ModelId it got for each slot, in slot order (load_scene_resources, game/app/scene_resources.h);
// a slot without one (an empty table: nothing loaded) gives meshes with a null model.
//
// Example, compiled as RenderViewBuilder.BannerExample in tests/unit/game/test_render_view.cpp:
//   Game game = Game::load_level("levels/duel.json", options);
//   game.step(InputFrame{});
//   RenderView view;
//   // The renderer's id of each required_models(game.world()) entry, as load_scene_resources returns them:
//   const std::vector<ModelId> models{ModelId{1u}, ModelId{2u}};
//   build_render_view(game.world(), models, 0.5, CameraSettings{}, HudState{}, 1280, 720, view);
//   // every view.meshes[i].model is one of `models`; Renderer::render(view, 1280, 720)
#pragma once
#include <span>
#include <string>
#include <vector>

#include "game/render/camera_settings.h"
#include "game/render/hud_layout.h"
#include "gfx/render_view.h"

namespace arc {

class World;

const std::vector<std::string>& required_models(const World& world);

// The frame's camera at `alpha` between the previous tick and this one: the World's rig in its
// mode, or the level's fixed camera (build_render_view() draws through it).
CameraView frame_camera(const World& world, double alpha, const CameraSettings& camera);

// `models`: the renderer's ModelId for each of World::model_paths, in order.
void build_render_view(const World& world, std::span<const ModelId> models, double alpha, const CameraSettings& camera, const HudState& hud, int width,
                       int height, RenderView& out);

}  // namespace arc
