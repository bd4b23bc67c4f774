// gfx/mesh_pass.h — glTF models on the GPU and the opaque pass that draws them.
//
// add_model() uploads a ModelData (vertices, indices, textures with mipmaps) and keeps its
// cover boxes (cover_boxes.h) for the particle batch's soft-edge reach test. draw() renders
// every MeshInstance of a view with depth test and write on: directional light with specular
// highlights from each material's metallic and roughness factors, ambient and a fill light, a
// Fresnel rim that outlines silhouettes, emissive, tint, flash and the team colour of the
// materials that take it (albedo textures multiply it as detail), each placed
// camera-relative (the translation subtracted in double).
//
// Example, compiled as GlExamples.MeshPass in tests/unit/gfx/test_gl_examples.cpp:
//   MeshPass meshes;
//   int ship = meshes.add_model(load_model("assets/models/viper.glb"), settings.filter);
//   int draw_calls = meshes.draw(view, programs.mesh, vp.view_proj, settings.reversed_z, settings.hdr);
#pragma once
#include <epoxy/gl.h>

#include <vector>

#include <glm/mat4x4.hpp>

#include "assets/model.h"
#include "gfx/cover_boxes.h"
#include "gfx/render_settings.h"
#include "gfx/render_view.h"
#include "gfx/shader_programs.h"

namespace arc {

class MeshPass {
 public:
  MeshPass() = default;
  ~MeshPass();
  MeshPass(const MeshPass&) = delete;
  MeshPass& operator=(const MeshPass&) = delete;

  // Returns the model's position in the table (MeshInstance::model.index()).
  int add_model(const ModelData& model, RenderSettings::Filter filter);
  void set_texture_filter(RenderSettings::Filter filter);  // for every model texture
  // Draws into the bound framebuffer; instances of unknown models are skipped. Returns the
  // draw calls (one per primitive). `linear` (HDR): textures, material and team colours are
  // decoded from sRGB to linear light.
  int draw(const RenderView& view, const Program& mesh, const glm::mat4& view_proj, bool reversed_z,
           bool linear = false) const;
  const ModelCoverBoxes& cover_boxes() const { return boxes_; }

 private:
  struct GpuPrimitive {
    GLuint vao = 0, vbo = 0, ibo = 0;
    GLsizei count = 0;
    int material = -1;
  };
  struct GpuModel {
    std::vector<GpuPrimitive> prims;
    std::vector<Material> materials;
    std::vector<GLuint> textures;         // RGBA8, as stored
    std::vector<GLuint> textures_linear;  // the same images as GL_SRGB8_ALPHA8
  };
  static GpuPrimitive upload_primitive(const MeshPrimitive& prim);
  std::vector<GpuModel> models_;
  ModelCoverBoxes boxes_;  // up to eight boxes per model that hold its triangles
};

}  // namespace arc
