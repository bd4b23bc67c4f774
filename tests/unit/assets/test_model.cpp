// glTF loading: the generated models, and a hand-made file with u8/u16/u32 indices, a
// non-indexed primitive and a node hierarchy with TRS and matrix transforms.
#include <cmath>
#include <cstring>
#include <string>
#include <vector>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include "assets/model.h"
#include "core/error.h"
#include "test_util.h"

namespace arc {
namespace {

size_t triangle_count(const ModelData& m) {
  size_t n = 0;
  for (const auto& p : m.primitives) n += p.indices.size() / 3;
  return n;
}

void expect_well_formed(const ModelData& m) {
  for (const auto& p : m.primitives) {
    ASSERT_EQ(p.normals.size(), p.positions.size());
    for (const auto& n : p.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-4f);
    for (uint32_t i : p.indices) EXPECT_LT(i, p.positions.size());
    EXPECT_EQ(p.indices.size() % 3, 0u);
  }
}

struct ShipCase {
  const char* file;
  float min_length, max_length;
};

class GeneratedShip : public ::testing::TestWithParam<ShipCase> {};

TEST_P(GeneratedShip, LoadsAsAWellFormedShipFacingMinusZ) {
  const ModelData m = load_model(GetParam().file);
  EXPECT_GT(triangle_count(m), 100u);
  EXPECT_LT(triangle_count(m), 2000u);
  expect_well_formed(m);
  const glm::vec3 size = m.bounds_max - m.bounds_min;
  EXPECT_GE(size.z, GetParam().min_length);
  EXPECT_LE(size.z, GetParam().max_length);
  EXPECT_GT(size.z, size.y);  // longer than tall
  EXPECT_LT(m.bounds_min.z, 0.0f);
  EXPECT_GT(m.bounds_max.z, 0.0f);
  EXPECT_GE(m.radius, 0.5f * size.z);
  EXPECT_LE(m.radius, glm::length(size));
  ASSERT_GE(m.materials.size(), 2u);
  // The glowing parts (nozzles, canopy, running lights) exist, and on balance sit behind the
  // nose: the ship faces −Z with its engines at the back.
  float nose_z = 0.0f;
  for (const auto& p : m.primitives)
    for (const auto& v : p.positions) nose_z = std::min(nose_z, v.z);
  EXPECT_FLOAT_EQ(nose_z, m.bounds_min.z);
  double glow_z = 0.0;
  size_t glow_vertices = 0;
  for (const auto& p : m.primitives)
    if (p.material >= 0 && glm::length(m.materials[size_t(p.material)].emissive) > 0.1f)
      for (const auto& v : p.positions) glow_z += v.z, ++glow_vertices;
  ASSERT_GT(glow_vertices, 0u);
  EXPECT_GT(glow_z / double(glow_vertices), 0.0);
}

// Hull detail: the hull's material carries the plating texture, mapped by
// UVs, with dark panel lines on mostly light plates; a red running light to port (−X) and a
// green one to starboard (+X) glow; hull and trim have a highlight (not fully rough).
TEST_P(GeneratedShip, HullHasPlatingAndRunningLights) {
  const ModelData m = load_model(GetParam().file);
  ASSERT_FALSE(m.materials.empty());
  const Material& hull = m.materials[0];
  ASSERT_GE(hull.base_color_image, 0);
  const Image& plating = m.images[size_t(hull.base_color_image)];
  std::vector<int> histogram(256, 0);
  for (size_t i = 0; i < plating.rgba.size(); i += 4) ++histogram[plating.rgba[i]];
  int dark = 0, light = 0;
  for (int v = 0; v < 110; ++v) dark += histogram[size_t(v)];
  for (int v = 191; v < 256; ++v) light += histogram[size_t(v)];
  const int texels = plating.width * plating.height;
  EXPECT_GT(dark, texels / 50) << "panel lines";
  EXPECT_GT(light, texels / 2) << "plates";
  EXPECT_LT(hull.roughness, 0.8f);
  for (const auto& p : m.primitives)
    if (p.material == 0) {
      EXPECT_EQ(p.uvs.size(), p.positions.size());
    }
  auto side_of = [&](auto is_colour) {
    double x = 0.0;
    size_t n = 0;
    for (const auto& p : m.primitives)
      if (p.material >= 0 && is_colour(m.materials[size_t(p.material)].emissive))
        for (const auto& v : p.positions) x += v.x, ++n;
    return n ? x / double(n) : 0.0;
  };
  EXPECT_LT(side_of([](glm::vec3 e) { return e.r > 0.8f && e.g < 0.3f && e.b < 0.3f; }), -1.0) << "red to port";
  EXPECT_GT(side_of([](glm::vec3 e) { return e.g > 0.8f && e.r < 0.3f && e.b < 0.5f; }), 1.0) << "green to starboard";
}

// Each class reads by its hull colour: every pair differs clearly, and none is close to the
// default team colours (blue [0.22, 0.5, 1], red [1, 0.2, 0.12]) that paint their stripes.
TEST(GeneratedShips, ClassesDifferInHullColour) {
  std::vector<glm::vec3> hulls;
  for (const char* name : {"viper", "warden", "dart"})
    hulls.push_back(glm::vec3(load_model(std::string("assets/models/") + name + ".glb").materials.at(0).base_color));
  for (size_t i = 0; i < hulls.size(); ++i) {
    for (size_t j = i + 1; j < hulls.size(); ++j) EXPECT_GT(glm::length(hulls[i] - hulls[j]), 0.2f) << i << " " << j;
    EXPECT_GT(glm::length(hulls[i] - glm::vec3(0.22f, 0.5f, 1.0f)), 0.45f) << i;
    EXPECT_GT(glm::length(hulls[i] - glm::vec3(1.0f, 0.2f, 0.12f)), 0.45f) << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Assets, GeneratedShip,
                         ::testing::Values(ShipCase{"assets/models/viper.glb", 12.0f, 17.0f},
                                           ShipCase{"assets/models/warden.glb", 17.0f, 24.0f},
                                           ShipCase{"assets/models/dart.glb", 11.0f, 16.0f}));

TEST(GeneratedScenery, WallIsA40MetrePanelFacingPlusZ) {
  const ModelData m = load_model("assets/models/wall.glb");
  expect_well_formed(m);
  EXPECT_FLOAT_EQ(m.bounds_min.x, -20.0f);
  EXPECT_FLOAT_EQ(m.bounds_max.x, 20.0f);
  EXPECT_FLOAT_EQ(m.bounds_min.y, -20.0f);
  EXPECT_FLOAT_EQ(m.bounds_max.y, 20.0f);
  EXPECT_GT(m.bounds_max.z, 0.3f);  // relief on the front face
  EXPECT_LT(m.bounds_max.z - m.bounds_min.z, 3.0f);
}

TEST(GeneratedScenery, AsteroidIsLumpy) {
  const ModelData m = load_model("assets/models/asteroid.glb");
  expect_well_formed(m);
  EXPECT_GE(triangle_count(m), 300u);
  float rmin = 1e9f, rmax = 0.0f;
  for (const auto& p : m.primitives)
    for (const auto& v : p.positions) rmin = std::min(rmin, glm::length(v)), rmax = std::max(rmax, glm::length(v));
  EXPECT_GT(rmax / rmin, 1.3f);
  EXPECT_FLOAT_EQ(rmax, m.radius);
}

// A unit quad in the XY plane facing +Z, stored once and indexed three ways.
std::string quad_buffer() {
  const float pos[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const uint8_t i8[6] = {0, 1, 2, 0, 2, 3};
  const uint16_t i16[6] = {0, 1, 2, 0, 2, 3};
  const uint32_t i32[6] = {0, 1, 2, 0, 2, 3};
  std::string b(92, '\0');
  std::memcpy(b.data(), pos, 48);
  std::memcpy(b.data() + 48, i8, 6);
  std::memcpy(b.data() + 56, i16, 12);
  std::memcpy(b.data() + 68, i32, 24);
  return b;
}

// node 0: translate (10,0,0) → node 1: rotate 90° about +Y, scale 2, mesh 0 (u8)
//   → node 2: matrix translate (0,5,0), mesh 1 (u16).  node 3: mesh 2 (u32 and non-indexed).
// Scene 1 (the default) holds nodes 0 and 3; scene 0 holds only node 3.
const char* kHandMadeGltf = R"({
  "asset": {"version": "2.0"},
  "scene": 1,
  "scenes": [{"nodes": [3]}, {"nodes": [0, 3]}],
  "nodes": [
    {"translation": [10, 0, 0], "children": [1]},
    {"rotation": [0, 0.70710678118654752, 0, 0.70710678118654752], "scale": [2, 2, 2], "mesh": 0, "children": [2]},
    {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,5,0,1], "mesh": 1},
    {"mesh": 2}
  ],
  "meshes": [
    {"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]},
    {"primitives": [{"attributes": {"POSITION": 0}, "indices": 2, "mode": 4}]},
    {"primitives": [{"attributes": {"POSITION": 0}, "indices": 3}, {"attributes": {"POSITION": 4}}]}
  ],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1, 1]}, "emissiveFactor": [1, 0.5, 0]}],
  "buffers": [{"uri": "quad.bin", "byteLength": 92}],
  "bufferViews": [
    {"buffer": 0, "byteOffset": 0, "byteLength": 48},
    {"buffer": 0, "byteOffset": 48, "byteLength": 6},
    {"buffer": 0, "byteOffset": 56, "byteLength": 12},
    {"buffer": 0, "byteOffset": 68, "byteLength": 24}
  ],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
    {"bufferView": 1, "componentType": 5121, "count": 6, "type": "SCALAR"},
    {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"},
    {"bufferView": 3, "componentType": 5125, "count": 6, "type": "SCALAR"},
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]}
  ]
})";

void expect_vec3(glm::vec3 actual, glm::vec3 expected) {
  EXPECT_NEAR(actual.x, expected.x, 1e-5f);
  EXPECT_NEAR(actual.y, expected.y, 1e-5f);
  EXPECT_NEAR(actual.z, expected.z, 1e-5f);
}

TEST(HandMadeGltf, ReadsEveryIndexTypeAndBakesTheNodeHierarchy) {
  const auto dir = test::scratch_dir();
  test::write_bytes(dir / "quad.bin", quad_buffer());
  test::write_bytes(dir / "scene.gltf", kHandMadeGltf);
  const ModelData m = load_model((dir / "scene.gltf").string());
  ASSERT_EQ(m.primitives.size(), 4u);  // default scene: meshes 0, 1, 2 (two primitives)
  expect_well_formed(m);
  // Without normals in the file every triangle gets its own vertices: 2 triangles → 6 vertices.
  for (size_t i = 0; i < 3; ++i) {
    ASSERT_EQ(m.primitives[i].indices.size(), 6u) << i;
    EXPECT_EQ(m.primitives[i].positions.size(), 6u) << i;
  }
  EXPECT_EQ(m.primitives[3].indices.size(), 3u);

  // Mesh 0 under T(10,0,0)·R_y(90°)·S(2): (1,0,0) → (2,0,0) → (0,0,−2) → (10,0,−2); normal +Z → +X.
  const MeshPrimitive& p0 = m.primitives[0];
  EXPECT_EQ(p0.material, 0);
  expect_vec3(p0.positions[p0.indices[1]], {10, 0, -2});
  expect_vec3(p0.positions[p0.indices[2]], {10, 2, -2});
  for (const auto& n : p0.normals) expect_vec3(n, {1, 0, 0});
  // Mesh 1 one level deeper, after the matrix translation (0,5,0): (1,0,0) → (10,10,−2).
  const MeshPrimitive& p1 = m.primitives[1];
  EXPECT_EQ(p1.material, -1);
  expect_vec3(p1.positions[p1.indices[1]], {10, 10, -2});
  // Mesh 2 at the root is untouched.
  expect_vec3(m.primitives[2].positions[m.primitives[2].indices[2]], {1, 1, 0});
  for (const auto& n : m.primitives[3].normals) expect_vec3(n, {0, 0, 1});

  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_FLOAT_EQ(m.materials[0].base_color.g, 0.25f);
  EXPECT_FLOAT_EQ(m.materials[0].emissive.r, 1.0f);
  EXPECT_EQ(m.materials[0].base_color_image, -1);
  expect_vec3(m.bounds_min, {0, 0, -2});
  expect_vec3(m.bounds_max, {10, 12, 0});
  EXPECT_NEAR(m.radius, glm::length(glm::vec3(10, 12, -2)), 1e-4f);
}

TEST(HandMadeGltf, MirroringTransformKeepsFrontFacesOutward) {
  const auto dir = test::scratch_dir();
  test::write_bytes(dir / "quad.bin", quad_buffer());
  std::string text = kHandMadeGltf;
  const std::string from = R"("scale": [2, 2, 2])";
  text.replace(text.find(from), from.size(), R"("scale": [-2, 2, 2])");
  test::write_bytes(dir / "mirror.gltf", text);
  const ModelData m = load_model((dir / "mirror.gltf").string());
  const MeshPrimitive& p = m.primitives[0];
  for (size_t t = 0; t < p.indices.size(); t += 3) {
    const glm::vec3 a = p.positions[p.indices[t]], b = p.positions[p.indices[t + 1]], c = p.positions[p.indices[t + 2]];
    const glm::vec3 winding = glm::normalize(glm::cross(b - a, c - a));
    expect_vec3(winding, p.normals[p.indices[t]]);
  }
}

// Textures go through the same OpenImageIO decoder as every other image; emissive strength
// (KHR_materials_emissive_strength) scales the emissive factor beyond glTF's [0, 1].
TEST(HandMadeGltf, ReadsBaseColourAndEmissiveTextures) {
  const auto dir = test::scratch_dir();
  test::write_bytes(dir / "quad.bin", quad_buffer());
  Image tex;
  tex.width = 2;
  tex.height = 1;
  tex.rgba = {255, 0, 0, 255, 10, 20, 30, 40};
  save_image((dir / "tex.png").string(), tex);
  std::string text = kHandMadeGltf;
  const std::string from = R"("emissiveFactor": [1, 0.5, 0]}],)";
  text.replace(text.find(from), from.size(),
               R"("emissiveFactor": [1, 0.5, 0], "emissiveTexture": {"index": 1},
                      "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}}],
                  "textures": [{"source": 0}, {"source": 0}], "images": [{"uri": "tex.png"}],)");
  const std::string base = R"("baseColorFactor": [0.5, 0.25, 1, 1])";
  text.replace(text.find(base), base.size(), base + R"(, "baseColorTexture": {"index": 0})");
  test::write_bytes(dir / "textured.gltf", text);
  const ModelData m = load_model((dir / "textured.gltf").string());
  ASSERT_EQ(m.images.size(), 1u);
  EXPECT_EQ(m.images[0].width, 2);
  EXPECT_EQ(m.images[0].height, 1);
  EXPECT_EQ(m.images[0].rgba, tex.rgba);
  EXPECT_EQ(m.materials[0].base_color_image, 0);
  EXPECT_EQ(m.materials[0].emissive_image, 0);
  EXPECT_FLOAT_EQ(m.materials[0].emissive.g, 2.0f);  // 0.5 × emissiveStrength 4

  test::write_bytes(dir / "tex.png", "\x89PNG\r\n\x1a\n truncated");
  try {
    load_model((dir / "textured.gltf").string());
    FAIL() << "a broken texture loaded";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind((dir / "textured.gltf").string() + ": ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace arc
