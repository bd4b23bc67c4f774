// Headless frames: an EGL context, a Renderer with the level's resources, and read-back to an Image.
#include "game/app/frame_renderer.h"

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
  impl_->models = load_scene_resources(*impl_->renderer, game.world(), desc.root_dir);
}

FrameRenderer::~FrameRenderer() = default;

Image FrameRenderer::render(const Game& game, double alpha) {
  build_render_view(game.world(), impl_->models, alpha, CameraSettings{}, HudState{}, impl_->desc.width, impl_->desc.height,
                    impl_->view);
  impl_->renderer->render(impl_->view, impl_->desc.width, impl_->desc.height);
  return impl_->renderer->read_pixels();
}

std::string FrameRenderer::context_description() const { return impl_->context->description(); }

}  // namespace arc
