// gfx/render_targets.h — the framebuffers a frame draws into, and reading them back.
//
// The scene buffer (colour + 32-bit float depth) is the window size × render scale; every pass up
// to the particles draws into it. Its colour is RGBA8 (display values) or, with HDR, a float
// format in linear light (SceneFormat). With MSAA the opaque passes draw into a multisampled twin
// instead, and resolve_opaque() blits its colour and depth down into the scene buffer, so the
// particles and the depth copy see single-sample buffers. The depth copy is a depth texture the
// particle pass samples for soft edges, filled from THIS frame's depth by copy_depth(), where the
// driver does not let the soft particles read the scene's depth at their own pixel
// (gl_features.h, has_depth_fetch). resolve() scales the scene colour into the window (default
// framebuffer) or, offscreen, into an RGBA8 target of the window size that read_pixels() returns;
// with HDR or FXAA the post passes write there instead (bind_output()). The HUD then draws there
// at full size.
//
// Example, compiled as GlExamples.RenderTargets in tests/unit/gfx/test_gl_examples.cpp:
//   RenderTargets targets(/*offscreen=*/true, /*float_scene=*/false);
//   targets.ensure(1280, 720, 1.0, {});  // (re)allocates on a size or format change
//   targets.bind_opaque();               // ... opaque passes ...
//   targets.resolve_opaque(programs.msaa_resolve);  // no-op without MSAA
//   targets.copy_depth();                // ... particles sample depth_copy() ...
//   targets.resolve(1280, 720);          // ... HUD ...
//   Image frame = targets.read_pixels();
#pragma once
#include <epoxy/gl.h>

#include <vector>

#include "assets/model.h"
#include "gfx/particle_coverage.h"
#include "gfx/render_settings.h"
#include "gfx/shader_programs.h"

namespace arc {

// How the scene buffer is stored: 8-bit display values or a float format in linear light
// (hdr_format), and how many samples the opaque passes take (0 or 1: no MSAA).
struct SceneFormat {
  bool hdr = false;
  HdrFormat hdr_format = HdrFormat::Rgba16f;
  int samples = 0;
  // The scene stored top row first, as a window system stores the window (gfx/renderer.h):
  // the passes draw it with clip control's upper-left origin and the resolve flips it back.
  // With the 8-bit scene's BGRA order (the X window's own), the resolve into the window is
  // then a copy of rows instead of a draw.
  bool top_down = false;
  bool operator==(const SceneFormat& o) const {
    return hdr == o.hdr && hdr_format == o.hdr_format && samples == o.samples && top_down == o.top_down;
  }
};

// RGBA8 storage in BGRA order for the bound 2-D texture (render_targets.cpp says why).
void allocate_rgba8(int w, int h);

// Rectangles of scene pixels counted from the bottom row (GL's window coordinates) as rows of
// a scene stored top row first: y → height − y.
void flip_rows(std::vector<PixelRect>& rects, int height);

class RenderTargets {
 public:
  // offscreen: resolve into an RGBA8 target for read_pixels(); float_scene: an RGBA16F scene
  // buffer, so NaN and infinity survive to read_pixels_float().
  RenderTargets(bool offscreen, bool float_scene);
  ~RenderTargets();
  RenderTargets(const RenderTargets&) = delete;
  RenderTargets& operator=(const RenderTargets&) = delete;

  // Sizes the scene buffer and depth copy to round(w·scale) × round(h·scale) (at least 1) and
  // the offscreen target to w × h; throws std::runtime_error when a framebuffer is incomplete.
  void ensure(int w, int h, double scale, const SceneFormat& format);
  int scene_width() const { return scene_w_; }
  int scene_height() const { return scene_h_; }
  bool has_scene() const { return scene_fbo_ != 0; }
  GLuint scene_color() const { return scene_color_; }  // for the post passes
  GLuint scene_fbo() const { return scene_fbo_; }
  // The scene colour alone, no depth attached: what the half-resolution composite blends into
  // (llvmpipe takes its faster linear rasteriser only into a framebuffer without depth).
  GLuint scene_color_fbo() const { return scene_color_fbo_; }
  GLenum scene_internal_format() const { return scene_internal_; }
  bool scene_bgra() const { return scene_bgra_; }  // 8-bit colour in BGRA order (allocate_rgba8)
  int samples() const { return samples_; }  // of the opaque target as allocated (0: no MSAA)
  bool top_down() const { return format_.top_down; }  // the scene's rows are stored top first

  // Binds the scene framebuffer with a viewport over all of it.
  void bind_scene() const;
  // Binds what the opaque passes draw into: the multisampled target with MSAA, else the scene.
  void bind_opaque() const;
  // With MSAA: averages the opaque target's colour into the scene colour and copies one
  // sample's depth into the scene depth, then binds the scene. Without: nothing. An HDR scene
  // is averaged by `hdr_resolve` (shaders/msaa_resolve.frag, as if tone-mapped), an 8-bit one
  // by a blit.
  void resolve_opaque(const Program& hdr_resolve) const;
  // Copies the scene's depth into the depth copy, then binds the scene framebuffer again: all
  // of it, or only `rects` (scene pixels; what the soft particles can read).
  void copy_depth() const;
  void copy_depth(const std::vector<PixelRect>& rects) const;
  GLuint depth_copy() const { return copy_depth_; }
  // The scene's own depth texture: particles drawn into another target (half resolution)
  // sample it directly, with no copy, since it is not attached where they draw.
  GLuint scene_depth() const { return scene_depth_; }
  // Scales the scene colour into the window or the offscreen target (linear filtering unless
  // the sizes match) and leaves that bound with a width × height viewport. A top-down scene
  // (SceneFormat::top_down) is read with its rows reversed, which puts it upright: into a
  // window, whose rows the driver also keeps top first, the two reversals cancel and Mesa
  // copies the rows, far cheaper on llvmpipe than the converting draw a bottom-up RGBA scene
  // takes.
  void resolve(int width, int height) const;
  // Binds the window or the offscreen target with a width × height viewport.
  void bind_output(int width, int height) const;

  Image read_pixels() const;                    // offscreen only; RGBA8, rows top to bottom
  std::vector<float> read_pixels_float() const; // the scene buffer as RGBA floats, rows top to bottom

 private:
  void allocate_scene(int sw, int sh);
  void allocate_multisampled(int sw, int sh);
  void allocate_target(int w, int h);
  bool offscreen_, float_scene_;
  SceneFormat format_;
  GLenum scene_internal_ = GL_RGBA8;
  GLuint scene_fbo_ = 0, scene_color_fbo_ = 0, scene_color_ = 0, scene_depth_ = 0;
  bool scene_bgra_ = false, target_bgra_ = false;  // 8-bit colour stored in BGRA order (allocate_rgba8)
  GLuint ms_fbo_ = 0, ms_color_ = 0, ms_depth_ = 0;  // ms_color_: a multisample texture
  GLuint resolve_vao_ = 0;
  int samples_ = 0;
  GLuint copy_fbo_ = 0, copy_depth_ = 0;
  GLuint target_fbo_ = 0, target_color_ = 0;
  int scene_w_ = 0, scene_h_ = 0, target_w_ = 0, target_h_ = 0;
};

}  // namespace arc
