// gfx/render_targets.cpp — scene buffer, depth copy, offscreen target and read-back.
#include "gfx/render_targets.h"
#include "gfx/gl_features.h"
#include "gfx/texture_filter.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace arc {

void flip_rows(std::vector<PixelRect>& rects, int height) {
  for (PixelRect& r : rects) {
    const int y0 = height - r.y1, y1 = height - r.y0;
    r.y0 = y0;
    r.y1 = y1;
  }
}

RenderTargets::RenderTargets(bool offscreen, bool float_scene) : offscreen_(offscreen), float_scene_(float_scene) {}

RenderTargets::~RenderTargets() {
  GLuint tex[] = {scene_color_, scene_depth_, copy_depth_, target_color_, ms_color_};
  glDeleteTextures(5, tex);
  glDeleteRenderbuffers(1, &ms_depth_);
  glDeleteVertexArrays(1, &resolve_vao_);
  GLuint fbos[] = {scene_fbo_, scene_color_fbo_, copy_fbo_, target_fbo_, ms_fbo_};
  glDeleteFramebuffers(5, fbos);
}

void RenderTargets::ensure(int w, int h, double scale, const SceneFormat& format) {
  int sw = std::max(1, int(std::lround(w * scale)));
  int sh = std::max(1, int(std::lround(h * scale)));
  if (sw != scene_w_ || sh != scene_h_ || !scene_fbo_ || !(format == format_)) {
    format_ = format;
    allocate_scene(sw, sh);
    allocate_multisampled(sw, sh);
  }
  if (offscreen_ && (w != target_w_ || h != target_h_ || !target_fbo_ || target_bgra_ != scene_bgra_)) allocate_target(w, h);
}

void RenderTargets::allocate_scene(int sw, int sh) {
  scene_w_ = sw;
  scene_h_ = sh;
  if (!scene_fbo_) {
    glGenFramebuffers(1, &scene_fbo_);
    glGenFramebuffers(1, &scene_color_fbo_);
    glGenFramebuffers(1, &copy_fbo_);
    glGenTextures(1, &scene_color_);
    glGenTextures(1, &scene_depth_);
    glGenTextures(1, &copy_depth_);
  }
  // Float scenes of tests keep RGBA16F (NaN and infinity survive, alpha is kept); HDR takes the
  // format RendererDesc::hdr_format names (post_pass.h says which is cheaper; the blend reads no
  // destination alpha, so three channels do).
  scene_internal_ = float_scene_ ? GL_RGBA16F
                    : !format_.hdr ? GL_RGBA8
                    : format_.hdr_format == HdrFormat::Rgba16f ? GL_RGBA16F
                                                               : GL_R11F_G11F_B10F;
  const bool is_float = scene_internal_ != GL_RGBA8;
  // An 8-bit scene is stored in BGRA order (allocate_rgba8), except under MSAA, whose resolving
  // blit wants the multisampled colour's format.
  scene_bgra_ = !is_float && format_.samples <= 1;
  glBindTexture(GL_TEXTURE_2D, scene_color_);
  if (scene_bgra_)
    allocate_rgba8(sw, sh);
  else
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(scene_internal_), sw, sh, 0, is_float ? GL_RGB : GL_RGBA,
                 is_float ? GL_FLOAT : GL_UNSIGNED_BYTE, nullptr);
  set_target_sampling(GL_TEXTURE_2D, GL_LINEAR);
  // Float depth in both modes: reversed-Z needs it, and the copy must match the format. A
  // texture, so that particles drawn into another target (half resolution) sample it as it is.
  glBindTexture(GL_TEXTURE_2D, scene_depth_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, sw, sh, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  set_target_sampling(GL_TEXTURE_2D, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, scene_fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, scene_color_, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, scene_depth_, 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("scene framebuffer incomplete");
  glBindFramebuffer(GL_FRAMEBUFFER, scene_color_fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, scene_color_, 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("scene colour framebuffer incomplete");
  glBindTexture(GL_TEXTURE_2D, copy_depth_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, sw, sh, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  set_target_sampling(GL_TEXTURE_2D, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, copy_fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, copy_depth_, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("depth copy framebuffer incomplete");
}

// The opaque passes' multisampled twin of the scene buffer: same colour format (a resolving
// blit needs it), float depth. Drivers may give more samples than asked; samples() says.
void RenderTargets::allocate_multisampled(int sw, int sh) {
  samples_ = 0;
  if (format_.samples <= 1) return;
  if (!ms_fbo_) {
    glGenFramebuffers(1, &ms_fbo_);
    glGenTextures(1, &ms_color_);
    glGenRenderbuffers(1, &ms_depth_);
    glGenVertexArrays(1, &resolve_vao_);
  }
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  const int samples = std::min(format_.samples, int(max_samples));
  glBindRenderbuffer(GL_RENDERBUFFER, ms_depth_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT32F, sw, sh);
  GLint got = 0;
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &got);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, ms_color_);
  glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, got, scene_internal_, sw, sh, GL_TRUE);
  glBindFramebuffer(GL_FRAMEBUFFER, ms_fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE, ms_color_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ms_depth_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("multisampled scene framebuffer incomplete");
  samples_ = got;
}

void RenderTargets::allocate_target(int w, int h) {
  target_w_ = w;
  target_h_ = h;
  if (!target_fbo_) {
    glGenFramebuffers(1, &target_fbo_);
    glGenTextures(1, &target_color_);
  }
  glBindTexture(GL_TEXTURE_2D, target_color_);
  // The scene's channel order, so that the resolve into it is a copy of rows.
  target_bgra_ = scene_bgra_;
  if (target_bgra_) allocate_rgba8(w, h);
  else glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindFramebuffer(GL_FRAMEBUFFER, target_fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target_color_, 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("offscreen target framebuffer incomplete");
}

// RGBA8 storage in BGRA order for the bound 2-D texture. The unsized internal format lets Mesa
// take the order of the (BGRA) data as its storage, as an X window stores its pixels. On
// llvmpipe that order is what its fast linear rasteriser takes (a composite into a colour-only
// BGRA framebuffer runs about twice as fast as into RGBA8; docs/performance.md), and a copy
// into the window is a copy of rows.
void allocate_rgba8(int w, int h) {
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_BGRA, GL_UNSIGNED_BYTE, nullptr);
}

void RenderTargets::bind_scene() const {
  glBindFramebuffer(GL_FRAMEBUFFER, scene_fbo_);
  glViewport(0, 0, scene_w_, scene_h_);
}

void RenderTargets::bind_opaque() const {
  glBindFramebuffer(GL_FRAMEBUFFER, samples_ > 1 ? ms_fbo_ : scene_fbo_);
  glViewport(0, 0, scene_w_, scene_h_);
}

void RenderTargets::resolve_opaque(const Program& hdr_resolve) const {
  if (samples_ <= 1) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, ms_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, scene_fbo_);
  // Depth takes one sample's value (depth is never averaged): what the particles test against
  // and the soft-edge copy reads.
  const bool blit_colour = !format_.hdr;
  glBlitFramebuffer(0, 0, scene_w_, scene_h_, 0, 0, scene_w_, scene_h_,
                    GL_DEPTH_BUFFER_BIT | (blit_colour ? GL_COLOR_BUFFER_BIT : 0), GL_NEAREST);
  bind_scene();
  if (blit_colour) return;
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_BLEND);
  glUseProgram(hdr_resolve.id);
  glUniform1i(hdr_resolve.loc("u_scene_ms"), 0);
  glUniform1i(hdr_resolve.loc("u_samples"), samples_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, ms_color_);
  glBindVertexArray(resolve_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthMask(GL_TRUE);
}

void RenderTargets::copy_depth() const { copy_depth({PixelRect{0, 0, scene_w_, scene_h_}}); }

void RenderTargets::copy_depth(const std::vector<PixelRect>& rects) const {
  // This frame's depth, never last frame's (Ribeiro: a stale copy flickers as the camera moves).
  // Same format and size on both sides, so where image copy exists (gl_features.h) it is a
  // plain copy of texels (a memcpy on llvmpipe); a depth blit runs a draw through the blitter.
  const bool image_copy = has_copy_image();
  if (!image_copy) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, scene_fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, copy_fbo_);
  }
  for (const PixelRect& r : rects) {
    const int x0 = std::clamp(r.x0, 0, scene_w_), x1 = std::clamp(r.x1, 0, scene_w_);
    const int y0 = std::clamp(r.y0, 0, scene_h_), y1 = std::clamp(r.y1, 0, scene_h_);
    if (x1 <= x0 || y1 <= y0) continue;
    if (image_copy)
      glCopyImageSubData(scene_depth_, GL_TEXTURE_2D, 0, x0, y0, 0, copy_depth_, GL_TEXTURE_2D, 0, x0, y0, 0, x1 - x0,
                         y1 - y0, 1);
    else
      glBlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, scene_fbo_);
}

void RenderTargets::resolve(int width, int height) const {
  GLuint dst = offscreen_ ? target_fbo_ : 0;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, scene_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, dst);
  const int y0 = format_.top_down ? scene_h_ : 0, y1 = format_.top_down ? 0 : scene_h_;
  glBlitFramebuffer(0, y0, scene_w_, y1, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                    (scene_w_ == width && scene_h_ == height) ? GL_NEAREST : GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, dst);
  glViewport(0, 0, width, height);
}

void RenderTargets::bind_output(int width, int height) const {
  glBindFramebuffer(GL_FRAMEBUFFER, offscreen_ ? target_fbo_ : 0);
  glViewport(0, 0, width, height);
}

Image RenderTargets::read_pixels() const {
  if (!offscreen_ || !target_fbo_) throw std::logic_error("read_pixels needs an offscreen renderer that has rendered");
  Image img;
  img.width = target_w_;
  img.height = target_h_;
  img.rgba.resize(size_t(img.width) * img.height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target_fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  flip_rows(img);
  return img;
}

std::vector<float> RenderTargets::read_pixels_float() const {
  if (!scene_fbo_) throw std::logic_error("read_pixels_float before any render");
  std::vector<float> px(size_t(scene_w_) * scene_h_ * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, scene_fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, scene_w_, scene_h_, GL_RGBA, GL_FLOAT, px.data());
  if (format_.top_down) return px;  // already top row first
  std::vector<float> out(px.size());
  size_t row = size_t(scene_w_) * 4;
  for (int y = 0; y < scene_h_; ++y)
    std::memcpy(&out[size_t(y) * row], &px[size_t(scene_h_ - 1 - y) * row], row * 4);
  return out;
}

}  // namespace arc
