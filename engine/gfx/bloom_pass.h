// gfx/bloom_pass.h — the glow of bright light: a downsample/upsample chain over the HDR scene.
//
// After Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare" (SIGGRAPH
// 2014), cut down for a software rasteriser: the first level is half the scene's size, one
// bilinear tap per pixel (the mean of 2×2 scene pixels) through a soft-knee threshold; each
// further level halves again through the 13-tap downsample (the first of them with Karis'
// average against flicker), six levels in all; then from the smallest up each level is 3×3-tent
// filtered and added onto the next larger one, up to the second level (a quarter of the scene's
// size), which the tone-map pass samples once per pixel (post_pass.h). The half-size level is
// only a step down: tent-filtering back up into it would cost more than all the other levels
// together. Targets are RGBA16F (llvmpipe reads and writes it faster than R11F_G11F_B10F).
//
// Example, compiled as GlExamples.BloomPass in tests/unit/gfx/test_gl_examples.cpp:
//   BloomPass bloom;
//   GLuint glow = bloom.run(targets.scene_color(), scene_w, scene_h, programs);
//   // glow: (scene_w / 4) × (scene_h / 4), the sum of levels 1 to 5
#pragma once
#include <epoxy/gl.h>

#include <vector>

#include "gfx/shader_programs.h"

namespace arc {

class BloomPass {
 public:
  static constexpr int kLevels = 6;
  static constexpr float kThreshold = 1.0f;  // linear scene value where the glow starts
  static constexpr float kKnee = 0.5f;       // half-width of the soft knee around it

  BloomPass();
  ~BloomPass();
  BloomPass(const BloomPass&) = delete;
  BloomPass& operator=(const BloomPass&) = delete;

  // Runs the chain over `scene` (a float texture of scene_w × scene_h) and returns the texture
  // holding the sum (the quarter-size level). Leaves blending off, no framebuffer bound in
  // particular.
  GLuint run(GLuint scene, int scene_w, int scene_h, const ShaderPrograms& programs);
  int summed_levels() const { return kLevels - 1; }  // levels the returned texture adds up

 private:
  struct Level {
    GLuint tex = 0, fbo = 0;
    int w = 0, h = 0;
  };
  void allocate(int scene_w, int scene_h);
  void draw(const Program& p, GLuint source, int source_w, int source_h, const Level& dst) const;
  std::vector<Level> levels_;
  int scene_w_ = 0, scene_h_ = 0;
  GLuint vao_ = 0;
};

}  // namespace arc
