// gfx/post_pass.cpp — tone map, FXAA and the image between them.
#include "gfx/post_pass.h"
#include "gfx/texture_filter.h"

#include <stdexcept>

namespace arc {

PostPass::PostPass() {
  glGenVertexArrays(1, &vao_);
  glGenSamplers(1, &nearest_);
  glSamplerParameteri(nearest_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(nearest_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(nearest_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(nearest_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

PostPass::~PostPass() {
  glDeleteVertexArrays(1, &vao_);
  glDeleteSamplers(1, &nearest_);
  glDeleteTextures(1, &ldr_tex_);
  glDeleteFramebuffers(1, &ldr_fbo_);
}

void PostPass::ensure_tonemapped(int w, int h) {
  if (ldr_fbo_ && w == ldr_w_ && h == ldr_h_) return;
  if (!ldr_fbo_) {
    glGenFramebuffers(1, &ldr_fbo_);
    glGenTextures(1, &ldr_tex_);
  }
  glBindTexture(GL_TEXTURE_2D, ldr_tex_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  set_target_sampling(GL_TEXTURE_2D, GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, ldr_fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, ldr_tex_, 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("tone-mapped image framebuffer incomplete");
  ldr_w_ = w;
  ldr_h_ = h;
}

// Into the bound framebuffer, over its viewport. When that is the scene's size each pixel reads
// exactly one scene texel, so the scene is sampled nearest (one texel read instead of four on
// a software rasteriser); otherwise bilinearly, like the blit it replaces.
void PostPass::tonemap(const PostInput& in, const ShaderPrograms& programs, bool same_size) const {
  const Program& p = in.bloom ? programs.tonemap_bloom : programs.tonemap;
  glUseProgram(p.id);
  glUniform1i(p.loc("u_scene"), 0);
  glUniform1i(p.loc("u_bloom"), 1);
  glUniform1f(p.loc("u_exposure"), in.exposure);
  glUniform1f(p.loc("u_bloom_strength"), in.bloom_strength);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, in.bloom);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, in.scene);
  glBindSampler(0, same_size ? nearest_ : 0);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindSampler(0, 0);
}

void PostPass::fxaa(GLuint image, int w, int h, const ShaderPrograms& programs) const {
  glUseProgram(programs.fxaa.id);
  glUniform1i(programs.fxaa.loc("u_image"), 0);
  glUniform2f(programs.fxaa.loc("u_texel"), 1.0f / float(w), 1.0f / float(h));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, image);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void PostPass::run(const PostInput& in, const ShaderPrograms& programs, const RenderTargets& targets, int width,
                   int height) {
  if (!in.hdr && !in.fxaa) {
    targets.resolve(width, height);
    return;
  }
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindVertexArray(vao_);
  GLuint image = in.scene;
  if (in.hdr && in.fxaa) {
    ensure_tonemapped(in.scene_w, in.scene_h);
    glBindFramebuffer(GL_FRAMEBUFFER, ldr_fbo_);
    glViewport(0, 0, in.scene_w, in.scene_h);
    tonemap(in, programs, true);
    image = ldr_tex_;
  }
  targets.bind_output(width, height);
  if (in.fxaa)
    fxaa(image, in.scene_w, in.scene_h, programs);
  else
    tonemap(in, programs, in.scene_w == width && in.scene_h == height);
  glBindVertexArray(0);
}

}  // namespace arc
