// Input limits (core/input_limits.h) and the linear cost they buy. Cost is counted, never timed:
// this program replaces operator new to count the bytes and blocks each parse allocates, and a
// loader is linear when twice the input costs at most about twice the allocations.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <new>
#include <string>

#include "core/error.h"
#include "core/input_limits.h"
#include "core/json.h"
#include "game/app/all_settings.h"
#include "replay/script.h"

namespace {
std::atomic<size_t> g_bytes{0}, g_blocks{0};
}  // namespace

void* operator new(size_t n) {
  g_bytes += n;
  ++g_blocks;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }

namespace {

struct Cost {
  size_t bytes = 0, blocks = 0;
};

Cost cost_of(const std::function<void()>& f) {
  const size_t b0 = g_bytes, n0 = g_blocks;
  f();
  return {g_bytes - b0, g_blocks - n0};
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const arc::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string repeat(const std::string& s, size_t n) {
  std::string out;
  for (size_t i = 0; i < n; ++i) out += s;
  return out;
}

// Documents of n repetitions of the shapes that cost the position recorder most: values at the
// deepest allowed level, values under the longest allowed keys, many small objects.
std::string deep_leaves(size_t n) {
  const std::string open = repeat("{\"k\":", 14) + "[";
  const std::string close = "]" + repeat("}", 14);
  return open + repeat("0,", n) + "0" + close;
}
std::string long_keys(size_t n) {
  const std::string key(200, 'k');
  std::string out = "{";
  for (size_t i = 0; i < n; ++i) out += "\"" + key + std::to_string(i) + "\":[0,0,0,0,0,0,0,0],";
  return out + "\"end\":0}";
}
std::string small_objects(size_t n) { return "[" + repeat("{\"a\":1},", n) + "{}]"; }

void expect_linear(const std::function<std::string(size_t)>& make, size_t n, const char* what) {
  const std::string small = make(n), big = make(2 * n);
  const Cost a = cost_of([&] { arc::JsonDoc::parse(small, "a.json"); });
  const Cost b = cost_of([&] { arc::JsonDoc::parse(big, "b.json"); });
  const double input_ratio = double(big.size()) / double(small.size());
  EXPECT_LE(double(b.bytes) / double(a.bytes), input_ratio * 1.1) << what << ": bytes " << a.bytes << " -> " << b.bytes;
  EXPECT_LE(double(b.blocks) / double(a.blocks), input_ratio * 1.1) << what << ": blocks " << a.blocks << " -> " << b.blocks;
}

}  // namespace

TEST(InputLimits, DeepNestingIsRefusedWithOneLineAndLittleMemory) {
  // 200 KB of '[': without the depth limit the parse tree would take gigabytes.
  const std::string text(200000, '[');
  std::string e;
  const Cost c = cost_of([&] { e = error_of([&] { arc::JsonDoc::parse(text, "nested.json"); }); });
  EXPECT_EQ(e.rfind("nested.json:1:17: arrays and objects nested deeper than 16 levels", 0), 0u) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos);
  EXPECT_LT(c.bytes, size_t(1) << 20) << "refusing must not build anything the size of the input";
}

TEST(InputLimits, LongStringIsRefusedAtItsPosition) {
  const std::string e = error_of([] { arc::JsonDoc::parse("{\n  \"name\": \"" + std::string(5000, 'x') + "\"}", "s.json"); });
  EXPECT_EQ(e.rfind("s.json:2:11: a string of 5000 bytes; strings in a data file", 0), 0u) << e;
}

TEST(InputLimits, LongPointerIsRefused) {
  const std::string key(100, 'k');
  const std::string text = "{\"" + key + "\":{\"" + key + "\":{\"" + key + "\":1}}}";
  const std::string e = error_of([&] { arc::JsonDoc::parse(text, "p.json"); });
  EXPECT_NE(e.find("p.json:1:"), std::string::npos) << e;
  EXPECT_NE(e.find("longer than 256 characters"), std::string::npos) << e;
}

TEST(InputLimits, TooManyObjectsAreRefused) {
  const std::string e = error_of([] { arc::JsonDoc::parse("[" + repeat("{},", 70000) + "{}]", "o.json"); });
  EXPECT_NE(e.find("more than 65536 objects"), std::string::npos) << e;
}

TEST(InputLimits, BracketsInsideStringsAndCommentsDoNotCount) {
  const std::string text = "// [[[[[[[[[[[[[[[[[[[[\n{\"a\": \"[[[[[[[[[[[[[[[[[[[[[[\\\"[[[\", /* {{{{{{{{{{{{{{{{{{{{ */ \"b\": 1}";
  EXPECT_EQ(arc::JsonDoc::parse(text, "c.json")->root()["b"], 1);
}

TEST(InputLimits, LargeFileIsRefusedBeforeItIsRead) {
  const std::string path = testing::TempDir() + "arcfire_big.json";
  {
    std::ofstream out(path);
    out << "[0]";
  }
  std::filesystem::resize_file(path, arc::kMaxDataFileBytes + 3);  // sparse: nothing is written
  const Cost c = cost_of([&] {
    const std::string e = error_of([&] { arc::JsonDoc::load_file(path); });
    EXPECT_NE(e.find(path + ": file is 16777219 bytes; a data file (level, ship class, effect, settings, bindings) may be at most 16 MiB"),
              std::string::npos) << e;
  });
  EXPECT_LT(c.bytes, size_t(64) << 10);
  std::remove(path.c_str());
}

TEST(InputLimits, ScriptLineAndSizeLimits) {
  const arc::Settings known = arc::all_settings();
  const std::string header = "arcfire-replay 1\nlevel levels/duel.json\n";
  std::string e = error_of([&] { arc::replay::parse_script(header + "# " + std::string(5000, 'x') + "\n", "l.replay", known); });
  EXPECT_EQ(e.rfind("l.replay:3:1: line of 5002 bytes; lines may be at most 4096", 0), 0u) << e;
  e = error_of([&] { arc::replay::parse_script(std::string(arc::kMaxScriptFileBytes + 1, '\n'), "big.replay", known); });
  EXPECT_EQ(e.rfind("big.replay: 16777217 bytes; a replay script may be at most 16 MiB", 0), 0u) << e;
}

TEST(InputLimits, JsonParsingCostIsLinearInTheInput) {
  expect_linear(deep_leaves, 20000, "values 15 levels deep");
  expect_linear(long_keys, 300, "values under 200-byte keys");
  expect_linear(small_objects, 10000, "small objects");
}

TEST(InputLimits, JsonParsingCostOfTheWorstAllowedFileIsBounded) {
  // The largest data file of the most expensive shape costs a few dozen bytes per input byte.
  const std::string text = deep_leaves(120000);
  ASSERT_LE(text.size(), arc::kMaxDataFileBytes);
  const Cost c = cost_of([&] { arc::JsonDoc::parse(text, "w.json"); });
  EXPECT_LT(c.bytes, size_t(100) << 20) << c.bytes;
  std::printf("worst allowed shape: %zu input bytes, %zu bytes allocated in %zu blocks\n", text.size(), c.bytes, c.blocks);
}

TEST(InputLimits, TooManyValuesAreRefused) {
  const std::string e = error_of([] { arc::JsonDoc::parse("[" + repeat("0,", size_t(1) << 20) + "0]", "v.json"); });
  EXPECT_NE(e.find("v.json:1:"), std::string::npos) << e;
  EXPECT_NE(e.find("more than 1048576 values"), std::string::npos) << e;
}

// Values under the longest paths allowed: n of them, each path 240 characters or so.
std::string long_paths(size_t n) {
  const std::string key(110, 'k');
  return "{\"" + key + "\":{\"" + key + "\":[" + repeat("0,", n) + "0]}}";
}

TEST(InputLimits, PathsOfAllValuesTogetherAreBounded) {
  const std::string e = error_of([] { arc::JsonDoc::parse(long_paths(200000), "p.json"); });
  EXPECT_NE(e.find("add up to more than 32 MiB"), std::string::npos) << e;
}

TEST(InputLimits, TheRecorderOfTheWorstAllowedShapesStaysSmall) {
  // Just under each bound: the most values, and the longest paths for as many values as fit.
  for (const std::string& text : {"[" + repeat("0,", (size_t(1) << 20) - 2) + "0]", long_paths(130000)}) {
    // Everything allocated counts, freed or not: an upper bound on what the parse holds at once.
    const Cost c = cost_of([&] { arc::JsonDoc::parse(text, "w.json"); });
    EXPECT_LT(c.bytes, size_t(400) << 20) << c.bytes;
    std::printf("worst allowed shape: %zu input bytes, %zu bytes allocated in %zu blocks\n", text.size(), c.bytes, c.blocks);
  }
}

TEST(InputLimits, RelativeTicksPastTheLastTickAreRefusedAtTheirLine) {
  const arc::Settings known = arc::all_settings();
  std::string text = "arcfire-replay 1\nlevel levels/duel.json\n";
  for (int i = 0; i < 11; ++i) text += "+100000000 axis pitch 0.5\n";
  const std::string e = error_of([&] { arc::replay::parse_script(text, "far.replay", known); });
  EXPECT_EQ(e, "far.replay:13:1: relative tick +100000000 after tick 1000000000 reaches tick 1100000000; "
               "allowed: ticks up to 1000000000") << e;
}

TEST(InputLimits, ScriptParsingCostIsLinearInTheInput) {
  const arc::Settings known = arc::all_settings();
  auto make = [](size_t n) {
    std::string s = "arcfire-replay 1\nlevel levels/duel.json\nseed 7\n";
    for (size_t t = 1; t <= n; ++t) s += std::to_string(t) + " axis pitch 0.5\n";
    return s;
  };
  const std::string small = make(5000), big = make(10000);
  const Cost a = cost_of([&] { arc::replay::parse_script(small, "a.replay", known); });
  const Cost b = cost_of([&] { arc::replay::parse_script(big, "b.replay", known); });
  const double input_ratio = double(big.size()) / double(small.size());
  EXPECT_LE(double(b.bytes) / double(a.bytes), input_ratio * 1.15) << a.bytes << " -> " << b.bytes;
  EXPECT_LE(double(b.blocks) / double(a.blocks), input_ratio * 1.15) << a.blocks << " -> " << b.blocks;
}

TEST(InputLimits, LongListIsRefusedAtItsKey) {
  const auto doc = arc::JsonDoc::parse("{\n  \"ships\": [" + repeat("1,", 300) + "1]\n}", "l.json");
  arc::JsonObject root(doc, "", &doc->root());
  const std::string e = error_of([&] { root.check_list_length("ships", 256); });
  EXPECT_EQ(e, "l.json:2:3: 'ships' lists 301 entries; at most 256 are allowed");
  EXPECT_EQ(error_of([&] { root.check_list_length("props", 1); }), "(no error)");
}

TEST(InputLimits, MessagesStayOneLineWhateverTheFileHolds) {
  // A case tests/fuzz finds (level, effect): a value with an escaped newline echoed back in
  // "got ..." would split the one line of a bad-input exit in two.
  const auto doc = arc::JsonDoc::parse("{\"type\": \"last\\nteam\\u0001\"}", "m.json");
  arc::JsonObject root(doc, "", &doc->root());
  const std::string e = error_of([&] { root.choice("type", "a", {"a", "b"}); });
  EXPECT_EQ(e, "m.json:1:10: 'type' must be one of \"a\" or \"b\", got \"last\\nteam\\x01\"");
}
