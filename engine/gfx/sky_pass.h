// gfx/sky_pass.h — the background at infinity: nebula and starfield, keyed by the level's seed.
//
// First pass of a frame, with depth off, into a scene buffer whose colour is not cleared: it
// writes every pixel's colour and an alpha of 1 (the grid's cells and the full-screen triangle
// cover the screen), which the renderer relies on. The nebula is either
// looked up in a cube map baked once per seed, resolution and shader build (render.sky =
// baked) or evaluated per pixel (exact, the reference); the stars are points blended on top.
// The baked map is looked up at every pixel (render.sky_grid = 0) or at the corners of a
// screen grid of N-pixel cells and interpolated across them (16 by default: on llvmpipe the
// per-pixel cube-map sample was 2.5 ms of a 1280×720 frame, the grid's 7200 triangles about a
// quarter of that; 58–75 dB PSNR against the per-pixel lookup in every level).
// Both follow RenderView::starfield_seed, which also orients the nebula's two lobes. Their
// colours are display values; with HDR they are decoded to linear light as they are drawn
// (the baked map is baked again in linear light).
//
//   SkyPass sky;
//   int draw_calls = sky.draw(view, programs, make_view_projection(...), settings, scene_height);
#pragma once
#include <epoxy/gl.h>

#include <cstdint>

#include <glm/vec3.hpp>

#include "gfx/render_settings.h"
#include "gfx/render_view.h"
#include "gfx/shader_programs.h"
#include "gfx/view_projection.h"

namespace arc {

class SkyPass {
 public:
  SkyPass();
  ~SkyPass();
  SkyPass(const SkyPass&) = delete;
  SkyPass& operator=(const SkyPass&) = delete;

  // Draws into the bound framebuffer; `scene_height` sizes the stars. Returns the draw calls.
  int draw(const RenderView& view, const ShaderPrograms& programs, const ViewProjection& vp,
           const RenderSettings& settings, int scene_height);

 private:
  void build_stars(uint64_t seed);
  void bake(const ShaderPrograms& programs, int resolution, bool linear);
  void set_uniforms(const Program& p, const glm::mat3& basis, float tan_x, float tan_y) const;

  GLuint empty_vao_ = 0;  // the full-screen triangle is made in the vertex shader
  GLuint star_vao_ = 0, star_vbo_ = 0;
  int star_count_ = 0;
  uint64_t star_seed_ = ~0ull;
  glm::vec3 lobe_a_{1, 0, 0}, lobe_b_{0, 1, 0};
  // The baked nebula and what it was baked for: made again when the seed, the resolution or
  // the shaders change. One map of display values, one in linear light (HDR), so switching
  // render.hdr does not bake again.
  struct BakedCube {
    GLuint tex = 0;
    int size = 0;
    uint64_t seed = ~0ull;
    int shader_generation = -1;
  };
  BakedCube cubes_[2];  // [hdr]
  GLuint cube_fbo_ = 0;
};

}  // namespace arc
