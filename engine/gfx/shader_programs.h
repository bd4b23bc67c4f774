// gfx/shader_programs.h — every GLSL program of the renderer, built from the shader folder.
//
// All programs build together or not at all: reload() compiles the whole folder again and, on
// any error, keeps the old programs and returns the compiler's text (hot reload while the game
// runs keeps the last good shaders on screen). generation() counts successful builds, so a pass
// that bakes something with a shader (the sky's cube map) knows to bake again.
//
// Example, compiled as GlExamples.ShaderPrograms in tests/unit/gfx/test_gl_examples.cpp:
//   ShaderPrograms programs(data_root() + "/shaders");  // throws when a shader fails
//   glUseProgram(programs.mesh.id);
//   glUniform1i(programs.mesh.loc("u_base_tex"), 0);
//   std::string error = programs.reload();              // empty on success
#pragma once
#include <epoxy/gl.h>

#include <string>
#include <vector>

namespace arc {

struct Program {
  GLuint id = 0;
  GLint loc(const char* name) const { return glGetUniformLocation(id, name); }
};

class ShaderPrograms {
 public:
  // Throws std::runtime_error("shader build failed: ...") when a program does not build.
  explicit ShaderPrograms(std::string shader_dir);
  ~ShaderPrograms();
  ShaderPrograms(const ShaderPrograms&) = delete;
  ShaderPrograms& operator=(const ShaderPrograms&) = delete;

  // Rebuilds every program from the folder; on error the old ones stay and the error text is
  // returned, an empty string means success.
  std::string reload();
  int generation() const { return generation_; }

  Program sky, sky_exact, sky_grid, sky_corners, sky_cells, stars, mesh, hud;
  // particle.vert + particle.frag: hard edges (SOFT 0), and the soft variants by
  // particle_soft[curve][density extent][fetch]: the curve linear (kSoftLinear), Lorach's
  // contrast curve (kSoftContrast) or that curve at power 2, a square (kSoftSquare); with
  // DENSITY_EXTENT, the method's range scaled by the texture alpha; with FB_DEPTH, the depth
  // read from the framebuffer (gl_features.h, has_depth_fetch; id 0 where the context cannot)
  // instead of from a copy.
  enum SoftCurve { kSoftLinear = 0, kSoftContrast = 1, kSoftSquare = 2 };
  Program particle_hard;
  Program particle_soft[3][2][2];
  // The same programs with particle.vert's INDEXED variant: each quad's particle is pulled
  // through the order buffer texture of an indexed batch (particle_batch.h, per cluster). Built
  // by build_indexed() (throws as the constructor does), only where the per-cluster preparation
  // is used, so a software rasteriser's start compiles none of them; id 0 until then.
  Program particle_hard_indexed;
  Program particle_soft_indexed[3][2][2];
  void build_indexed();
  bool has_indexed() const;
  // Post passes over post.vert's full-screen triangle: the bloom chain's first step (threshold),
  // its first 13-tap step (Karis average), its other steps down and up, the tone map without
  // and with bloom, FXAA.
  Program bloom_prefilter, bloom_down_karis, bloom_down, bloom_up, tonemap, tonemap_bloom, fxaa;
  Program msaa_resolve;  // the HDR scene's multisampled colour, averaged as if tone-mapped
  Program particle_composite;  // half-resolution particles over the scene (particle_target.h)

 private:
  struct Spec {
    Program* p;
    const char* vs;
    const char* fs;
    std::string defines;        // into the fragment shader
    std::string vdefines = "";  // into the vertex shader
  };
  void build_all();  // throws with the compiler's text; leaves the old programs on failure
  void add_particle_specs(std::vector<Spec>& specs, bool indexed);
  void build_specs(const std::vector<Spec>& specs);
  std::string dir_;
  int generation_ = 0;
  bool indexed_ = false;  // the INDEXED particle programs are built
};

}  // namespace arc
