// House rules a newcomer relies on, checked over engine/ and game/: no source file passes 600
// lines, and no function body passes 80 lines unless a comment line right above it gives the
// reason, starting "// Long:"; such a line stands only right above a function of 80 lines or
// more. Functions are found the way the code is written here: a body opened by a line ending
// in '{' at column 0 or 2 (namespace-level functions and class members in line) and closed by
// a '}' at the same indentation. (test_house_text.cpp checks the words of comments and docs.)
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include "core/data_root.h"

namespace {

const std::string kRoot = arc::build_source_tree();  // the sources, found through the build
constexpr size_t kMaxFileLines = 600;
constexpr size_t kMaxFunctionLines = 80;

std::vector<std::string> lines_of(const std::filesystem::path& p) {
  std::ifstream f(p);
  std::vector<std::string> out;
  for (std::string l; std::getline(f, l);) out.push_back(l);
  return out;
}

std::vector<std::filesystem::path> sources() {
  std::vector<std::filesystem::path> out;
  for (const char* dir : {"engine", "game"})
    for (const auto& e : std::filesystem::recursive_directory_iterator(kRoot + "/" + dir))
      if (e.path().extension() == ".cpp" || e.path().extension() == ".h") out.push_back(e.path());
  return out;
}

bool opens_function(const std::string& l, size_t indent) {
  if (l.size() <= indent || l.back() != '{' || l.find_first_not_of(' ') != indent) return false;
  if (l.find('(') == std::string::npos) return false;  // struct, class, enum, namespace
  for (const char* word : {"namespace", "struct ", "class ", "enum ", "if (", "for (", "while (", "switch ("})
    if (l.find(word) != std::string::npos) return false;
  return true;
}

struct Function {
  size_t start;   // 0-based line of the signature's first line
  size_t length;  // lines from the signature to the closing brace
};

std::vector<Function> functions(const std::vector<std::string>& lines) {
  std::vector<Function> out;
  for (size_t indent : {size_t(0), size_t(2)}) {
    const std::string close = std::string(indent, ' ') + "}";
    for (size_t i = 0; i < lines.size(); ++i) {
      if (!opens_function(lines[i], indent)) continue;
      size_t start = i;  // a signature may span lines: find where it starts
      while (start > 0 && !lines[start - 1].empty() && lines[start - 1].find_first_not_of(' ') > indent) --start;
      size_t end = i + 1;
      while (end < lines.size() && lines[end].rfind(close, 0) != 0) ++end;
      out.push_back({start, end - start + 1});
      i = end;
    }
  }
  return out;
}

bool long_reason(const std::string& line) {
  const size_t b = line.find_first_not_of(' ');
  return b != std::string::npos && line.compare(b, 8, "// Long:") == 0;
}

// Functions longer than the limit without a "// Long:" reason: "file:line (N lines)".
std::vector<std::string> long_functions(const std::filesystem::path& p, const std::vector<std::string>& lines) {
  std::vector<std::string> out;
  for (const Function& f : functions(lines)) {
    const bool reason = f.start > 0 && lines[f.start - 1].find("// Long:") != std::string::npos;
    if (f.length > kMaxFunctionLines && !reason)
      out.push_back(p.string() + ":" + std::to_string(f.start + 1) + " (" + std::to_string(f.length) + " lines)");
  }
  return out;
}

// "// Long:" lines not right above a function of at least the limit: "file:line (why)".
std::vector<std::string> needless_reasons(const std::filesystem::path& p, const std::vector<std::string>& lines) {
  std::vector<std::string> out;
  const std::vector<Function> found = functions(lines);
  for (size_t i = 0; i < lines.size(); ++i) {
    if (!long_reason(lines[i])) continue;
    std::string why = "no function the finder sees starts on the next line";
    for (const Function& f : found)
      if (f.start == i + 1)
        why = f.length >= kMaxFunctionLines ? "" : "its function has " + std::to_string(f.length) + " lines";
    if (!why.empty()) out.push_back(p.string() + ":" + std::to_string(i + 1) + " (" + why + ")");
  }
  return out;
}

TEST(HouseRules, NoSourceFilePassesSixHundredLines) {
  for (const auto& p : sources()) {
    const size_t n = lines_of(p).size();
    EXPECT_LE(n, kMaxFileLines) << std::filesystem::relative(p, kRoot).string() << " has " << n << " lines";
  }
}

TEST(HouseRules, NoFunctionPassesEightyLinesWithoutAReason) {
  for (const auto& p : sources())
    for (const std::string& f : long_functions(std::filesystem::relative(p, kRoot), lines_of(p)))
      ADD_FAILURE() << f << ": split it, or say why above it with a \"// Long:\" comment";
}

TEST(HouseRules, LongReasonsOnlyAboveLongFunctions) {
  for (const auto& p : sources())
    for (const std::string& f : needless_reasons(std::filesystem::relative(p, kRoot), lines_of(p)))
      ADD_FAILURE() << f << ": a \"// Long:\" reason belongs only above a function of " << kMaxFunctionLines
                    << " lines or more; drop it";
}

// The finder sees a long function and accepts a stated reason.
TEST(HouseRules, FinderSeesLongFunctions) {
  std::vector<std::string> code{"int f(int x) {"};
  for (int i = 0; i < 90; ++i) code.push_back("  x += 1;");
  code.push_back("}");
  EXPECT_EQ(long_functions("f.cpp", code).size(), 1u);
  code.insert(code.begin(), "// Long: one table of cases, clearer in one place.");
  EXPECT_TRUE(long_functions("f.cpp", code).empty());
  code.erase(code.begin());
  code.resize(40);
  code.push_back("}");
  EXPECT_TRUE(long_functions("f.cpp", code).empty());
}

// A stated reason above a short function, or above no function, is flagged; above one of the
// limit's length it is not.
TEST(HouseRules, FinderSeesNeedlessReasons) {
  std::vector<std::string> code{"// Long: one table of cases.", "int f(int x) {"};
  for (int i = 0; i < 78; ++i) code.push_back("  x += 1;");
  code.push_back("}");
  EXPECT_TRUE(needless_reasons("f.cpp", code).empty());  // 80 lines
  code.erase(code.begin() + 2);
  ASSERT_EQ(needless_reasons("f.cpp", code).size(), 1u);  // 79 lines
  EXPECT_NE(needless_reasons("f.cpp", code)[0].find("f.cpp:1 (its function has 79 lines)"), std::string::npos);
  code.insert(code.begin() + 1, "");
  EXPECT_EQ(needless_reasons("f.cpp", code).size(), 1u);  // not right above
}

}  // namespace
