// gfx/post_pass.h — from the scene buffer to the output: tone mapping and edge anti-aliasing.
//
// The last scene pass before the HUD, replacing the plain resolve where it has work to do:
//   hdr off, no FXAA   the scene colour is blitted to the output as before (RenderTargets::resolve)
//   hdr on             scene (+ bloom) × exposure through the ACES fit, encoded sRGB
//                      (shaders/tonemap.frag), into the output, or with FXAA into an RGBA8 image
//                      of the scene's size that the FXAA pass then filters into the output
//   hdr off, FXAA      the 8-bit scene colour filtered by FXAA into the output
// The HUD draws afterwards onto the output, so the filter never touches it.
//
// Measured on this project's 2-core llvmpipe (`arcfire-bench --scene render_look`, 1280×720,
// medians of same-round ratios, machine shared): the HDR scene in R11F_G11F_B10F costs 1.07–1.08
// of the same frame in RGBA16F (llvmpipe packs and unpacks the shared-exponent-free 11/10-bit
// floats in software), so RendererDesc::hdr_format defaults to RGBA16F. HDR with bloom costs
// 1.8 (gallery) to 2.1 (battle) of the 8-bit frame; FXAA 1.5–1.6 of the HDR frame (nine
// filtered taps a pixel; a one-tap copy pass alone is 1.1); MSAA 1.6–2.3 (llvmpipe gives 4
// samples for msaa2 as well).
//
// Example, compiled as GlExamples.PostPass in tests/unit/gfx/test_gl_examples.cpp:
//   PostPass post;
//   post.run({targets.scene_color(), scene_w, scene_h, bloom_tex, 0.1f, 1.0f, true, true}, programs, targets,
//            1280, 720);
#pragma once
#include <epoxy/gl.h>

#include "gfx/render_targets.h"
#include "gfx/shader_programs.h"

namespace arc {

struct PostInput {
  GLuint scene = 0;
  int scene_w = 1, scene_h = 1;
  GLuint bloom = 0;             // the bloom chain's sum, or 0 for none
  float bloom_strength = 0.0f;  // what one unit of the chain's sum adds to the scene
  float exposure = 1.0f;
  bool hdr = false;
  bool fxaa = false;
};

class PostPass {
 public:
  PostPass();
  ~PostPass();
  PostPass(const PostPass&) = delete;
  PostPass& operator=(const PostPass&) = delete;

  // Leaves the output bound with a width × height viewport, blending and depth test off.
  void run(const PostInput& in, const ShaderPrograms& programs, const RenderTargets& targets, int width, int height);

 private:
  void ensure_tonemapped(int w, int h);
  void tonemap(const PostInput& in, const ShaderPrograms& programs, bool same_size) const;
  void fxaa(GLuint image, int w, int h, const ShaderPrograms& programs) const;
  GLuint vao_ = 0;
  GLuint nearest_ = 0;                // sampler for reading the scene texel for texel
  GLuint ldr_fbo_ = 0, ldr_tex_ = 0;  // the tone-mapped image FXAA reads
  int ldr_w_ = 0, ldr_h_ = 0;
};

}  // namespace arc
