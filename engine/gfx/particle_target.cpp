// gfx/particle_target.cpp — the half-resolution particle target and its composite.
#include "gfx/particle_target.h"
#include "gfx/render_targets.h"
#include "gfx/texture_filter.h"

#include <algorithm>
#include <stdexcept>

namespace arc {

ParticleTarget::~ParticleTarget() {
  glDeleteTextures(1, &color_);
  glDeleteRenderbuffers(1, &depth_);
  glDeleteFramebuffers(1, &fbo_);
  glDeleteVertexArrays(1, &vao_);
  glDeleteBuffers(1, &vbo_);
}

void ParticleTarget::allocate(int w, int h, GLenum color_format) {
  if (!fbo_) {
    glGenFramebuffers(1, &fbo_);
    glGenTextures(1, &color_);
    glGenRenderbuffers(1, &depth_);
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vbo_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindVertexArray(0);
  }
  w_ = w;
  h_ = h;
  format_ = color_format;
  const bool is_float = color_format != GL_RGBA8;
  glBindTexture(GL_TEXTURE_2D, color_);
  // Alpha holds the transmittance: a format with an alpha channel even when the scene's has
  // none. 8-bit in BGRA order, as the scene: the composite then takes llvmpipe's linear path.
  if (is_float) glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
  else allocate_rgba8(w, h);
  set_target_sampling(GL_TEXTURE_2D, GL_LINEAR);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, w, h);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("half-resolution particle framebuffer incomplete");
}

void ParticleTarget::begin(GLuint scene_fbo, int scene_w, int scene_h, GLenum color_format) {
  const int w = std::max(1, scene_w / 2), h = std::max(1, scene_h / 2);
  if (w != w_ || h != h_ || color_format != format_ || !fbo_) allocate(w, h, color_format);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, scene_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
  glBlitFramebuffer(0, 0, scene_w, scene_h, 0, 0, w_, h_, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, w_, h_);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
}

void ParticleTarget::composite(const Program& program, GLuint scene_fbo, int scene_w, int scene_h,
                               const std::vector<PixelRect>& rects) {
  // Two triangles a rectangle; edges on whole pixels, so neighbours neither overlap nor gap.
  vertices_.clear();
  const float sx = 2.0f / float(scene_w), sy = 2.0f / float(scene_h);
  for (const PixelRect& r : rects) {
    const float x0 = float(r.x0) * sx - 1.0f, x1 = float(r.x1) * sx - 1.0f;
    const float y0 = float(r.y0) * sy - 1.0f, y1 = float(r.y1) * sy - 1.0f;
    vertices_.insert(vertices_.end(), {x0, y0, x1, y0, x0, y1, x0, y1, x1, y0, x1, y1});
  }
  glBindFramebuffer(GL_FRAMEBUFFER, scene_fbo);
  glViewport(0, 0, scene_w, scene_h);
  if (vertices_.empty()) return;
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFuncSeparate(GL_ONE, GL_SRC_ALPHA, GL_ZERO, GL_ONE);  // the scene's alpha stays
  glUseProgram(program.id);
  glUniform1i(program.loc("u_particles"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, color_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices_.size() * sizeof(float)), vertices_.data(), GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices_.size() / 2));
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
}

}  // namespace arc
