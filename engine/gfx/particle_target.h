// gfx/particle_target.h — particles drawn at half resolution, then put over the scene.
//
// render.particle_resolution = half: the particle pass draws into a target of half the scene's
// width and height (a quarter of the pixels to blend, which is most of a busy frame's cost on
// a software rasteriser), then one full-screen pass puts it over the scene. The target starts
// at (0, 0, 0, 1); the particles blend their colour as always (Ilmonen 2006 eq. 3: GL_ONE,
// GL_ONE_MINUS_SRC_ALPHA) and their alpha as GL_ZERO, GL_ONE_MINUS_SRC_ALPHA, so the target
// ends holding the summed light S and the remaining transmittance T = Π(1 − αᵢ). Putting it over
// with GL_ONE, GL_SRC_ALPHA gives S + T·scene: exactly the chained blend of every particle over
// the scene, evaluated at half resolution and filtered up bilinearly. The depth test uses the
// scene's depth taken down to half size (one sample per 2×2), soft edges read the full depth
// copy, so particles can bleed by a pixel over a mesh's outline. The composite covers only the
// rectangles it is given (ParticleCoverage: the tiles a particle can touch); elsewhere the
// target holds its clear value and would change nothing.
//
// Example, compiled as GlExamples.ParticleTarget in tests/unit/gfx/test_gl_examples.cpp:
//   ParticleTarget half;
//   half.begin(targets.scene_fbo(), scene_w, scene_h, targets.scene_internal_format());
//   particles.draw(batch, programs, settings, frame);  // frame.transmittance_alpha = true
//   half.composite(programs.particle_composite, targets.scene_color_fbo(), scene_w, scene_h, rects);
#pragma once
#include <epoxy/gl.h>

#include <vector>

#include "gfx/particle_coverage.h"
#include "gfx/shader_programs.h"

namespace arc {

class ParticleTarget {
 public:
  ParticleTarget() = default;
  ~ParticleTarget();
  ParticleTarget(const ParticleTarget&) = delete;
  ParticleTarget& operator=(const ParticleTarget&) = delete;

  // Sizes the target to half the scene (at least 1×1) in the scene's colour format, takes the
  // scene's depth down into it, clears its colour to (0, 0, 0, 1) and leaves it bound.
  void begin(GLuint scene_fbo, int scene_w, int scene_h, GLenum color_format);
  int width() const { return w_; }
  int height() const { return h_; }
  // Puts the target over the scene (S + T·scene) inside `rects` (scene pixels) and leaves
  // `scene_fbo` bound: the scene colour's framebuffer, best without depth attached
  // (RenderTargets::scene_color_fbo: llvmpipe's linear rasteriser then takes the composite).
  void composite(const Program& program, GLuint scene_fbo, int scene_w, int scene_h, const std::vector<PixelRect>& rects);

 private:
  void allocate(int w, int h, GLenum color_format);
  GLuint fbo_ = 0, color_ = 0, depth_ = 0, vao_ = 0, vbo_ = 0;
  std::vector<float> vertices_;  // the rectangles' triangles, NDC, rebuilt each frame
  int w_ = 0, h_ = 0;
  GLenum format_ = 0;
};

}  // namespace arc
