// gfx/bloom_pass.h — the glow of bright light: a downsample/upsample chain over the HDR scene.
//
// After Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare" (SIGGRAPH
// 2014): the first level is half the scene's size and takes only light above a soft-knee
// threshold (with Karis' average against flicker); each further level halves again through the
// 13-tap downsample, six levels in all; then from the smallest up each level is 3×3-tent
// filtered and added onto the next larger one. The largest level then holds the sum of all
// levels, which the tone-map pass adds to the scene (post_pass.h). Everything runs at half
// resolution or less in float (R11F_G11F_B10F): about 0.4 of one full-screen layer in pixels.
//
//   BloomPass bloom;
//   GLuint glow = bloom.run(targets.scene_color(), scene_w, scene_h, programs);
//   // glow: level 0, (scene_w / 2) × (scene_h / 2), holds kLevels levels' sum
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
  // of its largest level. Leaves blending off and no framebuffer bound in particular.
  GLuint run(GLuint scene, int scene_w, int scene_h, const ShaderPrograms& programs);
  int levels() const { return int(levels_.size()); }

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
