// gfx/sky_pass.h — the background at infinity: nebula and starfield, keyed by the level's seed.
//
// First pass of a frame, with depth off, into a scene buffer whose colour is not cleared: the
// nebula writes every pixel's colour and an alpha of 1 (the grid and the full-screen triangle
// cover the screen), which the renderer relies on. The nebula is either looked up in a cube
// map baked once per seed, resolution and shader build (render.sky = baked) or evaluated per
// pixel (exact, the reference); the stars are points blended on top.
// The baked map is looked up at every pixel (render.sky_grid = 0) or at the corners of a
// screen grid of N-pixel cells and interpolated across them: the nebula is smooth at that
// scale, and a per-pixel cube-map sample is dear on a software rasteriser. The grid is drawn:
//  - into an 8-bit BGRA scene without MSAA (the default settings): the corners go into a small
//    texture of one texel per corner (sky_corners.frag), which one screen rectangle reads with
//    bilinear filtering into the scene's colour alone (`color_only_fbo`, no depth attached;
//    sky_cells.*), a plain texture read that llvmpipe's fast linear rasteriser takes;
//  - otherwise (float or multisampled scenes) as two Gouraud triangles a cell (sky_grid.*).
// The two interpolate a cell differently (bilinear against two planes), and the linear
// rasteriser interpolates in 8 bits, rounding down, so in the darkest nebula a faint lattice
// of 1/255 steps can show along the cells' edges. test_renderer.cpp bounds the error against
// the per-pixel lookup; docs/performance.md gives cost and PSNR per cell size.
// Both follow RenderView::starfield_seed, which also orients the nebula's two lobes. Their
// colours are display values; with HDR they are decoded to linear light as they are drawn
// (the baked map is baked again in linear light).
//
// Example, compiled as GlExamples.SkyPass in tests/unit/gfx/test_gl_examples.cpp:
//   SkyPass sky;
//   int draw_calls = sky.draw_nebula(view, programs, vp, settings, scene_w, scene_h);
//   draw_calls += sky.draw_stars(view, programs, vp, settings, scene_h);
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

  // The nebula, into the bound framebuffer: a scene of scene_width × scene_height. With
  // `color_only_fbo` (the scene's colour alone, 8-bit BGRA, not multisampled) it binds that and
  // draws there, and leaves it bound with a viewport over the scene. Returns the draw calls.
  int draw_nebula(const RenderView& view, const ShaderPrograms& programs, const ViewProjection& vp,
                  const RenderSettings& settings, int scene_width, int scene_height, GLuint color_only_fbo = 0);
  // The stars blended over the nebula, in the bound framebuffer; `scene_height` sizes them.
  // Not into the colour-only framebuffer: stars among the rectangle's tiles would cost
  // llvmpipe its linear rasteriser there.
  int draw_stars(const RenderView& view, const ShaderPrograms& programs, const ViewProjection& vp,
                 const RenderSettings& settings, int scene_height);
  // Bakes one face of the nebula for `seed` ahead of its first frame (a mission about to
  // launch), keeping the maps in use; true once all six faces are baked. A face costs about a
  // sixth of a whole bake, which a launch frame would otherwise pay at once.
  bool warm(uint64_t seed, const ShaderPrograms& programs, const RenderSettings& settings);

 private:
  struct BakedCube;
  void build_stars(uint64_t seed);
  // The map for this seed and look, made (or taken from the least recently used) if missing.
  BakedCube& cube_for(uint64_t seed, const ShaderPrograms& programs, const RenderSettings& settings);
  // Bakes faces [first, last) of `cube`.
  void bake_faces(BakedCube& cube, const ShaderPrograms& programs, int first, int last);
  void set_uniforms(const Program& p, const glm::mat3& basis, float tan_x, float tan_y) const;
  // The grid of N-pixel cells over a scene, the last row and column cut at its edge.
  struct SkyGrid {
    int n, scene_w, scene_h, cells_x, cells_y;
    float cell_ndc_x, cell_ndc_y;  // a cell's size in normalised device coordinates
  };
  static SkyGrid sky_grid_of(int n, int scene_w, int scene_h);
  void draw_corner_cells(const ShaderPrograms& programs, const glm::mat3& basis, float tan_x, float tan_y,
                         int cube_size, const SkyGrid& grid, GLuint color_only_fbo);

  GLuint empty_vao_ = 0;  // the full-screen triangle is made in the vertex shader
  GLuint corner_tex_ = 0, corner_fbo_ = 0;  // one BGRA texel per grid corner
  int corners_x_ = 0, corners_y_ = 0;
  GLuint star_vao_ = 0, star_vbo_ = 0;
  int star_count_ = 0;
  uint64_t star_seed_ = ~0ull;
  glm::vec3 lobe_a_{1, 0, 0}, lobe_b_{0, 1, 0};
  // The baked nebulae and what each was baked for: made again when the seed, the resolution,
  // the colour space (render.hdr) or the shaders change. A few are kept, so the menu's sky and
  // the mission's both stay ready, and switching render.hdr does not bake again.
  struct BakedCube {
    GLuint tex = 0;
    int size = 0;
    uint64_t seed = ~0ull;
    bool linear = false;
    int shader_generation = -1;
    int faces = 0;          // faces baked so far, in order
    uint64_t last_use = 0;  // for eviction: the least recently used map goes first
  };
  static constexpr int kKeptCubes = 4;
  BakedCube cubes_[kKeptCubes];
  uint64_t use_clock_ = 0;
  GLuint cube_fbo_ = 0;
};

}  // namespace arc
