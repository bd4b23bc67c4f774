// gfx/texture_filter.h — render.texture_filter applied to a bound, mipmapped texture.
//
// The mesh pass (model textures) and the particle pass (the sprite array) both follow the
// setting, and apply it again when it changes.
#pragma once
#include <epoxy/gl.h>

#include "gfx/render_settings.h"

namespace arc {

inline void apply_texture_filter(GLenum target, RenderSettings::Filter filter) {
  GLint min_filter = GL_LINEAR_MIPMAP_LINEAR;
  if (filter == RenderSettings::Filter::Nearest) min_filter = GL_NEAREST;
  if (filter == RenderSettings::Filter::Linear) min_filter = GL_LINEAR;
  if (filter == RenderSettings::Filter::MipmapNearest) min_filter = GL_LINEAR_MIPMAP_NEAREST;
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, min_filter);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter == RenderSettings::Filter::Nearest ? GL_NEAREST : GL_LINEAR);
}

// A render target's texture: one filter both ways (GL_LINEAR to be filtered when read back
// scaled, GL_NEAREST for depth) and clamped to its edges.
inline void set_target_sampling(GLenum target, GLint filter) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace arc
