// gfx/particle_pass.cpp — sprite array, particle buffer texture, index buffer and the draw.
#include "gfx/particle_pass.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

#include "gfx/color_space.h"
#include "gfx/sprite_trim.h"
#include "gfx/texture_filter.h"

namespace arc {
namespace {

// Contrast power 2 (the default) squares instead of calling pow(); power 1 is the identity
// curve, the linear program. The density-extent variant only for runs that hold that method;
// the INDEXED vertex shader only for an indexed batch.
const Program& choose_program(const ShaderPrograms& programs, const ParticleRun& run, float contrast_power, bool fetch,
                              bool indexed) {
  if (!run.soft) return indexed ? programs.particle_hard_indexed : programs.particle_hard;
  const int curve = !run.contrast || contrast_power == 1.0f ? ShaderPrograms::kSoftLinear
                    : contrast_power == 2.0f               ? ShaderPrograms::kSoftSquare
                                                           : ShaderPrograms::kSoftContrast;
  const auto& soft = indexed ? programs.particle_soft_indexed : programs.particle_soft;
  return soft[curve][run.density_extent ? 1 : 0][fetch ? 1 : 0];
}

// The frame's uniforms of one particle program (each program the runs use, once a frame).
void set_uniforms(const Program& particle, const RenderSettings& rs, const ParticleFrame& frame, const SpriteTrim& trim,
                  const ParticleBatch& batch) {
  if (batch.indexed()) {
    glUniform1i(particle.loc("u_soft_override"), batch.soft_override);
    glUniform1i(particle.loc("u_order"), 4);
  }
  glUniformMatrix4fv(particle.loc("u_view"), 1, GL_FALSE, glm::value_ptr(frame.vp.view));
  glUniformMatrix4fv(particle.loc("u_proj"), 1, GL_FALSE, glm::value_ptr(frame.vp.proj));
  glUniform1f(particle.loc("u_tan_half_y"), float(std::tan(frame.fov_y_radians * 0.5)));
  glUniform1f(particle.loc("u_size_clamp"), rs.size_clamp);
  glUniform1f(particle.loc("u_near"), frame.near_plane);
  glUniform1f(particle.loc("u_inv_near_fade"), rs.near_fade > 0.0f ? 1.0f / rs.near_fade : 1e30f);
  glUniform1f(particle.loc("u_contrast_power"), rs.contrast_power);
  // view depth = x / (y·depth + z) with the denominator's sign made positive in every mode
  // (standard depth has depth + B ≤ 0), so the shader guards it with one max().
  const glm::vec2 linearize = frame.vp.linearize;
  float lsign = linearize.x >= 0.0f ? 1.0f : -1.0f;
  glUniform3f(particle.loc("u_linearize"), lsign * linearize.x, lsign, lsign * linearize.y);
  glUniform1i(particle.loc("u_linear"), rs.hdr);
  glUniform1i(particle.loc("u_sprites"), 0);
  glUniform1i(particle.loc("u_scene_depth"), 1);
  glUniform1i(particle.loc("u_particles"), 2);
  glUniform2f(particle.loc("u_inv_depth_size"), 1.0f / float(frame.scene_width), 1.0f / float(frame.scene_height));
  // Sprite texels per screen pixel at unit view depth and unit half-size, and which mip levels
  // the filter can read (the trim box of the coarsest one is taken: sprite_trim.h).
  glUniform1i(particle.loc("u_trim"), 3);
  glUniform1f(particle.loc("u_lod_scale"), trim.lod_scale(float(std::tan(frame.fov_y_radians * 0.5)), frame.scene_height));
  glUniform1i(particle.loc("u_trim_mode"), int(trim_mode(rs)));
}

}  // namespace

ParticlePass::ParticlePass(size_t draw_limit) {
  // Particles are pulled by the vertex shader from a buffer texture over the frame's upload;
  // the VAO holds only the index buffer (two triangles per particle).
  static_assert(sizeof(ParticleInstance) == 64 && offsetof(ParticleInstance, sprite) == 56 &&
                    offsetof(ParticleInstance, soft_edge) == 58 && offsetof(ParticleInstance, billboard) == 59,
                "shaders/particle.vert reads ParticleInstance as four RGBA32UI texels");
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glGenBuffers(1, &ibo_);
  glGenTextures(1, &tbo_);
  glGenBuffers(1, &order_buf_);
  glGenTextures(1, &order_tbo_);
  glBindBuffer(GL_TEXTURE_BUFFER, order_buf_);
  glBufferData(GL_TEXTURE_BUFFER, sizeof(uint32_t), nullptr, GL_STREAM_DRAW);
  glBindTexture(GL_TEXTURE_BUFFER, order_tbo_);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_R32UI, order_buf_);
  glBindBuffer(GL_TEXTURE_BUFFER, vbo_);
  glBufferData(GL_TEXTURE_BUFFER, sizeof(ParticleInstance), nullptr, GL_STREAM_DRAW);
  glBindTexture(GL_TEXTURE_BUFFER, tbo_);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32UI, vbo_);
  GLint max_texels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
  max_particles_per_draw_ = max_source_particles_ = size_t(std::max(max_texels, 4)) / 4;
  if (draw_limit > 0) max_particles_per_draw_ = std::min(max_particles_per_draw_, draw_limit);
  Image white;
  white.width = white.height = 1;
  white.rgba = {255, 255, 255, 255};
  white.premultiplied = true;
  set_sprites({white}, RenderSettings{}.filter);
}

ParticlePass::~ParticlePass() {
  glDeleteVertexArrays(1, &vao_);
  GLuint bufs[] = {vbo_, ibo_, order_buf_};
  glDeleteBuffers(3, bufs);
  GLuint tex[] = {tbo_, sprite_tex_, sprite_tex_linear_, trim_tex_, order_tbo_};
  glDeleteTextures(5, tex);
  if (fragment_query_) glDeleteQueries(1, &fragment_query_);
}

void ParticlePass::set_sprites(const std::vector<Image>& sprites, RenderSettings::Filter filter) {
  if (sprites.empty()) throw std::invalid_argument("set_sprites: at least one sprite is needed");
  sprites_ = sprites;
  filter_ = filter;
  sprite_w_ = sprite_h_ = 0;
  for (auto& s : sprites_) {
    sprite_w_ = std::max(sprite_w_, s.width);
    sprite_h_ = std::max(sprite_h_, s.height);
  }
  // Display values premultiplied in sRGB bytes, exactly as load_sprite() does (the image before
  // HDR); the linear-light array is made the first time an HDR frame needs it.
  std::vector<Image> display = sprites_;
  for (Image& s : display) premultiply(s);
  if (!sprite_tex_) glGenTextures(1, &sprite_tex_);
  upload_sprite_array(sprite_tex_, GL_RGBA8, display);
  // The trim boxes of the array as uploaded (linear-light premultiplication keeps the zeros).
  std::vector<Image> stretched;
  for (const Image& s : display) stretched.push_back(stretch_nearest(s, sprite_w_, sprite_h_));
  trim_.boxes = trim_boxes(stretched);
  trim_.levels = mip_levels(sprite_w_, sprite_h_);
  trim_.texels = std::max(sprite_w_, sprite_h_);
  if (!trim_tex_) glGenTextures(1, &trim_tex_);
  glBindTexture(GL_TEXTURE_2D, trim_tex_);
  static_assert(sizeof(TrimBox) == 4 * sizeof(float), "trim boxes are uploaded as RGBA32F texels");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, trim_.levels, GLsizei(stretched.size()), 0, GL_RGBA, GL_FLOAT,
               trim_.boxes.data());
  set_target_sampling(GL_TEXTURE_2D, GL_NEAREST);
  if (sprite_tex_linear_) glDeleteTextures(1, &sprite_tex_linear_);
  sprite_tex_linear_ = 0;
}

GLuint ParticlePass::sprite_texture(bool linear) {
  if (!linear) return sprite_tex_;
  if (!sprite_tex_linear_) {
    std::vector<Image> texels;
    for (const Image& s : sprites_) texels.push_back(premultiply_linear_srgb(s));
    glGenTextures(1, &sprite_tex_linear_);
    upload_sprite_array(sprite_tex_linear_, GL_SRGB8_ALPHA8, texels);
  }
  return sprite_tex_linear_;
}

// Layers share one size; smaller sprites are stretched by nearest sampling at upload.
void ParticlePass::upload_sprite_array(GLuint tex, GLenum internal_format, const std::vector<Image>& sprites) const {
  const int w = sprite_w_, h = sprite_h_;
  glBindTexture(GL_TEXTURE_2D_ARRAY, tex);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GLint(internal_format), w, h, GLsizei(sprites.size()), 0, GL_RGBA,
               GL_UNSIGNED_BYTE, nullptr);
  for (size_t layer = 0; layer < sprites.size(); ++layer) {
    const Image s = stretch_nearest(sprites[layer], w, h);
    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, GLint(layer), w, h, 1, GL_RGBA, GL_UNSIGNED_BYTE, s.rgba.data());
  }
  // Mipmaps of an sRGB array are averaged in linear light (the driver decodes and encodes).
  glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  apply_texture_filter(GL_TEXTURE_2D_ARRAY, filter_);
}

void ParticlePass::set_texture_filter(RenderSettings::Filter filter) {
  filter_ = filter;
  for (GLuint tex : {sprite_tex_, sprite_tex_linear_}) {
    if (!tex) continue;
    glBindTexture(GL_TEXTURE_2D_ARRAY, tex);
    apply_texture_filter(GL_TEXTURE_2D_ARRAY, filter);
  }
}

// Orphans the buffer when it must grow or is in use (GL_STREAM_DRAW: the driver hands a fresh
// one while the previous frame's draw still reads the old), then writes `bytes` at its start.
void ParticlePass::stream(GLuint buffer, size_t& capacity, const void* data, size_t bytes) {
  glBindBuffer(GL_TEXTURE_BUFFER, buffer);
  if (bytes > capacity) capacity = bytes * 3 / 2;
  glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(capacity), nullptr, GL_STREAM_DRAW);  // new or orphaned
  glBufferSubData(GL_TEXTURE_BUFFER, 0, GLsizeiptr(bytes), data);
}

void ParticlePass::upload(const std::vector<ParticleInstance>& particles) {
  stream(vbo_, capacity_bytes_, particles.data(), particles.size() * sizeof(ParticleInstance));
  uploaded_ = particles.size();
  ensure_indices(particles.size());
}

void ParticlePass::upload(const ParticleBatch& batch) {
  if (!batch.indexed()) return upload(batch.particles);
  stream(vbo_, capacity_bytes_, batch.source->data(), batch.source->size() * sizeof(ParticleInstance));
  stream(order_buf_, order_capacity_bytes_, batch.order.data(), batch.order.size() * sizeof(uint32_t));
  uploaded_ = batch.order.size();
  ensure_indices(batch.order.size());
}

// The static index buffer: two triangles per quad, for at least `quads` quads.
void ParticlePass::ensure_indices(size_t quads) {
  glBindVertexArray(vao_);
  if (quads > index_capacity_) {
    index_capacity_ = std::max<size_t>(quads * 3 / 2, 1024);
    std::vector<uint32_t> indices(index_capacity_ * 6);
    for (size_t i = 0; i < index_capacity_; ++i) {
      const uint32_t b = uint32_t(i * 4);
      const uint32_t quad[6] = {b, b + 1, b + 2, b + 2, b + 1, b + 3};
      std::copy(quad, quad + 6, indices.begin() + std::ptrdiff_t(i * 6));
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * 4), indices.data(), GL_STATIC_DRAW);
  }
}

int ParticlePass::draw(const ParticleBatch& batch, const ShaderPrograms& programs, const RenderSettings& rs,
                       const ParticleFrame& frame) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(rs.reversed_z ? GL_GREATER : GL_LEQUAL);  // as the mesh pass: far ones round to depth 1
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  if (frame.transmittance_alpha) glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
  else glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D_ARRAY, sprite_texture(rs.hdr));
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, frame.depth_copy);
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_BUFFER, tbo_);
  glActiveTexture(GL_TEXTURE3);
  glBindTexture(GL_TEXTURE_2D, trim_tex_);
  glActiveTexture(GL_TEXTURE4);
  glBindTexture(GL_TEXTURE_BUFFER, order_tbo_);
  glActiveTexture(GL_TEXTURE0);
  glBindVertexArray(vao_);
  if (count_fragments_) {
    if (!fragment_query_) glGenQueries(1, &fragment_query_);
    glBeginQuery(GL_SAMPLES_PASSED, fragment_query_);
  }
  // One draw per run, each with its program; a program's uniforms are set the first time a
  // run of the frame uses it.
  std::vector<GLuint> ready;
  GLuint current = 0;
  int draws = 0;
  for (const ParticleRun& run : batch.runs) {
    const Program& particle = choose_program(programs, run, rs.contrast_power, frame.depth_fetch, batch.indexed());
    if (particle.id == 0) throw std::logic_error("ParticlePass::draw: an indexed batch before build_indexed()");
    if (particle.id != current) {
      glUseProgram(particle.id);
      current = particle.id;
      if (std::find(ready.begin(), ready.end(), current) == ready.end()) {
        set_uniforms(particle, rs, frame, trim_, batch);
        ready.push_back(current);
      }
    }
    const size_t first_index = size_t(run.first) * 6 * sizeof(uint32_t);
    glDrawElements(GL_TRIANGLES, GLsizei(run.count * 6), GL_UNSIGNED_INT, reinterpret_cast<const void*>(first_index));
    ++draws;
  }
  if (count_fragments_) {
    glEndQuery(GL_SAMPLES_PASSED);
    query_pending_ = true;
  }
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  return draws;
}

long long ParticlePass::take_fragments() {
  if (!query_pending_) return -1;
  query_pending_ = false;
  GLuint64 samples = 0;
  glGetQueryObjectui64v(fragment_query_, GL_QUERY_RESULT, &samples);
  return static_cast<long long>(samples);
}

}  // namespace arc
