// gfx/particle_pass.h — the particle draw: upload of a prepared batch and one instanced draw.
//
// Owns the sprite array texture, the buffer texture the vertex shader pulls ParticleInstance
// from (shaders/particle.vert builds each quad from four RGBA32UI texels), the order buffer
// texture of an indexed batch (one R32UI texel per quad: which particle it draws), and the index
// buffer (two triangles per particle). draw() blends with depth test on and depth write off,
// GL_ONE, GL_ONE_MINUS_SRC_ALPHA (controlled-additive "burn", Ilmonen 2006 §4, equations 3–10
// unchanged in linear light with HDR: only the colours entering them are decoded), one draw per
// run of the batch (particle_runs.h) with the cheapest program the run allows: hard edges when
// no particle of it is soft, the contrast curve only when one uses it. The CPU half (culling,
// flags, budget, sorting, runs) is particle_batch.h.
//
// Example, compiled as GlExamples.ParticlePass in tests/unit/gfx/test_gl_examples.cpp:
//   ParticlePass particles(0);
//   particles.set_sprites({load_sprite("assets/textures/sprite_smoke.png")}, settings.filter);
//   particles.upload(batch);  // its particles, or an indexed batch's source and order
//   if (batch.any_soft) targets.copy_depth();
//   particles.draw(batch, programs, settings, frame);  // one draw per run
#pragma once
#include <epoxy/gl.h>

#include <cstddef>
#include <vector>

#include "assets/model.h"
#include "gfx/particle_batch.h"
#include "gfx/render_settings.h"
#include "gfx/shader_programs.h"
#include "gfx/sprite_trim.h"
#include "gfx/view_projection.h"

namespace arc {

// What the particle draw reads from the frame besides the batch.
struct ParticleFrame {
  ViewProjection vp;
  double fov_y_radians = 1.0;
  float near_plane = 0.5f;
  GLuint depth_copy = 0;  // RenderTargets::depth_copy(), sampled by the soft programs
  int scene_width = 1, scene_height = 1;  // of the target drawn into (the depth copy is read in [0, 1])
  // Drawing into the half-resolution target (particle_target.h): alpha keeps the transmittance.
  bool transmittance_alpha = false;
  // The soft programs read the depth of the framebuffer drawn into instead of depth_copy
  // (gl_features.h, has_depth_fetch).
  bool depth_fetch = false;
};

class ParticlePass {
 public:
  // draw_limit: at most this many particles per draw when not 0 (tests reach the limit with
  // it); the context's GL_MAX_TEXTURE_BUFFER_SIZE / 4 otherwise.
  explicit ParticlePass(size_t draw_limit);
  ~ParticlePass();
  ParticlePass(const ParticlePass&) = delete;
  ParticlePass& operator=(const ParticlePass&) = delete;

  // Layers of one array texture, all stretched to the largest sprite's size. Starts with one
  // white layer, so particles draw as squares of their colour before any sprites are set.
  // Straight-alpha sprites (Image::premultiplied false, as stored on disk) are premultiplied
  // here: in sRGB bytes for the 8-bit scene, exactly as load_sprite() does, and in linear light
  // for HDR (color_space.h); premultiplied ones are taken as they are for the 8-bit scene.
  void set_sprites(const std::vector<Image>& sprites, RenderSettings::Filter filter);
  void set_texture_filter(RenderSettings::Filter filter);
  size_t max_particles_per_draw() const { return max_particles_per_draw_; }
  // The sprites' trim boxes (sprite_trim.h), for the batch's blended-area estimate.
  const SpriteTrim& trim() const { return trim_; }

  void upload(const std::vector<ParticleInstance>& particles);
  // The batch's particles, or for an indexed batch its source as it is and its order (an
  // R32UI buffer texture the vertex shader reads first).
  void upload(const ParticleBatch& batch);
  // Particles the buffer texture takes in one piece (GL_MAX_TEXTURE_BUFFER_SIZE / 4), whatever
  // the draw limit: the most an indexed batch's source may hold.
  size_t max_source_particles() const { return max_source_particles_; }
  // Draws what upload() received into the bound framebuffer, one draw per run of the batch,
  // and returns the number of draws. When counting fragments, an occlusion query spans the runs.
  int draw(const ParticleBatch& batch, const ShaderPrograms& programs, const RenderSettings& settings,
           const ParticleFrame& frame);
  void count_fragments(bool on) { count_fragments_ = on; }
  // The samples the last counted draw blended, read back when first asked for (after the frame
  // has been submitted, so the frame is not stalled halfway); −1 when none was counted since.
  long long take_fragments();
  void forget_fragments() { query_pending_ = false; }

 private:
  GLuint vao_ = 0, vbo_ = 0, ibo_ = 0, tbo_ = 0;
  size_t capacity_bytes_ = 0;   // in vbo_
  size_t index_capacity_ = 0;   // particles ibo_ has indices for
  size_t uploaded_ = 0;         // particles in vbo_
  size_t max_particles_per_draw_ = 0;
  size_t max_source_particles_ = 0;
  GLuint order_buf_ = 0, order_tbo_ = 0;  // an indexed batch's order (R32UI texels)
  size_t order_capacity_bytes_ = 0;
  static void stream(GLuint buffer, size_t& capacity, const void* data, size_t bytes);
  void ensure_indices(size_t quads);
  GLuint sprite_texture(bool linear);  // the array for this frame's colour space
  void upload_sprite_array(GLuint tex, GLenum internal_format, const std::vector<Image>& sprites) const;
  std::vector<Image> sprites_;        // as given, for the linear array made on first use
  RenderSettings::Filter filter_ = RenderSettings::Filter::Mipmap;
  GLuint sprite_tex_ = 0;             // RGBA8, premultiplied display values
  GLuint sprite_tex_linear_ = 0;      // SRGB8_ALPHA8, premultiplied in linear light; 0 until needed
  int sprite_w_ = 1, sprite_h_ = 1;
  SpriteTrim trim_;                   // each sprite's box at each mip level
  GLuint trim_tex_ = 0;               // the same boxes, RGBA32F texels (level, sprite)
  bool count_fragments_ = false;
  GLuint fragment_query_ = 0;
  bool query_pending_ = false;
};

}  // namespace arc
