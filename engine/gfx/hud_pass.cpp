// gfx/hud_pass.cpp — font atlas texture, HUD vertex buffer and the overlay draw.
#include "gfx/hud_pass.h"
#include "gfx/texture_filter.h"

#include <cstddef>

namespace arc {

HudPass::HudPass() {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(HudVertex), reinterpret_cast<void*>(offsetof(HudVertex, x)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(HudVertex), reinterpret_cast<void*>(offsetof(HudVertex, u)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, sizeof(HudVertex), reinterpret_cast<void*>(offsetof(HudVertex, r)));
  glBindVertexArray(0);

  glGenTextures(1, &font_tex_);
  glBindTexture(GL_TEXTURE_2D, font_tex_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, font_.width(), font_.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE, font_.pixels());
  set_target_sampling(GL_TEXTURE_2D, GL_NEAREST);
}

HudPass::~HudPass() {
  glDeleteVertexArrays(1, &vao_);
  glDeleteBuffers(1, &vbo_);
  glDeleteTextures(1, &font_tex_);
}

int HudPass::draw(const HudLayer& hud, const Program& program, int w, int h) {
  vertices_.clear();
  font_.build(hud, vertices_);
  if (vertices_.empty()) return 0;
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glUseProgram(program.id);
  glUniform2f(program.loc("u_viewport"), float(w), float(h));
  glUniform1i(program.loc("u_font"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, font_tex_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices_.size() * sizeof(HudVertex)), vertices_.data(), GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices_.size()));
  glDisable(GL_BLEND);
  return 1;
}

}  // namespace arc
