// Header banners' usage examples stay true: a banner line
//   // Example, compiled as Suite.Name in tests/unit/<module>/<file>.cpp:
// followed by `//   code` lines names the test whose body holds that code. This test finds
// every such banner under engine/ and game/ and checks that each example line appears, in
// order, in the body of TEST(Suite, Name) in that file. The test compiles and runs the code;
// this keeps the banner and the test the same text, so an example can no longer go stale.
// An example that is itself part of the program (a template a header defines) is marked
//   // Example, compiled in game/sim/world.h:
// and its lines must appear, in order, in that file.
// A banner line that reads as code (`//   Type name = ...;`, `//   obj.call(...);`, `for (...)`)
// outside such an example fails the check: every usage example is compiled.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>
#include "core/data_root.h"

namespace {

const std::string kRoot = arc::build_source_tree();  // the sources, found through the build

std::string read(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

struct Example {
  std::string header, suite, name, test_file;
  std::vector<std::string> lines;
};

// An indented banner line (without its `//`) that reads as C++: a control statement, or a
// statement ending in ; { or } that starts as a declaration, a call or an assignment. Prose,
// formulas, tables, file formats and messages do not.
bool looks_like_code(const std::string& text) {
  static const std::regex control(R"(^(for|if|while|switch|return|template)\b.*)");
  static const std::regex declaration(
      R"(^(const\s+|static\s+|auto\s+)?[A-Za-z_][\w:]*(<[^;]*>)?[&*]?\s+[&*]?[A-Za-z_]\w*\s*(=|\(|\{|;|\[).*)");
  static const std::regex call(R"(^[A-Za-z_]\w*((\.|->|::)[A-Za-z_]\w*)*(\(\))?\s*(\(|=[^=]|\+=|-=|\[).*)");
  std::string t = text;
  const size_t comment = t.find(" //");
  if (comment != std::string::npos) t = t.substr(0, comment);
  t = trim(t);
  if (t.empty()) return false;
  if (std::regex_match(t, control)) return true;
  const char last = t.back();
  if (last != ';' && last != '{' && last != '}') return false;
  return std::regex_match(t, declaration) || std::regex_match(t, call);
}

// The compiled examples of one header's banner (its first comment block), and in `loose` the
// banner lines that read as code outside them.
void scan_banner(const std::string& header, const std::string& text, std::vector<Example>& out,
                 std::vector<std::string>& loose) {
  static const std::regex marker(R"(^// Example, compiled as (\w+)\.(\w+) in (\S+\.cpp):\s*$)");
  static const std::regex in_source(R"(^// Example, compiled in (\S+\.(h|cpp)):\s*$)");
  std::istringstream in(text);
  std::string line;
  Example* open = nullptr;
  while (std::getline(in, line) && line.rfind("//", 0) == 0) {
    std::smatch m;
    if (std::regex_match(line, m, marker)) {
      out.push_back({header, m[1], m[2], m[3], {}});
      open = &out.back();
    } else if (std::regex_match(line, m, in_source)) {
      out.push_back({header, "", "", m[1], {}});
      open = &out.back();
    } else if (open && line.rfind("//   ", 0) == 0) {
      open->lines.push_back(trim(line.substr(2)));
    } else {
      open = nullptr;
      if (line.rfind("//   ", 0) == 0 && looks_like_code(line.substr(2))) loose.push_back(header + ": " + line);
    }
  }
}

std::vector<Example> banner_examples(std::vector<std::string>* loose = nullptr) {
  std::vector<Example> out;
  std::vector<std::string> uncompiled;
  for (const char* dir : {"engine", "game"}) {
    for (const auto& e : std::filesystem::recursive_directory_iterator(kRoot + "/" + dir)) {
      if (e.path().extension() != ".h") continue;
      scan_banner(std::filesystem::relative(e.path(), kRoot).string(), read(e.path()), out, uncompiled);
    }
  }
  if (loose) *loose = uncompiled;
  return out;
}

// The text of TEST(suite, name) { ... } in `source`, or "" when there is no such test.
std::string test_body(const std::string& source, const std::string& suite, const std::string& name) {
  const std::regex head("TEST(_F)?\\(\\s*" + suite + "\\s*,\\s*" + name + "\\s*\\)\\s*\\{");
  std::smatch m;
  if (!std::regex_search(source, m, head)) return "";
  size_t i = size_t(m.position(0) + m.length(0)), depth = 1;
  const size_t start = i;
  for (; i < source.size() && depth > 0; ++i) depth += source[i] == '{' ? 1 : source[i] == '}' ? size_t(-1) : 0;
  return source.substr(start, i - start);
}

TEST(HeaderExamples, MatchTheirTests) {
  const std::vector<Example> examples = banner_examples();
  EXPECT_GE(examples.size(), 2u);
  for (const Example& ex : examples) {
    SCOPED_TRACE(ex.header);
    EXPECT_FALSE(ex.lines.empty()) << "example with no code lines";
    const std::string source = read(kRoot + "/" + ex.test_file);
    const std::string body = ex.suite.empty() ? source : test_body(source, ex.suite, ex.name);
    ASSERT_FALSE(body.empty()) << ex.header << ": no TEST(" << ex.suite << ", " << ex.name << ") in " << ex.test_file;
    size_t at = 0;
    for (const std::string& code : ex.lines) {
      const size_t found = body.find(code, at);
      EXPECT_NE(found, std::string::npos) << ex.header << ": example line not in " << ex.suite << "." << ex.name
                                          << " (after the previous line): " << code;
      if (found != std::string::npos) at = found + code.size();
    }
  }
}

// Every code example in a banner is a compiled one: a `//   code` line outside an
// "Example, compiled as" block names its header here.
TEST(HeaderExamples, EveryBannerExampleIsCompiled) {
  std::vector<std::string> loose;
  banner_examples(&loose);
  for (const std::string& line : loose)
    ADD_FAILURE() << "a usage example that no test compiles; put it under a line \"// Example, compiled as "
                     "Suite.Name in tests/unit/<module>/<file>.cpp:\" and make that test's body hold it: "
                  << line;
}

// The code detector: statements are code; prose, formulas, tables and messages are not.
TEST(HeaderExamples, CodeLinesAreToldFromProse) {
  for (const char* code : {"  Settings s;", "  FileWriter out(\"out/summary.json\");", "  out.commit();  // renamed",
                           "  int n = clock.advance(frame_seconds);   // run n ticks now", "  ships[s.index()];  // 3",
                           "  for (const Done& d : shots.finished())", "  arc::Rng r{seed, stream, tick};",
                           "  const EffectField* f = effect_field_at(\"/a\");", "  renderer->render(view, 640, 360);"})
    EXPECT_TRUE(looks_like_code(code)) << code;
  for (const char* prose : {"  value(t) = start + delta,", "  cockpit: no own shield (the camera sits inside);",
                            "                   larger on a kill;", "  \"levels/duel.json:12:7: 'seed' must be\"",
                            "  levels/duel.json:14:18: 'hull' must be a number in [1, 1e6], got -5",
                            "  hdr off, FXAA      the 8-bit scene colour filtered by FXAA into the output",
                            "  0 5c1f0e6a9b3d2c47 9e02d4c1a0b37f55      tick, cheap hash, full hash"})
    EXPECT_FALSE(looks_like_code(prose)) << prose;
  std::vector<Example> examples;
  std::vector<std::string> loose;
  scan_banner("a.h",
              "// a.h — one.\n//\n// Example, compiled as A.B in t.cpp:\n//   A a;\n//\n//   B b;\n#pragma once\n//   C c;\n",
              examples, loose);
  ASSERT_EQ(examples.size(), 1u);
  EXPECT_EQ(examples[0].lines, std::vector<std::string>{"A a;"});
  EXPECT_EQ(loose, std::vector<std::string>{"a.h: //   B b;"}) << "only the banner, and only outside examples";
}

// The checker itself fails on a line the test does not hold.
TEST(HeaderExamples, CheckerSeesAMismatch) {
  const std::string src = "TEST(A, B) {\n  int x = 1;\n  { x += 2; }\n}\nTEST(A, C) { int y = 0; }\n";
  const std::string body = test_body(src, "A", "B");
  EXPECT_NE(body.find("x += 2;"), std::string::npos);
  EXPECT_EQ(body.find("int y"), std::string::npos);
  EXPECT_TRUE(test_body(src, "A", "D").empty());
}

}  // namespace
