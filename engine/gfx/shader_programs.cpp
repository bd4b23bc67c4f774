// gfx/shader_programs.cpp — compiling and linking the shader folder, all or nothing.
#include "gfx/shader_programs.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/data_layers.h"
#include "core/input_file.h"
#include "core/input_limits.h"
#include "gfx/gl_features.h"

namespace arc {
namespace {

std::string read_text(const std::string& path) { return read_input_file(path, kMaxShaderFileBytes, "a shader"); }

// The compiler's or linker's log of a shader or program that failed.
std::string info_log(GLuint id, bool is_program) {
  char log[4096];
  if (is_program)
    glGetProgramInfoLog(id, sizeof log, nullptr, log);
  else
    glGetShaderInfoLog(id, sizeof log, nullptr, log);
  return log;
}

GLuint compile(GLenum type, const std::string& src, const std::string& name, std::string& err) {
  GLuint sh = glCreateShader(type);
  const char* p = src.c_str();
  glShaderSource(sh, 1, &p, nullptr);
  glCompileShader(sh);
  GLint ok = 0;
  glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
  if (ok) return sh;
  err += name + ": " + info_log(sh, false);
  glDeleteShader(sh);
  return 0;
}

// `defines` right after the #version line (the first line), where GLSL allows them.
void insert_defines(std::string& src, const std::string& defines) {
  if (defines.empty()) return;
  size_t eol = src.find('\n');
  src.insert(eol == std::string::npos ? src.size() : eol + 1, defines);
}

// Builds vert+frag from the shader folder; returns 0 and appends to err on failure.
// `vdefines` go into the vertex shader, `defines` into the fragment shader.
GLuint build_program(const std::string& dir, const std::string& vs, const std::string& fs, const std::string& defines,
                     const std::string& vdefines, std::string& err) {
  std::string vsrc, fsrc;
  try {
    vsrc = read_text(data_file(dir, vs));
    fsrc = read_text(data_file(dir, fs));
  } catch (const std::exception& e) {
    err += std::string(e.what()) + "\n";
    return 0;
  }
  insert_defines(vsrc, vdefines);
  insert_defines(fsrc, defines);
  GLuint v = compile(GL_VERTEX_SHADER, vsrc, data_file(dir, vs), err);
  GLuint f = compile(GL_FRAGMENT_SHADER, fsrc, data_file(dir, fs), err);
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
  if (ok) return prog;
  err += vs + "+" + fs + " link: " + info_log(prog, true);
  glDeleteProgram(prog);
  return 0;
}

}  // namespace

ShaderPrograms::ShaderPrograms(std::string shader_dir) : dir_(std::move(shader_dir)) {
  try {
    build_all();
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("shader build failed: ") + e.what());
  }
}

ShaderPrograms::~ShaderPrograms() {
  for (Program* p : {&sky, &sky_exact, &sky_grid, &sky_corners, &sky_cells, &stars, &mesh, &hud, &particle_hard,
                     &bloom_prefilter, &bloom_down_karis, &bloom_down, &bloom_up, &tonemap, &tonemap_bloom, &fxaa,
                     &msaa_resolve, &particle_composite})
    glDeleteProgram(p->id);
  glDeleteProgram(particle_hard_indexed.id);
  for (auto* set : {&particle_soft, &particle_soft_indexed})
    for (auto& curve : *set)
      for (auto& density : curve)
        for (Program& p : density) glDeleteProgram(p.id);
}

bool ShaderPrograms::has_indexed() const { return indexed_; }

void ShaderPrograms::build_indexed() {
  if (indexed_) return;
  std::vector<Spec> specs;
  add_particle_specs(specs, true);
  try {
    build_specs(specs);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("shader build failed: ") + e.what());
  }
  indexed_ = true;
}

std::string ShaderPrograms::reload() {
  try {
    build_all();
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

// The particle programs: hard edges and each soft variant, every curve with and without
// density extent's texture-alpha range, reading the depth from a copy and, where the context
// can, from the framebuffer; with `indexed`, the vertex shader's INDEXED variant of each.
void ShaderPrograms::add_particle_specs(std::vector<Spec>& specs, bool indexed) {
  const std::string vdefines = indexed ? "#define INDEXED 1\n" : "#define INDEXED 0\n";
  specs.push_back({indexed ? &particle_hard_indexed : &particle_hard, "particle.vert", "particle.frag",
                   "#define SOFT 0\n#define CONTRAST 0\n#define CONTRAST_SQUARE 0\n#define DENSITY_EXTENT 0\n#define FB_DEPTH 0\n",
                   vdefines});
  const char* curves[3] = {"#define CONTRAST 0\n#define CONTRAST_SQUARE 0\n",
                           "#define CONTRAST 1\n#define CONTRAST_SQUARE 0\n",
                           "#define CONTRAST 1\n#define CONTRAST_SQUARE 1\n"};
  auto& soft = indexed ? particle_soft_indexed : particle_soft;
  for (int curve = 0; curve < 3; ++curve)
    for (int density = 0; density < 2; ++density)
      for (int fetch = 0; fetch < 2; ++fetch) {
        if (fetch && !has_depth_fetch()) continue;
        specs.push_back({&soft[curve][density][fetch], "particle.vert", "particle.frag",
                         std::string("#define SOFT 1\n") + curves[curve] + "#define DENSITY_EXTENT " +
                             char('0' + density) + "\n#define FB_DEPTH " + char('0' + fetch) + "\n",
                         vdefines});
      }
}

// All of `specs` or none: on any error the built ones are deleted, the old ones kept, and the
// compiler's text thrown.
void ShaderPrograms::build_specs(const std::vector<Spec>& specs) {
  std::string err;
  std::vector<GLuint> built;
  for (auto& s : specs) built.push_back(build_program(dir_, s.vs, s.fs, s.defines, s.vdefines, err));
  bool all = std::all_of(built.begin(), built.end(), [](GLuint id) { return id != 0; });
  if (!all) {
    for (GLuint id : built)
      if (id) glDeleteProgram(id);
    throw std::runtime_error(err);
  }
  for (size_t i = 0; i < built.size(); ++i) {
    if (specs[i].p->id) glDeleteProgram(specs[i].p->id);
    specs[i].p->id = built[i];
  }
}

void ShaderPrograms::build_all() {
  std::vector<Spec> specs = {
      {&sky, "sky.vert", "sky.frag", ""},
      {&sky_exact, "sky.vert", "sky_exact.frag", ""},
      {&sky_grid, "sky_grid.vert", "sky_grid.frag", ""},
      {&sky_corners, "post.vert", "sky_corners.frag", ""},
      {&sky_cells, "sky_cells.vert", "sky_cells.frag", ""},
      {&stars, "stars.vert", "stars.frag", ""},
      {&mesh, "mesh.vert", "mesh.frag", ""},
      {&hud, "hud.vert", "hud.frag", ""},
      {&bloom_prefilter, "post.vert", "bloom_down.frag", "#define PREFILTER 1\n#define KARIS 0\n"},
      {&bloom_down_karis, "post.vert", "bloom_down.frag", "#define PREFILTER 0\n#define KARIS 1\n"},
      {&bloom_down, "post.vert", "bloom_down.frag", "#define PREFILTER 0\n#define KARIS 0\n"},
      {&bloom_up, "post.vert", "bloom_up.frag", ""},
      {&tonemap, "post.vert", "tonemap.frag", "#define BLOOM 0\n"},
      {&tonemap_bloom, "post.vert", "tonemap.frag", "#define BLOOM 1\n"},
      {&fxaa, "post.vert", "fxaa.frag", ""},
      {&msaa_resolve, "post.vert", "msaa_resolve.frag", ""},
      {&particle_composite, "particle_composite.vert", "particle_composite.frag", ""}};
  add_particle_specs(specs, false);
  // The indexed set is rebuilt with the rest once a per-cluster frame has asked for it.
  if (indexed_) add_particle_specs(specs, true);
  build_specs(specs);
  ++generation_;
}

}  // namespace arc
