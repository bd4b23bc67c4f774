// glTF files that are not what they claim (assets/gltf_claims.h, assets/model.cpp): another
// version, a required extension the loader lacks, an empty accessor, a node transform that
// overflows. Each is one line naming the file and the version, extension, accessor or node.
#include <cstring>
#include <string>
#include <gtest/gtest.h>
#include "assets/gltf_claims.h"
#include "assets/model.h"
#include "core/error.h"
#include "test_util.h"

namespace arc {
namespace {

// One triangle, its 36 bytes of positions and 6 of u16 indices in an embedded buffer (a data
// URI in .gltf, the BIN chunk in .glb); NODES and ASSET are replaced per test.
const char* kModel = R"({
  "asset": ASSET,
  "scenes": [{"nodes": [0]}],
  "nodes": NODES,
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
  "buffers": [{BUFFER"byteLength": 42}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": COUNT, "type": "VEC3"},
    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}
  ]EXTRA
})";

std::string triangle_bytes() {
  const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const uint16_t idx[3] = {0, 1, 2};
  std::string b(42, '\0');
  std::memcpy(b.data(), pos, 36);
  std::memcpy(b.data() + 36, idx, 6);
  return b;
}

std::string base64(const std::string& in) {
  static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < in.size(); i += 3) {
    uint32_t v = uint32_t(uint8_t(in[i])) << 16;
    if (i + 1 < in.size()) v |= uint32_t(uint8_t(in[i + 1])) << 8;
    if (i + 2 < in.size()) v |= uint32_t(uint8_t(in[i + 2]));
    out += abc[(v >> 18) & 63];
    out += abc[(v >> 12) & 63];
    out += i + 1 < in.size() ? abc[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? abc[v & 63] : '=';
  }
  return out;
}

struct Claims {
  std::string asset = R"({"version": "2.0"})";
  std::string nodes = R"([{"mesh": 0}])";
  int count = 3;
  std::string extra;
};

std::string with_part(std::string text, const std::string& key, const std::string& value) {
  const size_t at = text.find(key);
  if (at == std::string::npos) {
    ADD_FAILURE() << "no " << key;
    return text;
  }
  return text.replace(at, key.size(), value);
}

std::string gltf_text(const Claims& c, bool embedded_uri) {
  std::string t = with_part(kModel, "ASSET", c.asset);
  t = with_part(t, "NODES", c.nodes);
  t = with_part(t, "COUNT", std::to_string(c.count));
  t = with_part(t, "EXTRA", c.extra);
  return with_part(t, "BUFFER", embedded_uri ? "\"uri\": \"data:application/octet-stream;base64," + base64(triangle_bytes()) + "\", " : "");
}

void put_u32(std::string& s, uint32_t v) { s.append(reinterpret_cast<const char*>(&v), 4); }

// A binary glTF: header, the JSON chunk (padded with spaces) and the BIN chunk (with zeros).
std::string glb_bytes(const Claims& c) {
  std::string json = gltf_text(c, false);
  while (json.size() % 4) json += ' ';
  std::string bin = triangle_bytes();
  while (bin.size() % 4) bin += '\0';
  std::string out = "glTF";
  put_u32(out, 2);
  put_u32(out, uint32_t(12 + 8 + json.size() + 8 + bin.size()));
  put_u32(out, uint32_t(json.size()));
  put_u32(out, 0x4E4F534Au);
  out += json;
  put_u32(out, uint32_t(bin.size()));
  put_u32(out, 0x004E4942u);
  return out + bin;
}

class GltfClaims : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::scratch_dir(); }
  // The one-line error of loading the model, as .gltf and as .glb: both must give `expected`
  // after "PATH: ".
  void expect_refused(const Claims& c, const std::string& expected) {
    for (const bool binary : {false, true}) {
      const std::string path = (dir_ / (binary ? "m.glb" : "m.gltf")).string();
      test::write_bytes(path, binary ? glb_bytes(c) : gltf_text(c, true));
      std::string msg;
      try {
        load_model(path);
      } catch (const InputError& e) {
        msg = e.what();
      }
      EXPECT_EQ(msg, path + ": " + expected);
    }
  }
  std::filesystem::path dir_;
};

TEST_F(GltfClaims, TheBaselineLoadsAsGltfAndGlb) {
  test::write_bytes(dir_ / "ok.gltf", gltf_text(Claims{}, true));
  test::write_bytes(dir_ / "ok.glb", glb_bytes(Claims{}));
  EXPECT_EQ(load_model((dir_ / "ok.gltf").string()).primitives.size(), 1u);
  EXPECT_EQ(load_model((dir_ / "ok.glb").string()).primitives.size(), 1u);
  Claims minor;
  minor.asset = R"({"version": "2.1", "minVersion": "2.0", "generator": "x"})";
  test::write_bytes(dir_ / "minor.gltf", gltf_text(minor, true));
  EXPECT_EQ(load_model((dir_ / "minor.gltf").string()).primitives.size(), 1u);
}

TEST_F(GltfClaims, VersionOneIsRefusedNamingIt) {
  Claims c;
  c.asset = R"({"version": "1.0"})";
  expect_refused(c, "asset.version '1.0' is not glTF 2.x; allowed: \"2.0\" or another 2.x (glTF 2)");
}

TEST_F(GltfClaims, MissingOrOddVersionIsRefused) {
  Claims c;
  c.asset = R"({"generator": "hand"})";
  expect_refused(c, "asset.version is missing; a glTF file states its version; allowed: \"2.0\" or another 2.x (glTF 2)");
  c.asset = R"({"version": 2})";
  expect_refused(c, "asset.version is not a string; allowed: \"2.0\" or another 2.x (glTF 2)");
  c.asset = R"({"version": "3.0"})";
  expect_refused(c, "asset.version '3.0' is not glTF 2.x; allowed: \"2.0\" or another 2.x (glTF 2)");
  c.asset = R"({"version": "2.0", "minVersion": "2.1"})";
  expect_refused(c, "asset.minVersion '2.1' asks for a newer glTF than this loader reads; allowed: \"2.0\"");
}

TEST_F(GltfClaims, RequiredExtensionsTheLoaderLacksAreNamed) {
  for (const char* ext : {"KHR_draco_mesh_compression", "EXT_meshopt_compression"}) {
    Claims c;
    c.extra = std::string(R"(, "extensionsUsed": [")") + ext + R"("], "extensionsRequired": [")" + ext + "\"]";
    expect_refused(c, std::string("extensionsRequired lists '") + ext +
                          "', which this loader does not implement; allowed: KHR_materials_emissive_strength "
                          "(export without compression or other required extensions)");
  }
  Claims known;
  known.extra = R"(, "extensionsRequired": ["KHR_materials_emissive_strength"])";
  test::write_bytes(dir_ / "known.gltf", gltf_text(known, true));
  EXPECT_EQ(load_model((dir_ / "known.gltf").string()).primitives.size(), 1u);
}

TEST_F(GltfClaims, AnAccessorOfZeroPositionsIsNamed) {
  Claims c;
  c.count = 0;
  expect_refused(c, "mesh 0 primitive 0: POSITION accessor 0: count is 0; allowed: at least 1 element "
                    "(glTF accessors are never empty)");
}

TEST_F(GltfClaims, IndicesThatAreNotWholeTrianglesAreNamed) {
  Claims c;
  c.nodes = R"([{"mesh": 0}])";
  std::string text = gltf_text(c, true);
  text = with_part(text, R"("componentType": 5123, "count": 3)", R"("componentType": 5123, "count": 2)");
  test::write_bytes(dir_ / "two.gltf", text);
  std::string msg;
  try {
    load_model((dir_ / "two.gltf").string());
  } catch (const InputError& e) {
    msg = e.what();
  }
  EXPECT_EQ(msg, (dir_ / "two.gltf").string() + ": mesh 0 primitive 0: 2 indices is not a whole number of triangles");
}

TEST_F(GltfClaims, ScaleThatOverflowsWhenChainedNamesTheNode) {
  Claims c;
  c.nodes = R"([{"name": "hull", "scale": [1e30, 1e30, 1e30], "children": [1]},
                {"name": "wing", "scale": [1e30, 1e30, 1e30], "mesh": 0}])";
  expect_refused(c, "node 1 'wing': scale overflows the transform composed from the root (an entry reaches 1e+60); "
                    "allowed: transforms whose product stays within ±3.4e38 (single precision)");
  c.nodes = R"([{"matrix": [1e39,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], "mesh": 0}])";
  expect_refused(c, "node 0: matrix overflows the transform composed from the root (an entry reaches 1e+39); "
                    "allowed: transforms whose product stays within ±3.4e38 (single precision)");
}

TEST_F(GltfClaims, VerticesPlacedBeyondTheModelExtentAreNamed) {
  Claims c;
  c.nodes = R"([{"name": "far", "translation": [0, 2e9, 0], "mesh": 0}])";
  expect_refused(c, "node 0 'far': mesh 0 primitive 0: places a vertex at 2e+09 m; allowed: vertices within ±1e9 m "
                    "of the model's origin");
}

}  // namespace
}  // namespace arc
