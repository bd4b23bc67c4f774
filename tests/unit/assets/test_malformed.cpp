// Malformed glTF files: each must give an InputError that names the file and the problem,
// never a crash or an out-of-bounds read.
#include <cstring>
#include <string>
#include <gtest/gtest.h>
#include "assets/model.h"
#include "core/error.h"
#include "core/rng.h"
#include "test_util.h"

namespace arc {
namespace {

// The smallest valid file: one triangle whose positions and u16 indices live in tri.bin.
const char* kTriangle = R"({
  "asset": {"version": "2.0"},
  "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
  "buffers": [{"uri": "tri.bin", "byteLength": 42}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}
  ]
})";

std::string triangle_buffer(uint16_t last_index = 2) {
  const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const uint16_t idx[3] = {0, 1, last_index};
  std::string b(42, '\0');
  std::memcpy(b.data(), pos, 36);
  std::memcpy(b.data() + 36, idx, 6);
  return b;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Loads path and returns the InputError message ("" if it loaded, which fails the test).
std::string load_error(const std::string& path) {
  try {
    load_model(path);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << path << " loaded without an error";
  return "";
}

void expect_error(const std::string& path, const std::string& problem) {
  const std::string msg = load_error(path);
  EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
  EXPECT_NE(msg.find(problem), std::string::npos) << "message: " << msg << "\nexpected to mention: " << problem;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

class Malformed : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::scratch_dir();
    test::write_bytes(dir_ / "tri.bin", triangle_buffer());
  }
  std::string write(const std::string& name, const std::string& text) {
    test::write_bytes(dir_ / name, text);
    return (dir_ / name).string();
  }
  std::filesystem::path dir_;
};

TEST_F(Malformed, TheBaselineLoads) {
  const ModelData m = load_model(write("ok.gltf", kTriangle));
  ASSERT_EQ(m.primitives.size(), 1u);
  EXPECT_EQ(m.primitives[0].indices.size(), 3u);
}

TEST_F(Malformed, MissingFile) { expect_error((dir_ / "nope.glb").string(), "nope.glb: not found; allowed: a regular file"); }

TEST_F(Malformed, BadJson) { expect_error(write("bad.gltf", "{ \"asset\": { \"version\": "), "invalid glTF"); }

TEST_F(Malformed, IndexOutOfRange) {
  test::write_bytes(dir_ / "tri.bin", triangle_buffer(3));
  expect_error(write("index.gltf", kTriangle), "index 3 at position 2 is out of range (the primitive has 3 vertices)");
}

TEST_F(Malformed, MissingBufferFile) {
  expect_error(write("nobuf.gltf", replaced(kTriangle, "tri.bin", "missing.bin")), "missing.bin");
}

TEST_F(Malformed, BufferFileTooShort) {
  test::write_bytes(dir_ / "short.bin", triangle_buffer().substr(0, 30));
  expect_error(write("short.gltf", replaced(kTriangle, "tri.bin", "short.bin")), "invalid glTF");
}

TEST_F(Malformed, BufferIndexOutOfRange) {
  expect_error(write("bufidx.gltf", replaced(kTriangle, R"({"buffer": 0, "byteOffset": 36)", R"({"buffer": 4, "byteOffset": 36)")),
               "buffer 4 does not exist");
}

TEST_F(Malformed, AccessorRunsPastItsBufferView) {
  expect_error(write("count.gltf", replaced(kTriangle, R"("count": 3, "type": "VEC3")", R"("count": 30000, "type": "VEC3")")),
               "exceeds bufferView 0");
}

TEST_F(Malformed, AccessorOffsetRunsPastItsBufferView) {
  expect_error(write("offset.gltf", replaced(kTriangle, R"("componentType": 5123,)", R"("byteOffset": 2, "componentType": 5123,)")),
               "exceeds bufferView 1");
}

TEST_F(Malformed, BufferViewRunsPastItsBuffer) {
  // The buffer declares (and is) 42 bytes; a view to byte 50 must be caught before any read.
  const std::string text = replaced(kTriangle, R"("byteOffset": 36, "byteLength": 6)", R"("byteOffset": 36, "byteLength": 14)");
  expect_error(write("view.gltf", text), "bufferView 1 (bytes 36 + 14) exceeds buffer 0 of 42 bytes");
}

TEST_F(Malformed, NonTriangleMode) {
  expect_error(write("lines.gltf", replaced(kTriangle, R"("mode": 4)", R"("mode": 1)")),
               "primitive mode 1 is not supported (only 4, triangles)");
}

TEST_F(Malformed, NodeCycle) {
  expect_error(write("cycle.gltf", replaced(kTriangle, R"("nodes": [{"mesh": 0}])", R"("nodes": [{"mesh": 0, "children": [1]}, {"children": [0]}])")),
               "node");
}

TEST_F(Malformed, MaterialOutOfRange) {
  expect_error(write("mat.gltf", replaced(kTriangle, R"("mode": 4)", R"("mode": 4, "material": 2)")), "material 2 does not exist");
}

TEST_F(Malformed, WrongIndexComponentType) {
  expect_error(write("idxtype.gltf", replaced(kTriangle, R"("componentType": 5123)", R"("componentType": 5122)")),
               "indices must be SCALAR");
}

class MalformedGlb : public Malformed {
 protected:
  std::string viper() const { return test::read_bytes("assets/models/viper.glb"); }
};

TEST_F(MalformedGlb, TruncatedAtManyLengths) {
  const std::string full = viper();
  ASSERT_GT(full.size(), 1000u);
  for (size_t len : {size_t(0), size_t(3), size_t(11), size_t(12), size_t(19), size_t(20), size_t(100), full.size() / 2,
                     full.size() - 4, full.size() - 1}) {
    SCOPED_TRACE(len);
    expect_error(write("cut.glb", full.substr(0, len)), "truncated .glb");
  }
}

TEST_F(MalformedGlb, NotAGlb) {
  expect_error(write("text.glb", "this is plainly not a binary glTF file at all"), "not a binary glTF file");
}

TEST_F(MalformedGlb, ChunkLengthsLie) {
  std::string bytes = viper();
  const uint32_t huge = 0x7FFFFFF0u;
  std::memcpy(bytes.data() + 12, &huge, 4);  // JSON chunk length
  expect_error(write("json_len.glb", bytes), "JSON chunk runs past the end");
  bytes = viper();
  uint32_t json_len = 0;
  std::memcpy(&json_len, bytes.data() + 12, 4);
  std::memcpy(bytes.data() + 20 + json_len, &huge, 4);  // BIN chunk length
  expect_error(write("bin_len.glb", bytes), "BIN chunk runs past the end");
}

// Random byte corruption anywhere in a real .glb: every outcome must be a clean load or an
// InputError; the test fails on any other exception and crashes on a bad read under ASan.
TEST_F(MalformedGlb, RandomCorruptionNeverCrashes) {
  const std::string original = viper();
  const Rng rng{0xC0FFEEu, 1, 0};
  int errors = 0;
  for (uint64_t trial = 0; trial < 300; ++trial) {
    std::string bytes = original;
    for (uint64_t k = 0; k < 4; ++k) {
      const size_t at = size_t(rng.uniform(trial * 16 + k) * double(bytes.size()));
      bytes[at] = char(rng.bits(trial * 16 + 8 + k) & 0xFF);
    }
    const std::string path = write("fuzz.glb", bytes);
    try {
      const ModelData m = load_model(path);
      for (const auto& p : m.primitives)
        for (uint32_t i : p.indices) ASSERT_LT(i, p.positions.size());
    } catch (const InputError& e) {
      ++errors;
      EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    }
  }
  EXPECT_GT(errors, 0);
}

}  // namespace
}  // namespace arc
