// Header banners' usage examples stay true: a banner line
//   // Example, compiled as Suite.Name in tests/unit/<module>/<file>.cpp:
// followed by `//   code` lines names the test whose body holds that code. This test finds
// every such banner under engine/ and game/ and checks that each example line appears, in
// order, in the body of TEST(Suite, Name) in that file. The test compiles and runs the code;
// this keeps the banner and the test the same text, so an example can no longer go stale.
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

std::vector<Example> banner_examples() {
  static const std::regex marker(R"(^// Example, compiled as (\w+)\.(\w+) in (\S+\.cpp):\s*$)");
  std::vector<Example> out;
  for (const char* dir : {"engine", "game"}) {
    for (const auto& e : std::filesystem::recursive_directory_iterator(kRoot + "/" + dir)) {
      if (e.path().extension() != ".h") continue;
      std::istringstream in(read(e.path()));
      std::string line;
      Example* open = nullptr;
      while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_match(line, m, marker)) {
          out.push_back({std::filesystem::relative(e.path(), kRoot).string(), m[1], m[2], m[3], {}});
          open = &out.back();
        } else if (open && line.rfind("//   ", 0) == 0) {
          open->lines.push_back(trim(line.substr(2)));
        } else {
          open = nullptr;
        }
      }
    }
  }
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
    const std::string body = test_body(read(kRoot + "/" + ex.test_file), ex.suite, ex.name);
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

// The checker itself fails on a line the test does not hold.
TEST(HeaderExamples, CheckerSeesAMismatch) {
  const std::string src = "TEST(A, B) {\n  int x = 1;\n  { x += 2; }\n}\nTEST(A, C) { int y = 0; }\n";
  const std::string body = test_body(src, "A", "B");
  EXPECT_NE(body.find("x += 2;"), std::string::npos);
  EXPECT_EQ(body.find("int y"), std::string::npos);
  EXPECT_TRUE(test_body(src, "A", "D").empty());
}

}  // namespace
