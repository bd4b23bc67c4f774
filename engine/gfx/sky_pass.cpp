// gfx/sky_pass.cpp — seeded starfield, nebula cube-map bake, and the sky draw.
#include "gfx/sky_pass.h"
#include "gfx/gl_features.h"
#include "gfx/render_targets.h"
#include "gfx/texture_filter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>

#include "core/rng.h"

namespace arc {
namespace {

// Each cube face as sky_exact.frag sees it: columns right, up, back such that a face pixel at
// (sc, tc) in [−1, 1]² looks along right·sc + up·tc − back, the direction the GL cube map rules
// (major axis, sc, tc) assign to that texel.
const glm::mat3 kCubeFaceBasis[6] = {
    glm::mat3(glm::vec3(0, 0, -1), glm::vec3(0, -1, 0), glm::vec3(-1, 0, 0)),  // +X
    glm::mat3(glm::vec3(0, 0, 1), glm::vec3(0, -1, 0), glm::vec3(1, 0, 0)),    // −X
    glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(0, -1, 0)),    // +Y
    glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0)),    // −Y
    glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, -1)),   // +Z
    glm::mat3(glm::vec3(-1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, 1)),   // −Z
};

constexpr int kStars = 2600;

// The nebula's two lobes, oriented by the seed (drawn after the stars from the same stream).
std::pair<glm::vec3, glm::vec3> nebula_lobes(uint64_t seed) {
  const Rng r{seed, 0x57A25, 0};
  return {glm::vec3(r.unit_vector(uint64_t(kStars) * 6)), glm::vec3(r.unit_vector(uint64_t(kStars) * 6 + 1))};
}

}  // namespace

SkyPass::SkyPass() {
  glGenVertexArrays(1, &empty_vao_);
  glGenVertexArrays(1, &star_vao_);
  glGenBuffers(1, &star_vbo_);
}

SkyPass::~SkyPass() {
  GLuint vaos[] = {empty_vao_, star_vao_};
  glDeleteVertexArrays(2, vaos);
  glDeleteBuffers(1, &star_vbo_);
  for (BakedCube& c : cubes_) glDeleteTextures(1, &c.tex);
  glDeleteTextures(1, &corner_tex_);
  GLuint fbos[] = {cube_fbo_, corner_fbo_};
  glDeleteFramebuffers(2, fbos);
}

void SkyPass::build_stars(uint64_t seed) {
  // Seeded stars: a few bright ones, many faint, tints from red dwarfs to blue giants.
  const int n = kStars;
  Rng r{seed, 0x57A25, 0};
  std::vector<float> data;
  data.reserve(n * 7);
  for (int i = 0; i < n; ++i) {
    glm::dvec3 d = r.unit_vector(uint64_t(i));
    double u = r.uniform(uint64_t(n) * 4 + i);
    double bright = 0.2 + 0.8 * std::pow(u, 5.0);
    double t = r.uniform(uint64_t(n) * 5 + i);
    glm::dvec3 tint = t < 0.2 ? glm::dvec3(1.0, 0.75, 0.6) : t < 0.55 ? glm::dvec3(1.0, 0.95, 0.88)
                                                          : t < 0.85 ? glm::dvec3(0.9, 0.95, 1.0)
                                                                     : glm::dvec3(0.7, 0.82, 1.0);
    float size = float(2.0 + 3.0 * std::pow(u, 4.0));
    glm::vec3 c = glm::vec3(tint * bright * 1.6);
    data.insert(data.end(), {float(d.x), float(d.y), float(d.z), size, c.r, c.g, c.b});
  }
  std::tie(lobe_a_, lobe_b_) = nebula_lobes(seed);
  glBindVertexArray(star_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, star_vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * 4), data.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 28, nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 28, reinterpret_cast<void*>(16));
  glBindVertexArray(0);
  star_count_ = n;
  star_seed_ = seed;
}

void SkyPass::set_uniforms(const Program& p, const glm::mat3& basis, float tan_x, float tan_y) const {
  glUniformMatrix3fv(p.loc("u_cam_basis"), 1, GL_FALSE, glm::value_ptr(basis));
  glUniform2f(p.loc("u_tan_half"), tan_x, tan_y);
  glUniform3fv(p.loc("u_lobe_a"), 1, glm::value_ptr(lobe_a_));
  glUniform3fv(p.loc("u_lobe_b"), 1, glm::value_ptr(lobe_b_));
  glUniform1f(p.loc("u_seed"), float(star_seed_ % 1000));
}

// The nebula changes only with the level's seed, so it is rendered once into the six faces of a
// half-float cube map (a face of 256² is 0.35° a texel, the noise's finest feature about 4°) and
// each frame looks it up. The face edges need no seamless filtering (dear on llvmpipe): each face
// is baked with its outermost texel centres on the cube's edges (a field of view n/(n − 1) wider
// than the face), so neighbouring faces hold the same colours along a shared edge, and sky.frag
// scales the lookup's minor coordinates by (n − 1)/n so that a direction on an edge lands on
// those texel centres.
SkyPass::BakedCube& SkyPass::cube_for(uint64_t seed, const ShaderPrograms& programs, const RenderSettings& rs) {
  const int n = rs.sky_resolution;
  BakedCube* pick = nullptr;
  for (BakedCube& c : cubes_) {
    if (c.seed == seed && c.linear == rs.hdr && c.size == n && c.shader_generation == programs.generation()) {
      pick = &c;
      break;
    }
    if (!pick || c.last_use < pick->last_use) pick = &c;
  }
  BakedCube& cube = *pick;
  cube.last_use = ++use_clock_;
  if (cube.seed == seed && cube.linear == rs.hdr && cube.size == n && cube.shader_generation == programs.generation())
    return cube;
  if (!cube.tex) glGenTextures(1, &cube.tex);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube.tex);
  if (cube.size != n)
    for (int f = 0; f < 6; ++f)
      glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA16F, n, n, 0, GL_RGBA, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);
  cube.size = n;
  cube.seed = seed;
  cube.linear = rs.hdr;
  cube.shader_generation = programs.generation();
  cube.faces = 0;
  return cube;
}

// The nebula changes only with the level's seed, so it is rendered once into the six faces of a
// half-float cube map (a face of 256² is 0.35° a texel, the noise's finest feature about 4°) and
// each frame looks it up. The face edges need no seamless filtering (dear on llvmpipe): each face
// is baked with its outermost texel centres on the cube's edges (a field of view n/(n − 1) wider
// than the face), so neighbouring faces hold the same colours along a shared edge, and sky.frag
// scales the lookup's minor coordinates by (n − 1)/n so that a direction on an edge lands on
// those texel centres.
void SkyPass::bake_faces(BakedCube& cube, const ShaderPrograms& programs, int first, int last) {
  const int n = cube.size;
  if (!cube_fbo_) glGenFramebuffers(1, &cube_fbo_);
  GLint fbo = 0, vp[4];
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
  glGetIntegerv(GL_VIEWPORT, vp);
  // The faces are baked as GL stores a cube map's faces, whatever origin the scene is drawn
  // with (a top-down scene's upper-left origin would mirror every face).
  const bool clip_control = has_clip_control();
  GLint origin = GL_LOWER_LEFT, depth_mode = GL_NEGATIVE_ONE_TO_ONE;
  if (clip_control) {
    glGetIntegerv(GL_CLIP_ORIGIN, &origin);
    glGetIntegerv(GL_CLIP_DEPTH_MODE, &depth_mode);
    glClipControl(GL_LOWER_LEFT, GLenum(depth_mode));
  }
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_BLEND);
  glBindFramebuffer(GL_FRAMEBUFFER, cube_fbo_);
  glViewport(0, 0, n, n);
  const Program& p = programs.sky_exact;
  glUseProgram(p.id);
  glBindVertexArray(empty_vao_);
  const auto [lobe_a, lobe_b] = nebula_lobes(cube.seed);
  const float edge_to_edge = float(n) / float(n - 1);
  for (int f = first; f < last; ++f) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), cube.tex, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("sky cube map framebuffer incomplete");
    glUniformMatrix3fv(p.loc("u_cam_basis"), 1, GL_FALSE, glm::value_ptr(kCubeFaceBasis[f]));
    glUniform2f(p.loc("u_tan_half"), edge_to_edge, edge_to_edge);
    glUniform3fv(p.loc("u_lobe_a"), 1, glm::value_ptr(lobe_a));
    glUniform3fv(p.loc("u_lobe_b"), 1, glm::value_ptr(lobe_b));
    glUniform1f(p.loc("u_seed"), float(cube.seed % 1000));
    glUniform1i(p.loc("u_linear"), cube.linear);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  cube.faces = std::max(cube.faces, last);
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(fbo));
  glViewport(vp[0], vp[1], vp[2], vp[3]);
  if (clip_control) glClipControl(GLenum(origin), GLenum(depth_mode));
}

bool SkyPass::warm(uint64_t seed, const ShaderPrograms& programs, const RenderSettings& rs) {
  if (rs.sky_exact) return true;
  BakedCube& cube = cube_for(seed, programs, rs);
  if (cube.faces < 6) bake_faces(cube, programs, cube.faces, cube.faces + 1);
  return cube.faces == 6;
}

SkyPass::SkyGrid SkyPass::sky_grid_of(int n, int scene_w, int scene_h) {
  return {n, scene_w, scene_h, (scene_w + n - 1) / n, (scene_h + n - 1) / n, 2.0f * float(n) / float(scene_w),
          2.0f * float(n) / float(scene_h)};
}

int SkyPass::draw_nebula(const RenderView& v, const ShaderPrograms& programs, const ViewProjection& vp,
                         const RenderSettings& rs, int scene_w, int scene_h, GLuint color_only_fbo) {
  if (star_seed_ != v.starfield_seed) build_stars(v.starfield_seed);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_BLEND);
  GLuint cube_tex = 0;
  int cube_size = rs.sky_resolution;
  if (!rs.sky_exact) {
    BakedCube& cube = cube_for(star_seed_, programs, rs);
    if (cube.faces < 6) bake_faces(cube, programs, cube.faces, 6);
    cube_tex = cube.tex;
  }
  const bool grid = !rs.sky_exact && rs.sky_grid > 0;
  const float ty = float(std::tan(v.camera.fov_y_radians * 0.5)), tx = float(ty * vp.aspect);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube_tex);
  glBindVertexArray(empty_vao_);
  const SkyGrid g = sky_grid_of(std::max(rs.sky_grid, 1), scene_w, scene_h);
  int draws = 1;
  if (grid && color_only_fbo && !rs.hdr) {
    draw_corner_cells(programs, vp.camera_basis, tx, ty, cube_size, g, color_only_fbo);
    draws = 2;
  } else {
    if (color_only_fbo) {
      glBindFramebuffer(GL_FRAMEBUFFER, color_only_fbo);
      glViewport(0, 0, scene_w, scene_h);
    }
    const Program& p = rs.sky_exact ? programs.sky_exact : grid ? programs.sky_grid : programs.sky;
    glUseProgram(p.id);
    set_uniforms(p, vp.camera_basis, tx, ty);
    glUniform1i(p.loc("u_sky"), 0);
    glUniform1i(p.loc("u_linear"), rs.hdr);
    if (!rs.sky_exact) glUniform1f(p.loc("u_edge_scale"), float(cube_size - 1) / float(cube_size));
    if (grid) {
      glUniform1i(p.loc("u_cells_x"), g.cells_x);
      glUniform2f(p.loc("u_cell_ndc"), g.cell_ndc_x, g.cell_ndc_y);
      glDrawArrays(GL_TRIANGLES, 0, g.cells_x * g.cells_y * 6);
    } else {
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
  }
  return draws;
}

int SkyPass::draw_stars(const RenderView& v, const ShaderPrograms& programs, const ViewProjection& vp,
                        const RenderSettings& rs, int scene_h) {
  if (star_seed_ != v.starfield_seed) build_stars(v.starfield_seed);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glUseProgram(programs.stars.id);
  glUniformMatrix4fv(programs.stars.loc("u_view_proj"), 1, GL_FALSE, glm::value_ptr(vp.view_proj));
  glUniform1f(programs.stars.loc("u_pixel_scale"), float(std::max(1.0, scene_h / 720.0)));
  glUniform1i(programs.stars.loc("u_linear"), rs.hdr);
  glBindVertexArray(star_vao_);
  glDrawArrays(GL_POINTS, 0, star_count_);
  glDisable(GL_PROGRAM_POINT_SIZE);
  glDisable(GL_BLEND);
  return 1;
}

// The grid through a texture of its corners (sky_pass.h): the corners' lookups into that
// texture, then one rectangle over the scene's colour alone. The corner texture is indexed by
// its own texels (gl_FragCoord), and the rectangle maps NDC to it, so the result is the same
// under either clip origin. Leaves `color_only_fbo` bound with the scene's viewport.
void SkyPass::draw_corner_cells(const ShaderPrograms& programs, const glm::mat3& basis, float tan_x, float tan_y,
                                int cube_size, const SkyGrid& g, GLuint color_only_fbo) {
  if (!corner_fbo_) {
    glGenFramebuffers(1, &corner_fbo_);
    glGenTextures(1, &corner_tex_);
  }
  if (g.cells_x + 1 != corners_x_ || g.cells_y + 1 != corners_y_) {
    corners_x_ = g.cells_x + 1;
    corners_y_ = g.cells_y + 1;
    glBindTexture(GL_TEXTURE_2D, corner_tex_);
    allocate_rgba8(corners_x_, corners_y_);
    set_target_sampling(GL_TEXTURE_2D, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, corner_fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, corner_tex_, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("sky corner framebuffer incomplete");
    glBindTexture(GL_TEXTURE_2D, 0);  // not bound while drawn into
  }
  glBindFramebuffer(GL_FRAMEBUFFER, corner_fbo_);
  glViewport(0, 0, corners_x_, corners_y_);
  const Program& c = programs.sky_corners;
  glUseProgram(c.id);
  set_uniforms(c, basis, tan_x, tan_y);
  glUniform1i(c.loc("u_sky"), 0);
  glUniform1f(c.loc("u_edge_scale"), float(cube_size - 1) / float(cube_size));
  glUniform2f(c.loc("u_cell_ndc"), g.cell_ndc_x, g.cell_ndc_y);
  glDrawArrays(GL_TRIANGLES, 0, 3);

  glBindFramebuffer(GL_FRAMEBUFFER, color_only_fbo);
  glViewport(0, 0, g.scene_w, g.scene_h);
  const Program& r = programs.sky_cells;
  glUseProgram(r.id);
  glUniform1i(r.loc("u_corners"), 0);
  glUniform2f(r.loc("u_corner_scale"), float(g.scene_w) / float(g.n * corners_x_), float(g.scene_h) / float(g.n * corners_y_));
  glUniform2f(r.loc("u_corner_offset"), 0.5f / float(corners_x_), 0.5f / float(corners_y_));
  glBindTexture(GL_TEXTURE_2D, corner_tex_);
  glDrawArrays(GL_TRIANGLES, 0, 6);
  glBindTexture(GL_TEXTURE_2D, 0);  // nor bound when the next frame's corners are drawn
}

}  // namespace arc
