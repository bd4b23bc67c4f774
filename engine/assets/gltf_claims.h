// assets/gltf_claims.h — what a glTF file claims to be, and where its nodes place vertices.
//
// A file that says it is glTF 1.0, needs a version the loader does not know (asset.minVersion)
// or requires an extension the loader does not implement (Draco or meshopt compression, ...)
// would load as something else, or as nothing, without a word. Its JSON is scanned once,
// without building a tree, for asset.version, asset.minVersion and extensionsRequired, and
// such a file is one InputError naming what it claims and what is allowed.
//
// Its nodes' transforms are multiplied in double from the root; the product must stay a float
// transform (two nested nodes scaled 1e30 are finite in the file and infinite on the GPU), and
// the vertices it places must stay within ±1e9 m.
//
// Example, compiled as AssetExamples.CheckGltfClaims in tests/unit/assets/test_asset_examples.cpp:
//   check_gltf_claims(json_text.data(), json_text.size(), "ship.gltf");  // throws InputError
#pragma once
#include <cstddef>
#include <string>
#include <vector>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace arc {

// The extensions a file may list in extensionsRequired: the ones model.cpp implements.
const std::vector<std::string>& gltf_supported_extensions();

// Throws InputError "path: asset.version '1.0' is not glTF 2.x; allowed: ..." and the like.
void check_gltf_claims(const char* json, size_t size, const std::string& path);

// Placed vertices: no model is larger than a level's space (about ±1e9 m), so the squared
// distances in a model's float bounds and radius stay finite.
constexpr double kMaxModelExtent = 1.0e9;

// Throws InputError "WHERE overflows the transform composed from the root ..." when an entry of
// `world` is not finite or beyond single precision; `where` names the file, node and property.
void check_gltf_world_transform(const glm::dmat4& world, const std::string& where);
// Throws InputError "WHERE: places a vertex at 1e+30 m; allowed: ..." beyond kMaxModelExtent.
void check_gltf_placed_vertices(const std::vector<glm::vec3>& positions, const std::string& where);

}  // namespace arc
