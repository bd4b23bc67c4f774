// assets/model.h — glTF models as plain CPU data (no GL); images are in assets/image.h.
//
// load_model() reads .gltf or .glb through tinygltf: positions, normals, UVs, indices of any
// component type, base-colour factor and texture, emissive factor (and texture), metallic and
// roughness factors, the share of a material that takes a ship's team colour
// (extras.arcfire_team_color), with node transforms baked into the vertices. Every failure throws arc::InputError("path: what is wrong").
//
// Details of load_model: the default scene (or every root node when the file has no scenes) is
// walked with TRS or matrix node transforms; primitives must be triangles, indexed by
// u8/u16/u32 or not indexed at all; a primitive without normals is split into flat-shaded
// triangles; KHR_materials_emissive_strength scales the emissive factor. Every accessor and
// bufferView range is checked against its buffer before a byte is read, and a .glb container is
// checked before tinygltf sees it. Textures are decoded through OpenImageIO like load_image().
//
// Example, compiled as AssetExamples.LoadAModel in tests/unit/assets/test_asset_examples.cpp:
//   arc::ModelData ship = arc::load_model("assets/models/viper.glb");
#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "assets/image.h"

namespace arc {

struct Material {
  glm::vec4 base_color{1.0f};
  glm::vec3 emissive{0.0f};
  // glTF metallicFactor and roughnessFactor (a file without them reads glTF's defaults, 1 and
  // 1); the mesh shader's specular colour and highlight size. Made in code: matte, non-metal.
  float metallic = 0.0f;
  float roughness = 1.0f;
  int base_color_image = -1;  // index into ModelData::images, -1 = none
  int emissive_image = -1;
  // extras.arcfire_team_color: how much this material takes the team colour of the ship that
  // wears it (albedo, and the emissive's hue); 0 for every material of other models.
  float team_color = 0.0f;
};

struct MeshPrimitive {
  std::vector<glm::vec3> positions;  // model space, node transforms applied
  std::vector<glm::vec3> normals;    // same count as positions (generated flat if the file has none)
  std::vector<glm::vec2> uvs;        // empty or same count as positions
  std::vector<uint32_t> indices;     // triangles
  int material = -1;                 // index into ModelData::materials, -1 = default
};

struct ModelData {
  std::string path;
  std::vector<MeshPrimitive> primitives;
  std::vector<Material> materials;
  std::vector<Image> images;
  glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};
  float radius = 0.0f;  // bounding sphere around the model origin
};

ModelData load_model(const std::string& path);
// The same from the file's bytes; `path` names it in messages and picks .glb or .gltf (fuzz targets).
ModelData parse_model(const std::string& bytes, const std::string& path);

}  // namespace arc
