// gfx/mesh_pass.cpp — model upload and the lit opaque draw (shaders/mesh.frag: key light with
// a normalised highlight from the material's roughness, ambient and fill, a Fresnel rim).
#include "gfx/mesh_pass.h"

#include <cstddef>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>

#include "gfx/color_space.h"
#include "gfx/texture_filter.h"

namespace arc {

MeshPass::~MeshPass() {
  for (auto& model : models_) {
    for (auto& p : model.prims) {
      glDeleteVertexArrays(1, &p.vao);
      glDeleteBuffers(1, &p.vbo);
      glDeleteBuffers(1, &p.ibo);
    }
    if (!model.textures.empty()) glDeleteTextures(GLsizei(model.textures.size()), model.textures.data());
    if (!model.textures_linear.empty())
      glDeleteTextures(GLsizei(model.textures_linear.size()), model.textures_linear.data());
  }
}

int MeshPass::add_model(const ModelData& model, RenderSettings::Filter filter) {
  GpuModel g;
  g.materials = model.materials;
  // Each image twice: as stored for the 8-bit scene, and as GL_SRGB8_ALPHA8 for HDR, whose
  // sampler decodes base colour and emissive (sRGB in glTF) to linear before filtering.
  for (const Image& img : model.images)
    for (bool linear : {false, true}) {
      GLuint t = 0;
      glGenTextures(1, &t);
      glBindTexture(GL_TEXTURE_2D, t);
      glTexImage2D(GL_TEXTURE_2D, 0, linear ? GL_SRGB8_ALPHA8 : GL_RGBA8, img.width, img.height, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, img.rgba.data());
      glGenerateMipmap(GL_TEXTURE_2D);
      apply_texture_filter(GL_TEXTURE_2D, filter);
      (linear ? g.textures_linear : g.textures).push_back(t);
    }
  for (const MeshPrimitive& prim : model.primitives) g.prims.push_back(upload_primitive(prim));
  models_.push_back(std::move(g));
  boxes_.push_back(arc::cover_boxes(model.primitives, 3));
  return int(models_.size()) - 1;
}

MeshPass::GpuPrimitive MeshPass::upload_primitive(const MeshPrimitive& prim) {
  struct Vertex {
    glm::vec3 p, n;
    glm::vec2 uv;
  };
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
  return gp;
}

void MeshPass::set_texture_filter(RenderSettings::Filter filter) {
  for (auto& model : models_)
    for (const auto* textures : {&model.textures, &model.textures_linear})
      for (GLuint t : *textures) {
        glBindTexture(GL_TEXTURE_2D, t);
        apply_texture_filter(GL_TEXTURE_2D, filter);
      }
}

int MeshPass::draw(const RenderView& v, const Program& mesh, const glm::mat4& view_proj, bool reversed_z,
                   bool linear) const {
  // Colours picked on screen are decoded for the linear scene; light and scale factors are not.
  auto color = [linear](glm::vec3 c) { return linear ? srgb_to_linear(c) : c; };
  int draw_calls = 0;
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  // Standard depth keeps equal depths: a float buffer rounds 1 − near/d to exactly 1 (the clear
  // value) beyond about near × 1.7e7 (8e6 m at near 0.5), where GL_LESS would drop whole ships.
  glDepthFunc(reversed_z ? GL_GREATER : GL_LEQUAL);
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
    if (!inst.model || inst.model.index() >= models_.size()) continue;
    const GpuModel& g = models_[inst.model.index()];
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
    glUniform3fv(mesh.loc("u_team_color"), 1, glm::value_ptr(color(glm::vec3(inst.team_color))));
    for (const GpuPrimitive& p : g.prims) {
      Material mat;
      if (p.material >= 0 && p.material < int(g.materials.size())) mat = g.materials[size_t(p.material)];
      const glm::vec4 base_color(color(glm::vec3(mat.base_color)), mat.base_color.a);
      glUniform4fv(mesh.loc("u_base_color"), 1, glm::value_ptr(base_color));
      glUniform3fv(mesh.loc("u_emissive"), 1, glm::value_ptr(color(mat.emissive)));
      glUniform1f(mesh.loc("u_metallic"), mat.metallic);
      glUniform1f(mesh.loc("u_roughness"), mat.roughness);
      glUniform1f(mesh.loc("u_team_mask"), mat.team_color * inst.team_color.a);
      bool has_base = mat.base_color_image >= 0 && mat.base_color_image < int(g.textures.size());
      bool has_em = mat.emissive_image >= 0 && mat.emissive_image < int(g.textures.size());
      glUniform1i(mesh.loc("u_has_base_tex"), has_base);
      glUniform1i(mesh.loc("u_has_emissive_tex"), has_em);
      const std::vector<GLuint>& textures = linear ? g.textures_linear : g.textures;
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D, has_base ? textures[size_t(mat.base_color_image)] : 0);
      glActiveTexture(GL_TEXTURE1);
      glBindTexture(GL_TEXTURE_2D, has_em ? textures[size_t(mat.emissive_image)] : 0);
      glBindVertexArray(p.vao);
      glDrawElements(GL_TRIANGLES, p.count, GL_UNSIGNED_INT, nullptr);
      ++draw_calls;
    }
  }
  glActiveTexture(GL_TEXTURE0);
  return draw_calls;
}

}  // namespace arc
