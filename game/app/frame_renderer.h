// game/app/frame_renderer.h — renders Game state to images without a window.
//
// Owns an EGL headless context and a Renderer, loads only the models and sprites the level
// needs, and turns the current (interpolated) game state into an RGBA8 image. Used by
// `arcfire --headless --out`, replay snapshots, the attract demo and the golden-image tests.
// Creating one is the only thing that makes a GL context: replays without snapshots never do.
#pragma once
#include <memory>
#include <string>

#include "assets/image.h"
#include "core/data_root.h"
#include "core/settings.h"
#include "game/render/hud_layout.h"

namespace arc {

class Game;

struct FrameRendererDesc {
  int width = 1280;
  int height = 720;
  std::string root_dir = data_root();  // shaders/, assets/ (core/data_root.h)
};

class FrameRenderer {
 public:
  // Throws PlatformError (no EGL/GL) or InputError (bad assets).
  FrameRenderer(const FrameRendererDesc& desc, const Settings& settings, const Game& game);
  ~FrameRenderer();
  Image render(const Game& game, double alpha = 1.0);
  // With the HUD of `hud`, and `overlay` (a menu) drawn over it.
  Image render(const Game& game, double alpha, const HudState& hud, const HudLayer& overlay);
  // Loads the models of another level's game (a new renderer when they differ).
  void load_level(const Game& game);
  std::string gl_renderer() const;  // the device that draws (Renderer::gl_renderer)

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace arc
