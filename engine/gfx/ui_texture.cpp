// A panel thumbnail texture (see the header).
#include "gfx/ui_texture.h"

#include <epoxy/gl.h>

namespace arc {

UiTexture::UiTexture(const Image& rgba8) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, rgba8.width, rgba8.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba8.rgba.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  name_ = t;
}

UiTexture::~UiTexture() {
  const GLuint t = name_;
  glDeleteTextures(1, &t);
}

}  // namespace arc
