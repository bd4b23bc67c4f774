// gfx/hud_pass.h — the 2-D overlay: quads, lines and text in pixels, one alpha-blended draw.
//
// Last pass of a frame, after the scene is resolved to the output, so it is sharp at any
// render scale. hud_font.h turns the HudLayer into triangles over its font atlas.
//
// Example, compiled as GlExamples.HudPass in tests/unit/gfx/test_gl_examples.cpp:
//   HudPass hud;
//   int draw_calls = hud.draw(view.hud, programs.hud, 1280, 720);
#pragma once
#include <epoxy/gl.h>

#include <vector>

#include "gfx/hud_font.h"
#include "gfx/render_view.h"
#include "gfx/shader_programs.h"

namespace arc {

class HudPass {
 public:
  HudPass();
  ~HudPass();
  HudPass(const HudPass&) = delete;
  HudPass& operator=(const HudPass&) = delete;

  // Draws into the bound framebuffer, `width` × `height` pixels, depth test off. Returns the
  // draw calls (0 when the layer is empty).
  int draw(const HudLayer& hud, const Program& program, int width, int height);

 private:
  HudFont font_;
  GLuint vao_ = 0, vbo_ = 0, font_tex_ = 0;
  std::vector<HudVertex> vertices_;
};

}  // namespace arc
