// The usage examples of engine/core's header banners as tests (HeaderExamples.MatchTheirTests
// keeps each banner and its test the same text).
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/data_root.h"
#include "core/clock.h"
#include "core/file_writer.h"
#include "core/input_file.h"
#include "core/input_limits.h"
#include "core/json.h"
#include "core/rng.h"
#include "core/snapshot_io.h"
#include "core/typed_id.h"

namespace arc {
namespace {

TEST(CoreExamples, FixedStepClock) {
  const double frame_seconds = 0.05;
  FixedStepClock clock{60};
  int n = clock.advance(frame_seconds);   // run n ticks now
  double a = clock.alpha();               // interpolation factor in [0, 1)
  EXPECT_EQ(n, 3);
  EXPECT_GE(a, 0.0);
  EXPECT_LT(a, 1.0);
}

TEST(CoreExamples, KeyedRng) {
  const uint64_t seed = 7, stream = 2, tick = 30, i = 5;
  arc::Rng r{seed, stream, tick};         // a generator for one (seed, stream, tick)
  float u = r.uniform(i);                 // i-th value in [0, 1)
  glm::dvec3 d = r.unit_vector(i);        // uses indices i*4 and i*4+1
  EXPECT_GE(u, 0.0f);
  EXPECT_LT(u, 1.0f);
  EXPECT_NEAR(d.x * d.x + d.y * d.y + d.z * d.z, 1.0, 1e-9);
  EXPECT_EQ(r.uniform(i), (Rng{seed, stream, tick}.uniform(i))) << "the same key, the same value";
}

TEST(CoreExamples, SnapshotRoundTrip) {
  const uint64_t kMagic = 0x5453455453455453ull, x = 42;
  const glm::dvec3 p{1.5, -2.0, 1e9};
  snapshot::Writer out;  out.u64(x);  out.vec3(p);  std::vector<uint8_t> b = out.framed(kMagic, 1);
  snapshot::Reader in = snapshot::Reader::unframe(b.data(), b.size(), kMagic, 1, "particle world");
  uint64_t x2 = in.u64();  glm::dvec3 p2 = in.vec3();  in.expect_end();
  EXPECT_EQ(x2, x);
  EXPECT_EQ(p2, p);
  b.pop_back();
  EXPECT_THROW(snapshot::Reader::unframe(b.data(), b.size(), kMagic, 1, "particle world"), InputError);
}

TEST(CoreExamples, TypedId) {
  const std::vector<std::string> ships{"Player", "Red Leader", "Blue Two", "Red Two"};
  struct ShipTag;
  using ShipId = Id<ShipTag>;
  ShipId s = ShipId::from_index(3);    // value 4
  std::string name = ships[s.index()];  // ships[3]
  bool none = !ShipId{};               // null: names no ship
  EXPECT_EQ(s.value, 4u);
  EXPECT_EQ(name, "Red Two");
  EXPECT_TRUE(none);
}

TEST(CoreExamples, WriteAFile) {
  const std::filesystem::path cwd = std::filesystem::current_path();
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "core_examples_write";
  std::filesystem::create_directories(dir / "out");
  std::filesystem::current_path(dir);
  const std::string text = "{}\n";
  FileWriter out("out/summary.json");
  out.write(text);
  out.commit();  // renamed into place; without commit() the destructor removes the temporary
  const std::string written = read_text_file("out/summary.json");
  std::filesystem::current_path(cwd);
  EXPECT_EQ(written, text);
}

TEST(CoreExamples, CheckBeforeParsing) {
  const std::string path = arc::data_root() + "/levels/duel.json";
  const std::string text = read_text_file(path);
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(arc::data_root());
  check_file_size("levels/duel.json", kMaxDataFileBytes, "a data file");  // throws InputError
  check_json_text(text, path, kDataJsonLimits);                           // path:line:col: ...
  std::filesystem::current_path(cwd);
  EXPECT_THROW(check_json_text(std::string(20, '['), path, kDataJsonLimits), InputError);
}

TEST(CoreExamples, ReadAnInputFile) {
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(arc::data_root());
  std::string text = read_input_file("levels/duel.json", kMaxDataFileBytes, "a level");
  check_input_path("assets/textures/hull_dart.png", kMaxImageFileBytes, "an image");
  std::filesystem::current_path(cwd);
  EXPECT_NE(text.find("\"ships\""), std::string::npos);
  EXPECT_THROW(read_input_file("/dev/zero", kMaxDataFileBytes, "a level"), InputError);
}

TEST(CoreExamples, ReadALevel) {
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(arc::data_root());
  std::vector<std::string> names;
  std::shared_ptr<const JsonDoc> doc = JsonDoc::load_file("levels/duel.json");  // throws InputError
  JsonObject root(doc, "", &doc->root());
  uint64_t seed = root.integer("seed", 1, 0, UINT32_MAX);
  root.check_list_length("ships", kMaxLevelShips);  // before reading a list (core/input_limits.h)
  for (JsonObject s : root.objects("ships")) names.push_back(s.require_string("name"));
  std::filesystem::current_path(cwd);
  EXPECT_EQ(seed, 1101u);
  EXPECT_EQ(names, (std::vector<std::string>{"Player", "Red Leader"}));
}

}  // namespace
}  // namespace arc
