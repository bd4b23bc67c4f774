// gfx/bloom_pass.cpp — the bloom chain's textures and its down and up steps.
#include "gfx/bloom_pass.h"
#include "gfx/texture_filter.h"

#include <algorithm>
#include <stdexcept>

namespace arc {

BloomPass::BloomPass() { glGenVertexArrays(1, &vao_); }

BloomPass::~BloomPass() {
  for (Level& l : levels_) {
    glDeleteTextures(1, &l.tex);
    glDeleteFramebuffers(1, &l.fbo);
  }
  glDeleteVertexArrays(1, &vao_);
}

void BloomPass::allocate(int scene_w, int scene_h) {
  scene_w_ = scene_w;
  scene_h_ = scene_h;
  int w = scene_w, h = scene_h;
  levels_.resize(kLevels);
  for (Level& l : levels_) {
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
    l.w = w;
    l.h = h;
    if (!l.tex) {
      glGenTextures(1, &l.tex);
      glGenFramebuffers(1, &l.fbo);
    }
    glBindTexture(GL_TEXTURE_2D, l.tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
    set_target_sampling(GL_TEXTURE_2D, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, l.fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, l.tex, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("bloom framebuffer incomplete");
  }
}

void BloomPass::draw(const Program& p, GLuint source, int source_w, int source_h, const Level& dst) const {
  glBindFramebuffer(GL_FRAMEBUFFER, dst.fbo);
  glViewport(0, 0, dst.w, dst.h);
  glUseProgram(p.id);
  glUniform1i(p.loc("u_source"), 0);
  glUniform2f(p.loc("u_texel"), 1.0f / float(source_w), 1.0f / float(source_h));
  glUniform1f(p.loc("u_threshold"), kThreshold);
  glUniform1f(p.loc("u_knee"), kKnee);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, source);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

GLuint BloomPass::run(GLuint scene, int scene_w, int scene_h, const ShaderPrograms& programs) {
  if (scene_w != scene_w_ || scene_h != scene_h_ || levels_.empty()) allocate(scene_w, scene_h);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_BLEND);
  glBindVertexArray(vao_);
  draw(programs.bloom_prefilter, scene, scene_w, scene_h, levels_[0]);
  for (size_t i = 1; i < levels_.size(); ++i)
    draw(i == 1 ? programs.bloom_down_karis : programs.bloom_down, levels_[i - 1].tex, levels_[i - 1].w,
         levels_[i - 1].h, levels_[i]);
  // Up the chain: each level's tent-filtered image is added onto the next larger level, down
  // to level 1.
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  for (size_t i = levels_.size() - 1; i > 1; --i)
    draw(programs.bloom_up, levels_[i].tex, levels_[i].w, levels_[i].h, levels_[i - 1]);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  return levels_[1].tex;
}

}  // namespace arc
