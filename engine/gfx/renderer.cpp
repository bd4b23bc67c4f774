#include "gfx/renderer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "core/rng.h"
#include "gfx/cover_boxes.h"
#include "gfx/hud_font.h"

namespace arc {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error(path + ": cannot open shader");
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

GLuint compile(GLenum type, const std::string& src, const std::string& name, std::string& err) {
  GLuint sh = glCreateShader(type);
  const char* p = src.c_str();
  glShaderSource(sh, 1, &p, nullptr);
  glCompileShader(sh);
  GLint ok = 0;
  glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetShaderInfoLog(sh, sizeof log, nullptr, log);
    err += name + ": " + log;
    glDeleteShader(sh);
    return 0;
  }
  return sh;
}

// Builds vert+frag from the shader folder; returns 0 and appends to err on failure.
// `defines` goes right after the #version line of the fragment shader.
GLuint build_program(const std::string& dir, const std::string& vs, const std::string& fs, const std::string& defines,
                     std::string& err) {
  std::string vsrc, fsrc;
  try {
    vsrc = read_text(dir + "/" + vs);
    fsrc = read_text(dir + "/" + fs);
  } catch (const std::exception& e) {
    err += std::string(e.what()) + "\n";
    return 0;
  }
  if (!defines.empty()) {
    size_t eol = fsrc.find('\n');
    fsrc.insert(eol == std::string::npos ? fsrc.size() : eol + 1, defines);
  }
  GLuint v = compile(GL_VERTEX_SHADER, vsrc, dir + "/" + vs, err);
  GLuint f = compile(GL_FRAGMENT_SHADER, fsrc, dir + "/" + fs, err);
  if (!v || !f) {
    if (v) glDeleteShader(v);
    if (f) glDeleteShader(f);
    return 0;
  }
  GLuint prog = glCreateProgram();
  glAttachShader(prog, v);
  glAttachShader(prog, f);
  glLinkProgram(prog);
  glDeleteShader(v);
  glDeleteShader(f);
  GLint ok = 0;
  glGetProgramiv(prog, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetProgramInfoLog(prog, sizeof log, nullptr, log);
    err += vs + "+" + fs + " link: " + log;
    glDeleteProgram(prog);
    return 0;
  }
  return prog;
}

struct Program {
  GLuint id = 0;
  GLint loc(const char* name) const { return glGetUniformLocation(id, name); }
};

struct GpuPrimitive {
  GLuint vao = 0, vbo = 0, ibo = 0;
  GLsizei count = 0;
  int material = -1;
};

struct GpuModel {
  std::vector<GpuPrimitive> prims;
  std::vector<Material> materials;
  std::vector<GLuint> textures;
  std::vector<Box3> parts;  // up to eight boxes that hold its triangles (cover_boxes.h)
};

// An opaque mesh as the particle pass sees it: the view depth range of its box and the box's
// screen rectangle in tangent units (x/depth, y/depth); infinite when the box crosses the near
// plane.
struct Occluder {
  float nearest, farthest;
  float x0, y0, x1, y1;
  // Covers nothing: the identity of include().
  static Occluder none() {
    const float inf = std::numeric_limits<float>::infinity();
    return Occluder{inf, -inf, inf, inf, -inf, -inf};
  }
  void include(const Occluder& o) {
    nearest = std::min(nearest, o.nearest), farthest = std::max(farthest, o.farthest);
    x0 = std::min(x0, o.x0), x1 = std::max(x1, o.x1);
    y0 = std::min(y0, o.y0), y1 = std::max(y1, o.y1);
  }
};

// One mesh instance: the union of its part boxes' occluders, and where they are.
struct OccluderGroup {
  Occluder bound;
  size_t first, count;
};

// Where a particle's quad can be, as shaders/particle.vert builds it: corners lie within
// `radius` = √(size² + half_long²) of the view-space centre, whatever the billboard (the
// size clamp there only shrinks it), and the density methods' push along the view ray keeps
// the footprint. Computed once per particle for culling and the soft-edge reach test.
struct QuadBounds {
  glm::vec3 centre;  // view space
  float size, half_long, radius;
  bool axis_locked;
};

QuadBounds quad_bounds(const ParticleInstance& p, const glm::mat3& to_view, float axis_len) {
  QuadBounds b;
  b.centre = to_view * glm::vec3(p.pos[0], p.pos[1], p.pos[2]);
  b.size = std::max(p.size, 1e-6f);
  b.axis_locked = p.billboard == uint8_t(Billboard::AxisLocked);
  b.half_long = b.axis_locked ? 0.5f * axis_len + b.size : b.size;
  b.radius = std::sqrt(b.size * b.size + b.half_long * b.half_long) * 1.001f;
  return b;
}

// Set on the uploaded copy of a particle whose soft edges cannot change a pixel: no opaque
// mesh comes within its depth extent anywhere on its quad. shaders/particle.vert reads it.
constexpr uint8_t kSoftClear = 0x80;

uint32_t sortable_bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return (u & 0x80000000u) ? ~u : (u | 0x80000000u);
}

GLint min_filter(RenderSettings::Filter f) {
  switch (f) {
    case RenderSettings::Filter::Nearest: return GL_NEAREST;
    case RenderSettings::Filter::Linear: return GL_LINEAR;
    case RenderSettings::Filter::Mipmap: return GL_LINEAR_MIPMAP_LINEAR;
  }
  return GL_LINEAR;
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

void radix_sort_back_to_front(const std::vector<uint32_t>& keys, std::vector<uint32_t>& order) {
  // Descending keys = ascending of the complement.
  size_t n = keys.size();
  std::vector<uint32_t> k(n), k2(n), o2(n);
  order.resize(n);
  for (size_t i = 0; i < n; ++i) {
    k[i] = ~keys[i];
    order[i] = uint32_t(i);
  }
  for (int shift = 0; shift < 32; shift += 8) {
    std::array<uint32_t, 257> count{};
    for (size_t i = 0; i < n; ++i) ++count[((k[i] >> shift) & 0xFF) + 1];
    bool uniform_digit = false;  // all keys share this digit: the pass would be a plain copy
    for (int b = 1; b <= 256; ++b) uniform_digit = uniform_digit || count[b] == n;
    if (uniform_digit) continue;
    for (int b = 0; b < 256; ++b) count[b + 1] += count[b];
    for (size_t i = 0; i < n; ++i) {
      uint32_t dst = count[(k[i] >> shift) & 0xFF]++;
      k2[dst] = k[i];
      o2[dst] = order[i];
    }
    k.swap(k2);
    order.swap(o2);
  }
}

struct Renderer::Impl {
  RendererDesc desc;
  RenderSettings rs;
  std::string version;
  bool clip_control = false;
  bool timer_query = false;

  Program sky, sky_exact, stars, mesh, particle_hard, particle_soft, particle_contrast, particle_square, hud;

  std::vector<GpuModel> models;
  GLuint sprite_tex = 0;
  int sprite_layers = 0;
  int sprite_w = 1, sprite_h = 1;
  GLuint white_tex = 0;

  // Scene buffer at render scale, depth copy for soft edges, offscreen RGBA8 target.
  GLuint scene_fbo = 0, scene_color = 0, scene_depth = 0;
  GLuint copy_fbo = 0, copy_depth = 0;
  GLuint target_fbo = 0, target_color = 0;
  int scene_w = 0, scene_h = 0, target_w = 0, target_h = 0;
  bool scene_float = false;

  GLuint empty_vao = 0;
  GLuint star_vao = 0, star_vbo = 0;
  int star_count = 0;
  uint64_t star_seed = ~0ull;
  glm::vec3 lobe_a{1, 0, 0}, lobe_b{0, 1, 0};
  // The nebula baked into a cube map for render.sky = baked: made again when the level's seed,
  // the resolution or the shaders change.
  GLuint sky_cube = 0, sky_fbo = 0;
  int sky_cube_size = 0;
  uint64_t sky_cube_seed = ~0ull;

  GLuint particle_vao = 0, particle_vbo = 0, particle_ibo = 0, particle_tbo = 0;
  size_t particle_capacity = 0;  // bytes in particle_vbo
  size_t index_capacity = 0;     // particles particle_ibo has indices for
  size_t max_particles_per_draw = 0;  // GL_MAX_TEXTURE_BUFFER_SIZE / 4
  std::vector<ParticleInstance> upload;
  std::vector<uint32_t> keys, order;
  std::vector<Occluder> occluders;        // one per part box of each visible mesh instance
  std::vector<OccluderGroup> occluder_groups;
  Occluder occluder_bounds{};  // union of all: most particles of a frame fall outside it

  GLuint hud_vao = 0, hud_vbo = 0;
  HudFont font;
  GLuint font_tex = 0;

  std::array<GLuint, 3> queries{};
  std::array<bool, 3> query_pending{};
  int query_index = 0;
  double last_gpu_ms = -1;
  bool count_fragments = false;
  GLuint fragment_query = 0;
  bool time_passes = false;  // synchronous GL_TIME_ELAPSED of the particle pass and fill reference
  GLuint pass_query = 0;
  void begin_pass_timer();
  double end_pass_timer();

  FrameStats stats;
  glm::mat4 last_view_proj{1.0f};

  void load_programs(bool throw_on_error);
  void ensure_targets(int w, int h);
  void build_stars(uint64_t seed);
  void bake_sky();
  void set_sky_uniforms(const Program& p, const glm::mat3& basis, float tan_x, float tan_y) const;
  void draw_sky(const RenderView& v, const glm::mat3& cam_basis, const glm::mat4& view_proj, double aspect);
  void draw_meshes(const RenderView& v, const glm::mat4& view_proj);
  void draw_particles(const RenderView& v, const glm::mat4& view, const glm::mat4& proj, glm::vec2 linearize);
  void gather_occluders(const RenderView& v, const glm::mat3& to_view, float tan_x, float tan_y);
  bool soft_can_matter(const ParticleInstance& p, const QuadBounds& q, float near) const;
  void draw_hud(const HudLayer& hud, int w, int h);
  void upload_texture_params(GLenum target, bool mipmapped);
};

void Renderer::Impl::load_programs(bool throw_on_error) {
  std::string err;
  struct Spec {
    Program* p;
    const char* vs;
    const char* fs;
    const char* defines;
  };
  const Spec specs[] = {{&sky, "sky.vert", "sky.frag", ""},
                        {&sky_exact, "sky.vert", "sky_exact.frag", ""},
                        {&stars, "stars.vert", "stars.frag", ""},
                        {&mesh, "mesh.vert", "mesh.frag", ""},
                        {&particle_hard, "particle.vert", "particle.frag", "#define SOFT 0\n#define CONTRAST 0\n"},
                        {&particle_soft, "particle.vert", "particle.frag", "#define SOFT 1\n#define CONTRAST 0\n"},
                        {&particle_contrast, "particle.vert", "particle.frag",
                         "#define SOFT 1\n#define CONTRAST 1\n#define CONTRAST_SQUARE 0\n"},
                        {&particle_square, "particle.vert", "particle.frag",
                         "#define SOFT 1\n#define CONTRAST 1\n#define CONTRAST_SQUARE 1\n"},
                        {&hud, "hud.vert", "hud.frag", ""}};
  std::vector<GLuint> built;
  for (auto& s : specs) built.push_back(build_program(desc.shader_dir, s.vs, s.fs, s.defines, err));
  bool all = std::all_of(built.begin(), built.end(), [](GLuint id) { return id != 0; });
  if (!all) {
    for (GLuint id : built)
      if (id) glDeleteProgram(id);
    if (throw_on_error) throw std::runtime_error("shader build failed: " + err);
    throw std::runtime_error(err);
  }
  for (size_t i = 0; i < built.size(); ++i) {
    if (specs[i].p->id) glDeleteProgram(specs[i].p->id);
    specs[i].p->id = built[i];
  }
  sky_cube_seed = ~0ull;  // a changed nebula shader bakes again
}

Renderer::Renderer(const RendererDesc& desc) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.desc = desc;
  int ver = epoxy_gl_version();
  if (ver < 33) throw std::runtime_error("OpenGL 3.3 or newer is needed, the context has " + std::to_string(ver / 10) + "." + std::to_string(ver % 10));
  m.version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  m.version += std::string(" (") + reinterpret_cast<const char*>(glGetString(GL_RENDERER)) + ")";
  m.clip_control = ver >= 45 || epoxy_has_gl_extension("GL_ARB_clip_control");
  m.timer_query = ver >= 33 || epoxy_has_gl_extension("GL_ARB_timer_query");
  m.load_programs(true);

  glGenVertexArrays(1, &m.empty_vao);
  glGenVertexArrays(1, &m.star_vao);
  glGenBuffers(1, &m.star_vbo);

  // Particles are pulled by the vertex shader from a buffer texture over the frame's upload;
  // the VAO holds only the index buffer (two triangles per particle).
  static_assert(sizeof(ParticleInstance) == 64 && offsetof(ParticleInstance, sprite) == 56 &&
                    offsetof(ParticleInstance, soft_edge) == 58 && offsetof(ParticleInstance, billboard) == 59,
                "shaders/particle.vert reads ParticleInstance as four RGBA32UI texels");
  glGenVertexArrays(1, &m.particle_vao);
  glGenBuffers(1, &m.particle_vbo);
  glGenBuffers(1, &m.particle_ibo);
  glGenTextures(1, &m.particle_tbo);
  glBindBuffer(GL_TEXTURE_BUFFER, m.particle_vbo);
  glBufferData(GL_TEXTURE_BUFFER, sizeof(ParticleInstance), nullptr, GL_STREAM_DRAW);
  glBindTexture(GL_TEXTURE_BUFFER, m.particle_tbo);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32UI, m.particle_vbo);
  GLint max_texels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
  m.max_particles_per_draw = size_t(std::max(max_texels, 4)) / 4;
  if (desc.max_particles_per_draw > 0) m.max_particles_per_draw = std::min(m.max_particles_per_draw, desc.max_particles_per_draw);

  glGenVertexArrays(1, &m.hud_vao);
  glGenBuffers(1, &m.hud_vbo);
  glBindVertexArray(m.hud_vao);
  glBindBuffer(GL_ARRAY_BUFFER, m.hud_vbo);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(HudVertex), reinterpret_cast<void*>(offsetof(HudVertex, x)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(HudVertex), reinterpret_cast<void*>(offsetof(HudVertex, u)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, sizeof(HudVertex), reinterpret_cast<void*>(offsetof(HudVertex, r)));
  glBindVertexArray(0);

  glGenTextures(1, &m.font_tex);
  glBindTexture(GL_TEXTURE_2D, m.font_tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, m.font.width(), m.font.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
               m.font.pixels());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

  // A white 1×1 layer so particles draw (as soft squares of their colour) before any sprites.
  Image white;
  white.width = white.height = 1;
  white.rgba = {255, 255, 255, 255};
  white.premultiplied = true;
  set_sprites({white});

  if (m.timer_query) glGenQueries(3, m.queries.data());
}

Renderer::~Renderer() {
  Impl& m = *impl_;
  for (auto& model : m.models) {
    for (auto& p : model.prims) {
      glDeleteVertexArrays(1, &p.vao);
      glDeleteBuffers(1, &p.vbo);
      glDeleteBuffers(1, &p.ibo);
    }
    if (!model.textures.empty()) glDeleteTextures(GLsizei(model.textures.size()), model.textures.data());
  }
  for (Program* p : {&m.sky, &m.sky_exact, &m.stars, &m.mesh, &m.particle_hard, &m.particle_soft, &m.particle_contrast, &m.particle_square, &m.hud}) glDeleteProgram(p->id);
  GLuint tex[] = {m.sprite_tex, m.font_tex, m.scene_color, m.copy_depth, m.target_color, m.sky_cube};
  glDeleteTextures(6, tex);
  glDeleteRenderbuffers(1, &m.scene_depth);
  GLuint fbos[] = {m.scene_fbo, m.copy_fbo, m.target_fbo, m.sky_fbo};
  glDeleteFramebuffers(4, fbos);
  GLuint vaos[] = {m.empty_vao, m.star_vao, m.particle_vao, m.hud_vao};
  glDeleteVertexArrays(4, vaos);
  GLuint bufs[] = {m.star_vbo, m.particle_vbo, m.particle_ibo, m.hud_vbo};
  glDeleteBuffers(4, bufs);
  glDeleteTextures(1, &m.particle_tbo);
  if (m.timer_query) glDeleteQueries(3, m.queries.data());
  if (m.fragment_query) glDeleteQueries(1, &m.fragment_query);
  if (m.pass_query) glDeleteQueries(1, &m.pass_query);
}

std::string Renderer::gl_version() const { return impl_->version; }
bool Renderer::has_clip_control() const { return impl_->clip_control; }

void Renderer::Impl::upload_texture_params(GLenum target, bool mipmapped) {
  GLint minf = min_filter(rs.filter);
  if (!mipmapped && minf == GL_LINEAR_MIPMAP_LINEAR) minf = GL_LINEAR;
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, minf);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, rs.filter == RenderSettings::Filter::Nearest ? GL_NEAREST : GL_LINEAR);
}

int Renderer::add_model(const ModelData& model) {
  Impl& m = *impl_;
  GpuModel g;
  g.materials = model.materials;
  for (const Image& img : model.images) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    m.upload_texture_params(GL_TEXTURE_2D, true);
    g.textures.push_back(t);
  }
  struct Vertex {
    glm::vec3 p, n;
    glm::vec2 uv;
  };
  g.parts = cover_boxes(model.primitives, 3);
  for (const MeshPrimitive& prim : model.primitives) {
    std::vector<Vertex> verts(prim.positions.size());
    for (size_t i = 0; i < verts.size(); ++i) {
      verts[i].p = prim.positions[i];
      verts[i].n = i < prim.normals.size() ? prim.normals[i] : glm::vec3(0, 1, 0);
      verts[i].uv = i < prim.uvs.size() ? prim.uvs[i] : glm::vec2(0);
    }
    GpuPrimitive gp;
    gp.material = prim.material;
    gp.count = GLsizei(prim.indices.size());
    glGenVertexArrays(1, &gp.vao);
    glGenBuffers(1, &gp.vbo);
    glGenBuffers(1, &gp.ibo);
    glBindVertexArray(gp.vao);
    glBindBuffer(GL_ARRAY_BUFFER, gp.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(verts.size() * sizeof(Vertex)), verts.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gp.ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(prim.indices.size() * 4), prim.indices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, p)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, n)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, uv)));
    glBindVertexArray(0);
    g.prims.push_back(gp);
  }
  m.models.push_back(std::move(g));
  return int(m.models.size()) - 1;
}

void Renderer::set_sprites(const std::vector<Image>& sprites) {
  Impl& m = *impl_;
  if (sprites.empty()) throw std::invalid_argument("set_sprites: at least one sprite is needed");
  int w = 0, h = 0;
  for (auto& s : sprites) {
    w = std::max(w, s.width);
    h = std::max(h, s.height);
  }
  if (!m.sprite_tex) glGenTextures(1, &m.sprite_tex);
  glBindTexture(GL_TEXTURE_2D_ARRAY, m.sprite_tex);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, w, h, GLsizei(sprites.size()), 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  std::vector<uint8_t> resized;
  for (size_t layer = 0; layer < sprites.size(); ++layer) {
    const Image& s = sprites[layer];
    const uint8_t* data = s.rgba.data();
    if (s.width != w || s.height != h) {
      // Layers share one size; smaller sprites are stretched by nearest sampling at upload.
      resized.resize(size_t(w) * h * 4);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          std::memcpy(&resized[(size_t(y) * w + x) * 4], &s.rgba[(size_t(y * s.height / h) * s.width + x * s.width / w) * 4], 4);
      data = resized.data();
    }
    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, GLint(layer), w, h, 1, GL_RGBA, GL_UNSIGNED_BYTE, data);
  }
  glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  m.upload_texture_params(GL_TEXTURE_2D_ARRAY, true);
  m.sprite_layers = int(sprites.size());
  m.sprite_w = w;
  m.sprite_h = h;
}

void Renderer::apply_settings(const Settings& s) {
  RenderSettings r;
  const std::string& soft = s.choice("render.soft_edges");
  const char* names[] = {"off", "linear", "contrast", "average_density", "density_extent"};
  r.soft_override = -1;
  for (int i = 0; i < 5; ++i)
    if (soft == names[i]) r.soft_override = i;
  const std::string& sorting = s.choice("render.sorting");
  r.sorting = sorting == "off" ? RenderSettings::Sorting::Off
              : sorting == "cluster" ? RenderSettings::Sorting::Cluster
                                     : RenderSettings::Sorting::Full;
  r.reversed_z = s.choice("render.depth_mode") == "reversed";
  r.infinite_far = s.flag("render.infinite_far");
  const std::string& f = s.choice("render.texture_filter");
  r.filter = f == "nearest" ? RenderSettings::Filter::Nearest
             : f == "linear" ? RenderSettings::Filter::Linear
                             : RenderSettings::Filter::Mipmap;
  r.scale = s.number("render.scale");
  r.size_clamp = float(s.number("render.particle_size_clamp"));
  r.near_fade = float(s.number("render.near_fade"));
  r.contrast_power = float(s.number("render.contrast_power"));
  r.sky_exact = s.choice("render.sky") == "exact";
  r.sky_resolution = int(s.integer("render.sky_resolution"));
  set_render_settings(r);
}

void Renderer::set_render_settings(const RenderSettings& s) {
  Impl& m = *impl_;
  m.rs = s;
  if (!m.clip_control) m.rs.reversed_z = false;
  m.rs.scale = std::clamp(m.rs.scale, 0.1, 4.0);
  m.rs.sky_resolution = std::clamp(m.rs.sky_resolution, 16, 1024);
  glBindTexture(GL_TEXTURE_2D_ARRAY, m.sprite_tex);
  m.upload_texture_params(GL_TEXTURE_2D_ARRAY, true);
  for (auto& model : m.models)
    for (GLuint t : model.textures) {
      glBindTexture(GL_TEXTURE_2D, t);
      m.upload_texture_params(GL_TEXTURE_2D, true);
    }
}

const RenderSettings& Renderer::render_settings() const { return impl_->rs; }

void Renderer::Impl::ensure_targets(int w, int h) {
  int sw = std::max(1, int(std::lround(w * rs.scale)));
  int sh = std::max(1, int(std::lround(h * rs.scale)));
  if (sw != scene_w || sh != scene_h || scene_float != desc.float_scene || !scene_fbo) {
    scene_w = sw;
    scene_h = sh;
    scene_float = desc.float_scene;
    if (!scene_fbo) {
      glGenFramebuffers(1, &scene_fbo);
      glGenFramebuffers(1, &copy_fbo);
      glGenTextures(1, &scene_color);
      glGenRenderbuffers(1, &scene_depth);
      glGenTextures(1, &copy_depth);
    }
    glBindTexture(GL_TEXTURE_2D, scene_color);
    glTexImage2D(GL_TEXTURE_2D, 0, scene_float ? GL_RGBA16F : GL_RGBA8, sw, sh, 0, GL_RGBA,
                 scene_float ? GL_FLOAT : GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    // Float depth in both modes: reversed-Z needs it, and the copy must match the format.
    glBindRenderbuffer(GL_RENDERBUFFER, scene_depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, sw, sh);
    glBindFramebuffer(GL_FRAMEBUFFER, scene_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, scene_color, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, scene_depth);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("scene framebuffer incomplete");
    glBindTexture(GL_TEXTURE_2D, copy_depth);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, sw, sh, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindFramebuffer(GL_FRAMEBUFFER, copy_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, copy_depth, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("depth copy framebuffer incomplete");
  }
  if (desc.offscreen && (w != target_w || h != target_h || !target_fbo)) {
    target_w = w;
    target_h = h;
    if (!target_fbo) {
      glGenFramebuffers(1, &target_fbo);
      glGenTextures(1, &target_color);
    }
    glBindTexture(GL_TEXTURE_2D, target_color);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindFramebuffer(GL_FRAMEBUFFER, target_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target_color, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("offscreen target framebuffer incomplete");
  }
  if (!desc.offscreen) {
    target_w = w;
    target_h = h;
  }
}

void Renderer::Impl::build_stars(uint64_t seed) {
  // Seeded stars: a few bright ones, many faint, tints from red dwarfs to blue giants.
  const int n = 2600;
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
  lobe_a = glm::vec3(r.unit_vector(uint64_t(n) * 6));
  lobe_b = glm::vec3(r.unit_vector(uint64_t(n) * 6 + 1));
  glBindVertexArray(star_vao);
  glBindBuffer(GL_ARRAY_BUFFER, star_vbo);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * 4), data.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 28, nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 28, reinterpret_cast<void*>(16));
  glBindVertexArray(0);
  star_count = n;
  star_seed = seed;
}

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

void Renderer::Impl::set_sky_uniforms(const Program& p, const glm::mat3& basis, float tan_x, float tan_y) const {
  glUniformMatrix3fv(p.loc("u_cam_basis"), 1, GL_FALSE, glm::value_ptr(basis));
  glUniform2f(p.loc("u_tan_half"), tan_x, tan_y);
  glUniform3fv(p.loc("u_lobe_a"), 1, glm::value_ptr(lobe_a));
  glUniform3fv(p.loc("u_lobe_b"), 1, glm::value_ptr(lobe_b));
  glUniform1f(p.loc("u_seed"), float(star_seed % 1000));
}

// The nebula changes only with the level's seed, so it is rendered once into the six faces of
// a half-float cube map (a face of 256² is 0.35° a texel, the noise's finest feature about 4°)
// and each frame looks it up. Seamless filtering hides the face edges.
void Renderer::Impl::bake_sky() {
  const int n = rs.sky_resolution;
  if (!sky_cube) {
    glGenTextures(1, &sky_cube);
    glGenFramebuffers(1, &sky_fbo);
  }
  glBindTexture(GL_TEXTURE_CUBE_MAP, sky_cube);
  for (int f = 0; f < 6; ++f)
    glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA16F, n, n, 0, GL_RGBA, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  GLint fbo = 0, vp[4];
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
  glGetIntegerv(GL_VIEWPORT, vp);
  glBindFramebuffer(GL_FRAMEBUFFER, sky_fbo);
  glViewport(0, 0, n, n);
  glUseProgram(sky_exact.id);
  glBindVertexArray(empty_vao);
  for (int f = 0; f < 6; ++f) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), sky_cube, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("sky cube map framebuffer incomplete");
    set_sky_uniforms(sky_exact, kCubeFaceBasis[f], 1.0f, 1.0f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(fbo));
  glViewport(vp[0], vp[1], vp[2], vp[3]);
  sky_cube_size = n;
  sky_cube_seed = star_seed;
}

void Renderer::Impl::draw_sky(const RenderView& v, const glm::mat3& cam_basis, const glm::mat4& view_proj, double aspect) {
  if (star_seed != v.starfield_seed) build_stars(v.starfield_seed);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_BLEND);
  if (!rs.sky_exact && (sky_cube_seed != star_seed || sky_cube_size != rs.sky_resolution)) bake_sky();
  const Program& p = rs.sky_exact ? sky_exact : sky;
  glUseProgram(p.id);
  double ty = std::tan(v.camera.fov_y_radians * 0.5);
  set_sky_uniforms(p, cam_basis, float(ty * aspect), float(ty));
  glUniform1i(p.loc("u_sky"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, sky_cube);
  glBindVertexArray(empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glUseProgram(stars.id);
  glUniformMatrix4fv(stars.loc("u_view_proj"), 1, GL_FALSE, glm::value_ptr(view_proj));
  glUniform1f(stars.loc("u_pixel_scale"), float(std::max(1.0, scene_h / 720.0)));
  glBindVertexArray(star_vao);
  glDrawArrays(GL_POINTS, 0, star_count);
  glDisable(GL_PROGRAM_POINT_SIZE);
  glDisable(GL_BLEND);
  stats.draw_calls += 2;
}

void Renderer::Impl::draw_meshes(const RenderView& v, const glm::mat4& view_proj) {
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(rs.reversed_z ? GL_GREATER : GL_LESS);
  glDisable(GL_CULL_FACE);
  glUseProgram(mesh.id);
  glUniformMatrix4fv(mesh.loc("u_view_proj"), 1, GL_FALSE, glm::value_ptr(view_proj));
  glm::vec3 ld = glm::length(v.light_direction) > 0 ? glm::normalize(v.light_direction) : glm::vec3(0, -1, 0);
  glUniform3fv(mesh.loc("u_light_dir"), 1, glm::value_ptr(ld));
  glUniform3fv(mesh.loc("u_light_color"), 1, glm::value_ptr(v.light_color));
  glUniform3fv(mesh.loc("u_ambient"), 1, glm::value_ptr(v.ambient));
  glUniform1i(mesh.loc("u_base_tex"), 0);
  glUniform1i(mesh.loc("u_emissive_tex"), 1);
  for (const MeshInstance& inst : v.meshes) {
    if (inst.model < 0 || inst.model >= int(models.size())) continue;
    const GpuModel& g = models[size_t(inst.model)];
    // Camera-relative: the translation is subtracted in double before the matrix goes to float.
    glm::dvec3 rel = inst.position - v.camera.position;
    glm::dmat3 rot = glm::mat3_cast(inst.orientation) * inst.scale;
    glm::dmat4 model(rot);
    model[3] = glm::dvec4(rel, 1.0);
    glm::mat4 mf(model);
    glm::mat3 nm(glm::mat3_cast(inst.orientation));  // uniform scale: normals just rotate
    glUniformMatrix4fv(mesh.loc("u_model"), 1, GL_FALSE, glm::value_ptr(mf));
    glUniformMatrix3fv(mesh.loc("u_normal_mat"), 1, GL_FALSE, glm::value_ptr(nm));
    glUniform3fv(mesh.loc("u_tint"), 1, glm::value_ptr(inst.tint));
    glUniform1f(mesh.loc("u_emissive_boost"), inst.emissive_boost);
    glUniform3fv(mesh.loc("u_flash"), 1, glm::value_ptr(inst.flash));
    for (const GpuPrimitive& p : g.prims) {
      Material mat;
      if (p.material >= 0 && p.material < int(g.materials.size())) mat = g.materials[size_t(p.material)];
      glUniform4fv(mesh.loc("u_base_color"), 1, glm::value_ptr(mat.base_color));
      glUniform3fv(mesh.loc("u_emissive"), 1, glm::value_ptr(mat.emissive));
      bool has_base = mat.base_color_image >= 0 && mat.base_color_image < int(g.textures.size());
      bool has_em = mat.emissive_image >= 0 && mat.emissive_image < int(g.textures.size());
      glUniform1i(mesh.loc("u_has_base_tex"), has_base);
      glUniform1i(mesh.loc("u_has_emissive_tex"), has_em);
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D, has_base ? g.textures[size_t(mat.base_color_image)] : 0);
      glActiveTexture(GL_TEXTURE1);
      glBindTexture(GL_TEXTURE_2D, has_em ? g.textures[size_t(mat.emissive_image)] : 0);
      glBindVertexArray(p.vao);
      glDrawElements(GL_TRIANGLES, p.count, GL_UNSIGNED_INT, nullptr);
      ++stats.draw_calls;
    }
  }
  glActiveTexture(GL_TEXTURE0);
}

namespace {

// A model-space box under the instance's camera-relative transform as an Occluder; false when
// it lies wholly in front of the near plane or off the screen (tangent half-extents mx, my).
bool project_box(const Box3& box, const glm::dvec3& rel, const glm::dmat3& rot, const glm::mat3& to_view, float near,
                 float mx, float my, Occluder& o) {
  const float inf = std::numeric_limits<float>::infinity();
  o = Occluder::none();
  bool crosses_near = false;
  for (int i = 0; i < 8; ++i) {
    glm::dvec3 corner((i & 1) ? box.hi.x : box.lo.x, (i & 2) ? box.hi.y : box.lo.y, (i & 4) ? box.hi.z : box.lo.z);
    glm::vec3 c = to_view * glm::vec3(rel + rot * corner);
    float d = -c.z;
    o.nearest = std::min(o.nearest, d);
    o.farthest = std::max(o.farthest, d);
    if (d <= near) {
      crosses_near = true;
      continue;
    }
    o.x0 = std::min(o.x0, c.x / d);
    o.x1 = std::max(o.x1, c.x / d);
    o.y0 = std::min(o.y0, c.y / d);
    o.y1 = std::max(o.y1, c.y / d);
  }
  if (!(o.farthest > near)) return false;  // wholly in front of the near plane: it draws nothing
  if (crosses_near) o.x0 = o.y0 = -inf, o.x1 = o.y1 = inf;
  // Only what is on screen can stand behind a particle's pixels.
  if (o.x0 > mx || o.x1 < -mx || o.y0 > my || o.y1 < -my) return false;
  o.x0 = std::max(o.x0, -mx), o.x1 = std::min(o.x1, mx);
  o.y0 = std::max(o.y0, -my), o.y1 = std::min(o.y1, my);
  // Float transforms on the GPU differ from these in the last bits: widen a little.
  o.nearest -= 1e-4f * std::abs(o.nearest) + 1e-5f;
  o.farthest += 1e-4f * std::abs(o.farthest) + 1e-5f;
  return true;
}

}  // namespace

void Renderer::Impl::gather_occluders(const RenderView& v, const glm::mat3& to_view, float tan_x, float tan_y) {
  occluders.clear();
  occluder_groups.clear();
  const float near = float(v.camera.near_plane);
  const float mx = tan_x * 1.01f, my = tan_y * 1.01f;
  occluder_bounds = Occluder::none();
  for (const MeshInstance& inst : v.meshes) {
    if (inst.model < 0 || inst.model >= int(models.size())) continue;
    const GpuModel& g = models[size_t(inst.model)];
    // The same camera-relative transform draw_meshes uses, taken in double before float.
    const glm::dvec3 rel = inst.position - v.camera.position;
    const glm::dmat3 rot = glm::mat3_cast(inst.orientation) * inst.scale;
    OccluderGroup group{Occluder::none(), occluders.size(), 0};
    Occluder o;
    for (const Box3& part : g.parts) {
      if (!project_box(part, rel, rot, to_view, near, mx, my, o)) continue;
      occluders.push_back(o);
      group.bound.include(o);
      ++group.count;
    }
    if (group.count == 0) continue;
    occluder_groups.push_back(group);
    occluder_bounds.include(group.bound);
  }
}

// Whether an opaque surface can lie, at some pixel of the particle's quad, less than its depth
// extent E behind the quad, or between the quad and where the density methods push it (E/2 for
// average density, E for density extent, towards the camera). Behind that range every method
// gives exactly 1 (linear and contrast reach 1 at zb − z ≥ E, average density at E/2, density
// extent at E·texture alpha); in front of it the depth test rejects the fragment whatever the
// factor. When no mesh box reaches into the range, the particle can skip the depth read and
// stay bit-identical. With the bounds of QuadBounds: a camera-facing quad is built from
// view-space axes, so it lies at one view depth; an axis-locked quad lies in the plane through
// its centre square to the view ray, so its view depth varies by at most its radius times the
// sine of the ray's angle to the view axis.
bool Renderer::Impl::soft_can_matter(const ParticleInstance& p, const QuadBounds& q, float near) const {
  const glm::vec3& c = q.centre;
  float d = -c.z;
  float extent = p.soft_extent > 0.0f ? p.soft_extent : q.size;
  float dist = glm::length(c);
  float sine = dist > 0.0f ? std::sqrt(std::max(0.0f, 1.0f - (c.z / dist) * (c.z / dist))) : 1.0f;
  float spread = q.axis_locked ? q.radius * std::min(1.0f, sine + 1e-4f) : 0.0f;
  float reach = d + spread + extent * 1.001f;
  uint8_t method = p.soft_edge & ~kSoftClear;
  float push = method == uint8_t(SoftEdge::AverageDensity) ? 0.5f * extent
               : method == uint8_t(SoftEdge::DensityExtent) ? extent
                                                           : 0.0f;
  float front = d - spread - push * 1.001f;
  float z0 = d - spread, z1 = d + spread;
  bool whole_screen = !(z0 > near);
  // The quad's footprint in tangent units; pushing it along the view ray (density methods)
  // keeps the footprint.
  auto lo = [&](float a) { return a < 0.0f ? a / z0 : a / z1; };
  auto hi = [&](float b) { return b < 0.0f ? b / z1 : b / z0; };
  float x0 = whole_screen ? 0.0f : lo(c.x - q.radius), x1 = whole_screen ? 0.0f : hi(c.x + q.radius);
  float y0 = whole_screen ? 0.0f : lo(c.y - q.radius), y1 = whole_screen ? 0.0f : hi(c.y + q.radius);
  auto touches = [&](const Occluder& o) {
    return o.nearest < reach && o.farthest > front &&
           (whole_screen || (o.x0 <= x1 && x0 <= o.x1 && o.y0 <= y1 && y0 <= o.y1));
  };
  if (occluder_groups.empty() || !touches(occluder_bounds)) return false;
  for (const OccluderGroup& g : occluder_groups) {
    if (!touches(g.bound)) continue;
    for (size_t i = g.first; i < g.first + g.count; ++i)
      if (touches(occluders[i])) return true;
  }
  return false;
}

void Renderer::Impl::draw_particles(const RenderView& v, const glm::mat4& view, const glm::mat4& proj, glm::vec2 linearize) {
  auto t0 = std::chrono::steady_clock::now();
  const auto& in = v.particles;
  stats.particles_in = int(in.size());
  glm::vec3 fwd = -glm::vec3(glm::transpose(view)[2]);  // camera −Z in world space
  const glm::mat3 to_view(view);
  const float near = float(v.camera.near_plane);
  // The four side planes of the view frustum in view space, as unit normals pointing out: a
  // particle whose quad lies wholly outside one of them is not uploaded. Clusters are culled
  // whole before this (game/render); this drops the particles of a visible cluster that are off
  // screen, such as the far ends of a long beam, which would cost vertex work and setup.
  const float tx = 1.0f / proj[0][0], ty = 1.0f / proj[1][1];
  gather_occluders(v, to_view, tx, ty);
  const glm::vec3 planes[4] = {glm::normalize(glm::vec3(1, 0, tx)), glm::normalize(glm::vec3(-1, 0, tx)),
                               glm::normalize(glm::vec3(0, 1, ty)), glm::normalize(glm::vec3(0, -1, ty))};
  upload.clear();
  keys.clear();
  bool any_ordered = false;
  for (const ParticleInstance& p : in) {
    bool dark = p.color[0] <= 0 && p.color[1] <= 0 && p.color[2] <= 0 && p.color[3] <= 0;
    float depth = p.pos[0] * fwd.x + p.pos[1] * fwd.y + p.pos[2] * fwd.z;
    float axis_len = std::sqrt(p.axis[0] * p.axis[0] + p.axis[1] * p.axis[1] + p.axis[2] * p.axis[2]);
    float reach = std::max(p.size, 0.0f) + axis_len;
    if (dark || !(depth > -reach)) continue;  // invisible or wholly behind the camera (NaN fails too)
    const QuadBounds b = quad_bounds(p, to_view, axis_len);
    if (glm::dot(planes[0], b.centre) > b.radius || glm::dot(planes[1], b.centre) > b.radius ||
        glm::dot(planes[2], b.centre) > b.radius || glm::dot(planes[3], b.centre) > b.radius) {
      ++stats.culled_offscreen;
      continue;
    }
    ParticleInstance q = p;
    if (rs.soft_override >= 0) q.soft_edge = uint8_t(rs.soft_override);
    if (q.soft_edge != 0 && !soft_can_matter(q, b, near)) q.soft_edge |= kSoftClear;
    any_ordered = any_ordered || q.color[3] * (1.0f - q.burn) > 0.0f;
    upload.push_back(q);
    keys.push_back(sortable_bits(depth));
  }
  stats.particles_drawn = int(upload.size());
  if (upload.empty()) {
    stats.particle_prep_ms = stats.particle_cpu_ms = ms_since(t0);
    return;
  }
  // Pure additive particles need no order; as soon as one is alpha blended, the whole set is
  // ordered, because an additive glow in front of smoke must not be darkened by it.
  if (any_ordered && rs.sorting != RenderSettings::Sorting::Off) {
    if (rs.sorting == RenderSettings::Sorting::Cluster) {
      std::vector<uint32_t> cluster_ids;
      for (auto& p : upload) cluster_ids.push_back(p.cluster);
      std::vector<uint32_t> unique_ids = cluster_ids;
      std::sort(unique_ids.begin(), unique_ids.end());
      unique_ids.erase(std::unique(unique_ids.begin(), unique_ids.end()), unique_ids.end());
      std::vector<double> sum(unique_ids.size(), 0.0);
      std::vector<int> cnt(unique_ids.size(), 0);
      std::vector<uint32_t> slot(upload.size());
      for (size_t i = 0; i < upload.size(); ++i) {
        slot[i] = uint32_t(std::lower_bound(unique_ids.begin(), unique_ids.end(), cluster_ids[i]) - unique_ids.begin());
        const float* pp = upload[i].pos;
        sum[slot[i]] += pp[0] * fwd.x + pp[1] * fwd.y + pp[2] * fwd.z;
        ++cnt[slot[i]];
      }
      for (size_t i = 0; i < upload.size(); ++i) keys[i] = sortable_bits(float(sum[slot[i]] / cnt[slot[i]]));
    }
    radix_sort_back_to_front(keys, order);
    std::vector<ParticleInstance> sorted(upload.size());
    for (size_t i = 0; i < order.size(); ++i) sorted[i] = upload[order[i]];
    upload.swap(sorted);
    stats.sorted = int(upload.size());
  }

  // A buffer texture reaches GL_MAX_TEXTURE_BUFFER_SIZE texels (at least 65536, so 16384
  // particles; 2^27 on llvmpipe and desktop GPUs): beyond that the nearest ones are kept when
  // sorted (the order is back to front), an arbitrary subset otherwise.
  if (upload.size() > max_particles_per_draw) {
    stats.over_draw_limit = int(upload.size() - max_particles_per_draw);
    upload.erase(upload.begin(), upload.begin() + std::ptrdiff_t(upload.size() - max_particles_per_draw));
  }
  // Which program and whether the depth copy is needed, from the particles that are drawn.
  bool any_soft = false, any_contrast = false;
  for (const ParticleInstance& q : upload) {
    const bool soft = q.soft_edge != 0 && !(q.soft_edge & kSoftClear);
    stats.soft_shaded += soft;
    any_soft = any_soft || soft;
    any_contrast = any_contrast || (soft && q.soft_edge == uint8_t(SoftEdge::Contrast));
  }
  stats.particle_prep_ms = ms_since(t0);
  glBindBuffer(GL_TEXTURE_BUFFER, particle_vbo);
  size_t bytes = upload.size() * sizeof(ParticleInstance);
  if (bytes > particle_capacity) particle_capacity = bytes * 3 / 2;
  glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(particle_capacity), nullptr, GL_STREAM_DRAW);  // new or orphaned
  glBufferSubData(GL_TEXTURE_BUFFER, 0, GLsizeiptr(bytes), upload.data());
  glBindVertexArray(particle_vao);
  if (upload.size() > index_capacity) {
    index_capacity = std::max<size_t>(upload.size() * 3 / 2, 1024);
    std::vector<uint32_t> indices(index_capacity * 6);
    for (size_t i = 0; i < index_capacity; ++i) {
      const uint32_t b = uint32_t(i * 4);
      const uint32_t quad[6] = {b, b + 1, b + 2, b + 2, b + 1, b + 3};
      std::copy(quad, quad + 6, indices.begin() + std::ptrdiff_t(i * 6));
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, particle_ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * 4), indices.data(), GL_STATIC_DRAW);
  }

  const bool timing = timer_query && !time_passes && !query_pending[size_t(query_index)];
  if (timing) glBeginQuery(GL_TIME_ELAPSED, queries[size_t(query_index)]);
  begin_pass_timer();

  if (any_soft) {
    // This frame's depth, never last frame's (Ribeiro: a stale copy flickers as the camera moves).
    glBindFramebuffer(GL_READ_FRAMEBUFFER, scene_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, copy_fbo);
    glBlitFramebuffer(0, 0, scene_w, scene_h, 0, 0, scene_w, scene_h, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, scene_fbo);
    stats.depth_copied = true;
  }
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(rs.reversed_z ? GL_GREATER : GL_LESS);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  // Contrast power 2 (the default) squares instead of calling pow(); power 1 is the identity
  // curve, the plain soft program.
  const Program& particle = !any_soft                        ? particle_hard
                            : !any_contrast                  ? particle_soft
                            : rs.contrast_power == 2.0f      ? particle_square
                            : rs.contrast_power == 1.0f      ? particle_soft
                                                             : particle_contrast;
  glUseProgram(particle.id);
  glUniformMatrix4fv(particle.loc("u_view"), 1, GL_FALSE, glm::value_ptr(view));
  glUniformMatrix4fv(particle.loc("u_proj"), 1, GL_FALSE, glm::value_ptr(proj));
  glUniform1f(particle.loc("u_tan_half_y"), float(std::tan(v.camera.fov_y_radians * 0.5)));
  glUniform1f(particle.loc("u_size_clamp"), rs.size_clamp);
  glUniform1f(particle.loc("u_near"), float(v.camera.near_plane));
  glUniform1f(particle.loc("u_inv_near_fade"), rs.near_fade > 0.0f ? 1.0f / rs.near_fade : 1e30f);
  glUniform1f(particle.loc("u_contrast_power"), rs.contrast_power);
  // view depth = x / (y·depth + z) with the denominator's sign made positive in every mode
  // (standard depth has depth + B ≤ 0), so the shader guards it with one max().
  float lsign = linearize.x >= 0.0f ? 1.0f : -1.0f;
  glUniform3f(particle.loc("u_linearize"), lsign * linearize.x, lsign, lsign * linearize.y);
  glUniform2f(particle.loc("u_sprite_texels"), float(sprite_w), float(sprite_h));
  glUniform1f(particle.loc("u_viewport_h"), float(scene_h));
  glUniform1i(particle.loc("u_sprites"), 0);
  glUniform1i(particle.loc("u_scene_depth"), 1);
  glUniform1i(particle.loc("u_particles"), 2);
  glUniform2f(particle.loc("u_inv_depth_size"), 1.0f / float(scene_w), 1.0f / float(scene_h));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D_ARRAY, sprite_tex);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, copy_depth);
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_BUFFER, particle_tbo);
  glActiveTexture(GL_TEXTURE0);
  glBindVertexArray(particle_vao);
  if (count_fragments) {
    if (!fragment_query) glGenQueries(1, &fragment_query);
    glBeginQuery(GL_SAMPLES_PASSED, fragment_query);
  }
  glDrawElements(GL_TRIANGLES, GLsizei(upload.size() * 6), GL_UNSIGNED_INT, nullptr);
  if (count_fragments) {
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint64 samples = 0;
    glGetQueryObjectui64v(fragment_query, GL_QUERY_RESULT, &samples);
    stats.particle_fragments = static_cast<long long>(samples);
  }
  ++stats.draw_calls;
  ++stats.particle_draw_calls;
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  stats.particle_pass_gpu_ms = end_pass_timer();
  if (timing) {
    glEndQuery(GL_TIME_ELAPSED);
    query_pending[size_t(query_index)] = true;
  }
  stats.particle_cpu_ms = ms_since(t0);
}

void Renderer::Impl::draw_hud(const HudLayer& hud, int w, int h) {
  std::vector<HudVertex> verts;
  font.build(hud, verts);
  if (verts.empty()) return;
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glUseProgram(this->hud.id);
  glUniform2f(this->hud.loc("u_viewport"), float(w), float(h));
  glUniform1i(this->hud.loc("u_font"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, font_tex);
  glBindVertexArray(hud_vao);
  glBindBuffer(GL_ARRAY_BUFFER, hud_vbo);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(verts.size() * sizeof(HudVertex)), verts.data(), GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(verts.size()));
  ++stats.draw_calls;
  glDisable(GL_BLEND);
}

void Renderer::render(const RenderView& v, int width, int height) {
  Impl& m = *impl_;
  if (width <= 0 || height <= 0) throw std::invalid_argument("render: width and height must be positive");
  m.stats = FrameStats{};
  // Collect the oldest finished timer query so reading it never stalls.
  if (m.timer_query) {
    for (size_t i = 0; i < m.queries.size(); ++i) {
      if (!m.query_pending[i]) continue;
      GLint ready = 0;
      glGetQueryObjectiv(m.queries[i], GL_QUERY_RESULT_AVAILABLE, &ready);
      if (ready) {
        GLuint64 ns = 0;
        glGetQueryObjectui64v(m.queries[i], GL_QUERY_RESULT, &ns);
        m.last_gpu_ms = double(ns) * 1e-6;
        m.query_pending[i] = false;
      }
    }
    m.query_index = (m.query_index + 1) % int(m.queries.size());
  }
  m.ensure_targets(width, height);

  const CameraView& cam = v.camera;
  double aspect = double(m.scene_w) / double(m.scene_h);
  double n = std::max(cam.near_plane, 1e-6);
  double f = std::max(cam.far_plane, n * 1.0001);
  double ty = std::tan(std::clamp(cam.fov_y_radians, 1e-3, 3.1) * 0.5);
  glm::dmat4 proj(0.0);
  proj[0][0] = 1.0 / (ty * aspect);
  proj[1][1] = 1.0 / ty;
  proj[2][3] = -1.0;
  glm::vec2 linearize;
  if (m.rs.reversed_z) {
    // depth = A/d + B with depth(n) = 1 and depth(far) = 0; infinite: A = n, B = 0.
    double A = m.rs.infinite_far ? n : n * f / (f - n);
    double B = m.rs.infinite_far ? 0.0 : -n / (f - n);
    proj[2][2] = -B;
    proj[3][2] = A;
    linearize = glm::vec2(float(A), float(-B));
  } else if (m.rs.infinite_far) {
    proj[2][2] = -1.0;
    proj[3][2] = -2.0 * n;
    linearize = glm::vec2(float(-n), -1.0f);  // window depth = 1 − n/d
  } else {
    proj[2][2] = -(f + n) / (f - n);
    proj[3][2] = -2.0 * f * n / (f - n);
    linearize = glm::vec2(float(-n * f / (f - n)), float(-f / (f - n)));
  }
  glm::dmat3 cam_rot = glm::mat3_cast(cam.orientation);
  glm::dmat4 view(glm::transpose(cam_rot));  // rotation only: the camera is the origin
  glm::mat4 viewf(view), projf(proj);
  glm::mat4 view_proj = projf * viewf;
  m.last_view_proj = view_proj;

  if (m.clip_control) glClipControl(GL_LOWER_LEFT, m.rs.reversed_z ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
  glBindFramebuffer(GL_FRAMEBUFFER, m.scene_fbo);
  glViewport(0, 0, m.scene_w, m.scene_h);
  glDepthMask(GL_TRUE);
  glClearColor(0, 0, 0, 1);
  glClearDepth(m.rs.reversed_z ? 0.0 : 1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  m.draw_sky(v, glm::mat3(cam_rot), view_proj, aspect);
  m.draw_meshes(v, view_proj);
  m.draw_particles(v, viewf, projf, linearize);

  GLuint dst = m.desc.offscreen ? m.target_fbo : 0;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m.scene_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, dst);
  glBlitFramebuffer(0, 0, m.scene_w, m.scene_h, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                    (m.scene_w == width && m.scene_h == height) ? GL_NEAREST : GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, dst);
  glViewport(0, 0, width, height);
  m.draw_hud(v.hud, width, height);
  m.stats.particle_gpu_ms = m.last_gpu_ms;
}

Image Renderer::read_pixels() {
  Impl& m = *impl_;
  if (!m.desc.offscreen || !m.target_fbo) throw std::logic_error("read_pixels needs an offscreen renderer that has rendered");
  Image img;
  img.width = m.target_w;
  img.height = m.target_h;
  img.rgba.resize(size_t(img.width) * img.height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m.target_fbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  flip_rows(img);
  return img;
}

std::vector<float> Renderer::read_pixels_float() {
  Impl& m = *impl_;
  if (!m.scene_fbo) throw std::logic_error("read_pixels_float before any render");
  std::vector<float> px(size_t(m.scene_w) * m.scene_h * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m.scene_fbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, m.scene_w, m.scene_h, GL_RGBA, GL_FLOAT, px.data());
  std::vector<float> out(px.size());
  size_t row = size_t(m.scene_w) * 4;
  for (int y = 0; y < m.scene_h; ++y)
    std::memcpy(&out[size_t(y) * row], &px[size_t(m.scene_h - 1 - y) * row], row * 4);
  return out;
}

FrameStats Renderer::last_stats() const { return impl_->stats; }

std::string Renderer::reload() {
  try {
    impl_->load_programs(false);
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

void Renderer::Impl::begin_pass_timer() {
  if (!time_passes || !timer_query) return;
  if (!pass_query) glGenQueries(1, &pass_query);
  glBeginQuery(GL_TIME_ELAPSED, pass_query);
}

double Renderer::Impl::end_pass_timer() {
  if (!time_passes || !timer_query) return -1.0;
  glEndQuery(GL_TIME_ELAPSED);
  GLuint64 ns = 0;
  glGetQueryObjectui64v(pass_query, GL_QUERY_RESULT, &ns);
  return double(ns) * 1e-6;
}

double Renderer::draw_fill_reference(int count) {
  Impl& m = *impl_;
  if (!m.scene_fbo) throw std::logic_error("draw_fill_reference before any render");
  HudLayer layer;
  for (int i = 0; i < count; ++i)
    layer.quads.push_back({0, 0, float(m.scene_w), float(m.scene_h), glm::vec4(0.02f, 0.01f, 0.005f, 0.05f)});
  glBindFramebuffer(GL_FRAMEBUFFER, m.scene_fbo);
  glViewport(0, 0, m.scene_w, m.scene_h);
  m.begin_pass_timer();
  m.draw_hud(layer, m.scene_w, m.scene_h);
  return m.end_pass_timer();
}

void Renderer::finish() { glFinish(); }

void Renderer::count_particle_fragments(bool on) { impl_->count_fragments = on; }

void Renderer::time_gpu_passes(bool on) { impl_->time_passes = on; }

}  // namespace arc
