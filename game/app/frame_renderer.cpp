// Headless frames: an EGL context, a Renderer with the level's resources, and read-back to an Image.
#include "game/app/frame_renderer.h"

#include "core/data_layers.h"
#include "game/app/key_remap.h"
#include "game/app/scene_resources.h"
#include "game/render/render_view_builder.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "gfx/renderer.h"
#include "platform/platform.h"

namespace arc {

struct FrameRenderer::Impl {
  FrameRendererDesc desc;
  std::unique_ptr<HeadlessContext> context;
  std::unique_ptr<Renderer> renderer;
  std::vector<ModelId> models;  // the renderer's id of each of the level's model slots
  RenderView view;
  HudState hud;  // headless frames: the default bindings' keys in training prompts
  Settings settings;
  std::vector<std::string> model_paths;  // the level the models were loaded for
};

FrameRenderer::FrameRenderer(const FrameRendererDesc& desc, const Settings& settings, const Game& game)
    : impl_(std::make_unique<Impl>()) {
  impl_->desc = desc;
  impl_->context = create_headless_context();
  RendererDesc rd;
  rd.shader_dir = desc.root_dir + "/shaders";
  rd.offscreen = true;
  try {
    impl_->renderer = std::make_unique<Renderer>(rd);
  } catch (const std::runtime_error& e) {
    throw PlatformError(std::string("renderer: ") + e.what());
  }
  impl_->renderer->apply_settings(settings);
  impl_->settings = settings;
  impl_->hud.key_names = key_names(load_bindings(data_file(desc.root_dir, "assets/settings/bindings.json")));
  impl_->models = load_scene_resources(*impl_->renderer, game.world(), desc.root_dir);
  impl_->model_paths = game.world().model_paths;
}

void FrameRenderer::load_level(const Game& game) {
  if (game.world().model_paths == impl_->model_paths) return;
  RendererDesc rd;
  rd.shader_dir = impl_->desc.root_dir + "/shaders";
  rd.offscreen = true;
  impl_->renderer = std::make_unique<Renderer>(rd);
  impl_->renderer->apply_settings(impl_->settings);
  impl_->models = load_scene_resources(*impl_->renderer, game.world(), impl_->desc.root_dir);
  impl_->model_paths = game.world().model_paths;
}

Image FrameRenderer::render(const Game& game, double alpha, const HudState& hud, const HudLayer& overlay) {
  const int w = impl_->desc.width, h = impl_->desc.height;
  build_render_view(game.world(), impl_->models, alpha, CameraSettings{}, hud, w, h, impl_->view);
  HudLayer& layer = impl_->view.hud;
  layer.quads.insert(layer.quads.end(), overlay.quads.begin(), overlay.quads.end());
  layer.lines.insert(layer.lines.end(), overlay.lines.begin(), overlay.lines.end());
  layer.texts.insert(layer.texts.end(), overlay.texts.begin(), overlay.texts.end());
  impl_->renderer->render(impl_->view, w, h);
  return impl_->renderer->read_pixels();
}

FrameRenderer::~FrameRenderer() = default;

Image FrameRenderer::render(const Game& game, double alpha) {
  build_render_view(game.world(), impl_->models, alpha, CameraSettings{}, impl_->hud, impl_->desc.width, impl_->desc.height,
                    impl_->view);
  impl_->renderer->render(impl_->view, impl_->desc.width, impl_->desc.height);
  return impl_->renderer->read_pixels();
}

std::string FrameRenderer::gl_renderer() const { return impl_->renderer->gl_renderer(); }

}  // namespace arc
