// gfx/gl_features.h — what the current context offers beyond OpenGL 3.3, asked once.
//
// A process makes one kind of context (a window or EGL headless, the same driver), so each
// answer is taken the first time it is asked and kept.
#pragma once
#include <epoxy/gl.h>

namespace arc {

// glClipControl: reversed-Z depth and the upper-left origin of a top-down scene (renderer.h).
inline bool has_clip_control() {
  static const bool yes = epoxy_gl_version() >= 45 || epoxy_has_gl_extension("GL_ARB_clip_control");
  return yes;
}

// glCopyImageSubData: GL 4.3, or ARB_copy_image (NVIDIA's driver makes the 3.3 core context
// asked for and lists it).
inline bool has_copy_image() {
  static const bool yes = epoxy_gl_version() >= 43 || epoxy_has_gl_extension("GL_ARB_copy_image");
  return yes;
}

// gl_LastFragDepthARM: a fragment shader reads the depth stored at its own pixel of the
// framebuffer it draws into. Mesa's llvmpipe offers it on desktop GL; soft particles then read
// the opaque depth without a copy (renderer.h, RenderSettings::depth_fetch).
inline bool has_depth_fetch() {
  static const bool yes = epoxy_has_gl_extension("GL_ARM_shader_framebuffer_fetch_depth_stencil");
  return yes;
}

}  // namespace arc
