// gfx/post_pass.h — from the scene buffer to the output: tone mapping and edge anti-aliasing.
//
// The last scene pass before the HUD, replacing the plain resolve where it has work to do:
//   hdr off, no FXAA   the scene colour is blitted to the output (RenderTargets::resolve)
//   hdr on             scene (+ bloom) × exposure through the ACES fit, encoded sRGB
//                      (shaders/tonemap.frag), into the output, or with FXAA into an RGBA8 image
//                      of the scene's size that the FXAA pass then filters into the output
//   hdr off, FXAA      the 8-bit scene colour filtered by FXAA into the output
// The HUD draws afterwards onto the output, so the filter never touches it.
//
// RendererDesc::hdr_format defaults to RGBA16F: llvmpipe packs and unpacks R11F_G11F_B10F's
// 11/10-bit floats in software, which makes the smaller format the slower one there. HDR with
// bloom, FXAA (nine filtered taps a pixel) and MSAA each cost a multiple of the plain frame on
// a software rasteriser: docs/performance.md has the ratios (`arcfire-bench --scene render_look`).
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
