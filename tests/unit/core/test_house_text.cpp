// House rules for the words around the code: comments and READMEs describe the program, not
// the work that made it. Checked here:
//  - comments of every source under engine/, game/, shaders/, tools/ and tests/ (C++ and GLSL:
//    // and /* */ outside string literals; shell, Python, CMake: # outside quotes, and Python's
//    triple-quoted docstrings), and the top-level CMakeLists.txt; the code itself and string
//    literals are not read, and this file is skipped (its lists name what they forbid);
//  - all of README.md and tests/README.md;
//  - docs/**/*.md for dates only: a date of a measurement may stand in a table cell whose
//    column header says "measured on", nowhere else.
// A calendar date fails: 2026-11-27, 27/11/2026, "27 November", "November 27", "Nov 2026"
// (month names are matched with their capital; "May 3" alone reads as the verb and passes).
// So does narration, a fixed list chosen to miss the program's own words:
//  - a work item: "issue" before a number or "#" ("GL issues 3 draws" passes), "the issue
//    asks", "work item";
//  - the work's sessions and commits: "this session", "earlier session", "previous session"
//    ("a live session" and "the session ends" pass), "this commit", an earlier or previous
//    revision, commit or implementation;
//  - who did it: "we measured" and the like, "who ran";
//  - what the code used to do: "as before", "before HDR", "before the change" (or fix, split,
//    rewrite, refactor), and "used to" unless after a form of "be" or "get" ("is used to aim"
//    passes).
// "was" and "no longer" are not checked: the program's own state changes need them ("a loop
// no longer asked for fades out"); review catches the rest. The Text* tests below plant each
// kind of violation and each kind of legitimate text.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
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

struct Comment {
  size_t line;  // 1-based
  std::string text;
};

enum class Syntax { C, Hash, Python };

// The comments of C++ or GLSL text, one entry per line of each comment.
std::vector<Comment> c_comments(const std::string& t) {
  std::vector<Comment> out;
  size_t line = 1;
  auto add = [&](char c) {
    if (out.empty() || out.back().line != line) out.push_back({line, ""});
    out.back().text += c;
  };
  size_t i = 0;
  const size_t n = t.size();
  while (i < n) {
    const char c = t[i];
    if (c == '\n') {
      ++line, ++i;
    } else if (c == '/' && i + 1 < n && t[i + 1] == '/') {
      for (i += 2; i < n && t[i] != '\n'; ++i) add(t[i]);
    } else if (c == '/' && i + 1 < n && t[i + 1] == '*') {
      for (i += 2; i < n && !(t[i] == '*' && i + 1 < n && t[i + 1] == '/'); ++i) {
        if (t[i] == '\n') ++line;
        else add(t[i]);
      }
      i += 2;
    } else if (c == 'R' && i + 1 < n && t[i + 1] == '"' && (i == 0 || !std::isalnum(static_cast<unsigned char>(t[i - 1])))) {
      const size_t open = t.find('(', i + 2);
      if (open == std::string::npos) break;
      std::string end(1, ')');  // ")delimiter\""
      end.append(t, i + 2, open - i - 2).push_back('"');
      const size_t close = t.find(end, open);
      const size_t stop = close == std::string::npos ? n : close + end.size();
      for (; i < stop; ++i) line += t[i] == '\n';
    } else if (c == '"' || (c == '\'' && !(i > 0 && std::isdigit(static_cast<unsigned char>(t[i - 1]))))) {
      for (++i; i < n && t[i] != c && t[i] != '\n'; ++i)
        if (t[i] == '\\') ++i;
      if (i < n && t[i] == c) ++i;
    } else {
      ++i;
    }
  }
  return out;
}

// The comments of shell, CMake or Python text: '#' at the start or after a blank, outside
// quotes (a quote does not run past its line), and for Python every line of a """ docstring.
std::vector<Comment> hash_comments(const std::string& t, Syntax syntax) {
  std::vector<Comment> out;
  std::istringstream in(t);
  std::string l;
  bool docstring = false;
  for (size_t line = 1; std::getline(in, l); ++line) {
    if (line == 1 && l.rfind("#!", 0) == 0) continue;
    size_t from = 0;
    if (docstring) {
      const size_t close = l.find("\"\"\"");
      out.push_back({line, l.substr(0, close)});
      if (close == std::string::npos) continue;
      docstring = false;
      from = close + 3;
    }
    char quote = 0;
    for (size_t i = from; i < l.size(); ++i) {
      const char c = l[i];
      if (quote) {
        if (c == '\\' && quote == '"') ++i;
        else if (c == quote) quote = 0;
      } else if (syntax == Syntax::Python && l.compare(i, 3, "\"\"\"") == 0) {
        const size_t close = l.find("\"\"\"", i + 3);
        out.push_back({line, l.substr(i + 3, close == std::string::npos ? std::string::npos : close - i - 3)});
        if (close == std::string::npos) {
          docstring = true;
          break;
        }
        i = close + 2;
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '#' && (i == 0 || l[i - 1] == ' ' || l[i - 1] == '\t')) {
        out.push_back({line, l.substr(i + 1)});
        break;
      }
    }
  }
  return out;
}

std::vector<Comment> comments_of(const std::string& text, Syntax syntax) {
  return syntax == Syntax::C ? c_comments(text) : hash_comments(text, syntax);
}

struct Rule {
  std::regex pattern;
  const char* what;
};

const std::vector<Rule>& date_rules() {
  static const std::string month =
      "(January|February|March|April|May|June|July|August|September|October|November|December|"
      "Jan|Feb|Mar|Apr|Jun|Jul|Aug|Sep|Sept|Oct|Nov|Dec)";
  static const std::string month_not_may =
      "(January|February|March|April|June|July|August|September|October|November|December|"
      "Jan|Feb|Mar|Apr|Jun|Jul|Aug|Sep|Sept|Oct|Nov|Dec)";
  static const std::vector<Rule> rules{
      {std::regex(R"(\b(19|20)[0-9]{2}-(0[1-9]|1[0-2])-(0[1-9]|[12][0-9]|3[01])\b)"), "a calendar date"},
      {std::regex(R"(\b[0-9]{1,2}[./][0-9]{1,2}[./](19|20)[0-9]{2}\b)"), "a calendar date"},
      {std::regex(R"(\b(19|20)[0-9]{2}/(0[1-9]|1[0-2])/[0-9]{2}\b)"), "a calendar date"},
      {std::regex(R"(\b[0-3]?[0-9](st|nd|rd|th)? )" + month + R"(\b)"), "a calendar date"},
      {std::regex(R"(\b)" + month_not_may + R"(\.? [0-3]?[0-9](st|nd|rd|th)?\b)"), "a calendar date"},
      {std::regex(R"(\b)" + month + R"(\.?( [0-3]?[0-9](st|nd|rd|th)?,?)? (19|20)[0-9]{2}\b)"), "a calendar date"},
  };
  return rules;
}

const std::vector<Rule>& narration_rules() {
  using std::regex_constants::icase;
  using std::regex_constants::ECMAScript;
  static const std::vector<Rule> rules{
      {std::regex(R"(\bissue #?[0-9]+\b|\bissues #[0-9]+)", ECMAScript | icase), "a work item (issue N)"},
      {std::regex(R"(\bissue (also )?(asks|asked|wants|says|requires)\b)", ECMAScript | icase),
       "what a work item asked"},
      {std::regex(R"(\bwork items?\b)", ECMAScript | icase), "a work item"},
      {std::regex(R"(\b(this|earlier|previous) session\b)", ECMAScript | icase), "the work's sessions"},
      {std::regex(R"(\b(earlier|previous|prior|older|old) (revision|commit|implementation)s?\b)",
                  ECMAScript | icase),
       "an earlier revision"},
      {std::regex(R"(\b(we|I) (measured|ran|timed|tried|found|changed|fixed|saw|noticed)\b)", ECMAScript | icase),
       "who did what"},
      {std::regex(R"(\bwho ran\b)", ECMAScript | icase), "who ran what"},
      {std::regex(R"(\bas before\b)", ECMAScript | icase), "what the code used to do"},
      {std::regex(R"(\bbefore (HDR|the (change|fix|split|rewrite|refactor)))", ECMAScript | icase),
       "what the code used to do"},
      {std::regex(R"(\bthis commit\b)", ECMAScript | icase), "the work's commits"},
  };
  return rules;
}

// "used to" as history ("it used to blit"), not as a passive ("is used to blit").
bool history_used_to(const std::string& text) {
  static const std::regex used(R"((\w*)\W*\bused to\b)", std::regex_constants::ECMAScript | std::regex_constants::icase);
  static const std::set<std::string> be{"is", "are", "be", "been", "being", "was", "were", "get", "gets", "got",
                                        "getting", "isn't", "aren't", "not"};
  for (auto it = std::sregex_iterator(text.begin(), text.end(), used); it != std::sregex_iterator(); ++it) {
    std::string word = (*it)[1];
    for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!be.count(word)) return true;
  }
  return false;
}

// What is wrong with one line of prose: "" when nothing. `narration` off checks dates only.
std::string offence(const std::string& text, bool narration) {
  std::smatch m;
  for (const Rule& r : date_rules())
    if (std::regex_search(text, m, r.pattern)) return std::string(r.what) + " (\"" + m.str(0) + "\")";
  if (!narration) return "";
  for (const Rule& r : narration_rules())
    if (std::regex_search(text, m, r.pattern)) return std::string(r.what) + " (\"" + m.str(0) + "\")";
  if (history_used_to(text)) return "what the code used to do (\"used to\")";
  return "";
}

// "name:line: what" for each offending comment line.
std::vector<std::string> comment_offences(const std::string& name, const std::string& text, Syntax syntax) {
  std::vector<std::string> out;
  for (const Comment& c : comments_of(text, syntax)) {
    const std::string o = offence(c.text, true);
    if (!o.empty()) out.push_back(name + ":" + std::to_string(c.line) + ": " + o);
  }
  return out;
}

std::vector<std::string> prose_offences(const std::string& name, const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string l;
  for (size_t line = 1; std::getline(in, l); ++line) {
    const std::string o = offence(l, true);
    if (!o.empty()) out.push_back(name + ":" + std::to_string(line) + ": " + o);
  }
  return out;
}

std::vector<std::string> cells_of(const std::string& row) {
  std::vector<std::string> out;
  std::string cell;
  const size_t first = row.find('|');
  for (size_t i = first + 1; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size()) {
      cell += row[++i];
    } else if (row[i] == '|') {
      out.push_back(cell);
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  if (cell.find_first_not_of(" \t\r") != std::string::npos) out.push_back(cell);
  return out;
}

// Dates in a document under docs/: allowed only in a table cell whose column header says
// "measured on".
std::vector<std::string> doc_offences(const std::string& name, const std::string& text) {
  static const std::regex measured_on("measured on", std::regex_constants::ECMAScript | std::regex_constants::icase);
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string l;
  std::vector<bool> dated_columns;  // of the table the line is in; empty outside tables
  bool in_table = false;
  for (size_t line = 1; std::getline(in, l); ++line) {
    const bool row = l.find_first_not_of(" \t") != std::string::npos && l[l.find_first_not_of(" \t")] == '|';
    if (row && !in_table) {
      dated_columns.clear();
      for (const std::string& c : cells_of(l)) dated_columns.push_back(std::regex_search(c, measured_on));
    }
    in_table = row;
    std::string checked = l;
    if (row) {
      const std::vector<std::string> cells = cells_of(l);
      checked.clear();
      for (size_t i = 0; i < cells.size(); ++i)
        if (i >= dated_columns.size() || !dated_columns[i]) checked += cells[i] + " | ";
    }
    const std::string o = offence(checked, false);
    if (!o.empty()) out.push_back(name + ":" + std::to_string(line) + ": " + o);
  }
  return out;
}

bool is_source(const std::filesystem::path& p, Syntax& syntax) {
  static const std::set<std::string> c{".h", ".hpp", ".cpp", ".cc", ".c", ".glsl", ".vert", ".frag", ".geom", ".comp"};
  const std::string ext = p.extension().string();
  if (c.count(ext)) return syntax = Syntax::C, true;
  if (ext == ".sh" || ext == ".cmake" || p.filename() == "CMakeLists.txt") return syntax = Syntax::Hash, true;
  if (ext == ".py") return syntax = Syntax::Python, true;
  return false;
}

std::string from_root(const std::filesystem::path& p) { return std::filesystem::relative(p, kRoot).string(); }

TEST(HouseRules, SourceCommentsDescribeTheProgram) {
  const std::filesystem::path self = std::filesystem::path(kRoot) / "tests/unit/core/test_house_text.cpp";
  std::vector<std::filesystem::path> files{std::filesystem::path(kRoot) / "CMakeLists.txt"};
  for (const char* dir : {"engine", "game", "shaders", "tools", "tests"})
    for (const auto& e : std::filesystem::recursive_directory_iterator(kRoot + "/" + dir))
      if (e.is_regular_file()) files.push_back(e.path());
  for (const auto& p : files) {
    Syntax syntax;
    if (!is_source(p, syntax) || std::filesystem::equivalent(p, self)) continue;
    for (const std::string& o : comment_offences(from_root(p), read(p), syntax))
      ADD_FAILURE() << o << ": say what the program does and why; figures go to docs/performance.md";
  }
}

TEST(HouseRules, ReadmesDescribeTheProgram) {
  for (const char* name : {"README.md", "tests/README.md"})
    for (const std::string& o : prose_offences(name, read(kRoot + "/" + name)))
      ADD_FAILURE() << o << ": say what the program does and how to use it, not the history of the work";
}

TEST(HouseRules, DocsDateOnlyMeasurements) {
  for (const auto& e : std::filesystem::recursive_directory_iterator(kRoot + "/docs"))
    if (e.is_regular_file() && e.path().extension() == ".md")
      for (const std::string& o : doc_offences(from_root(e.path()), read(e.path())))
        ADD_FAILURE() << o << ": a date belongs only in a table column headed \"measured on\"";
}

// The checker catches planted dates and narration, and leaves the program's own words alone.
TEST(HouseRules, TextCheckerSeesDatesAndNarration) {
  for (const char* bad : {"measured on 2026-11-27", "27/11/2026", "on 27 November", "27th Nov", "November 27",
                          "Nov 27th", "in November 2026", "May 3, 2026", "Dec. 3", "the issue asks for it",
                          "the issue also asks", "issue 14 item 4", "(Issue #12)", "a work item", "this session",
                          "an earlier session measured", "an earlier revision measured 3 ms", "the previous commit",
                          "we measured 2.5 ms", "who ran which runs", "blitted as before", "as before HDR",
                          "drawn before HDR existed", "it used to blit", "Used to draw twice"})
    EXPECT_NE(offence(bad, true), "") << bad;
  for (const char* fine : {"GL issues 3 draws", "the issues it raises", "within 5/255 of the reference",
                           "1280x720 at 60 Hz", "a live session records", "the session ends", "an earlier frame",
                           "is used to aim", "are used to blend", "a loop no longer asked for fades out",
                           "it was drawn", "May 3 ships collide", "version 3.3 core", "16.7 ms at 60 Hz",
                           "the last build step", "before the HUD"})
    EXPECT_EQ(offence(fine, true), "") << fine;
  EXPECT_EQ(offence("the issue asks", false), "");  // docs: dates only
}

// Comments are found in each syntax, and string literals are not comments.
TEST(HouseRules, TextCheckerReadsCommentsOnly) {
  const std::string cpp =
      "int a = 1'000;  // fine\n"
      "const char* s = \"issue 14 // as before\";\n"
      "const char* r = R\"x(\n// as before\n)x\";\n"
      "/* a block\n   written 2026-11-27 */\n"
      "int b = 0;  // as before\n";
  const std::vector<std::string> c = comment_offences("f.cpp", cpp, Syntax::C);
  ASSERT_EQ(c.size(), 2u) << ::testing::PrintToString(c);
  EXPECT_NE(c[0].find("f.cpp:7:"), std::string::npos) << c[0];
  EXPECT_NE(c[1].find("f.cpp:8:"), std::string::npos) << c[1];

  const std::string sh =
      "#!/bin/sh\n"
      "echo \"issue 14 # as before\" $# ${#x}\n"
      "x=1  # the issue asks\n";
  const std::vector<std::string> s = comment_offences("f.sh", sh, Syntax::Hash);
  ASSERT_EQ(s.size(), 1u) << ::testing::PrintToString(s);
  EXPECT_NE(s[0].find("f.sh:3:"), std::string::npos) << s[0];

  const std::string py = "def f():\n    \"\"\"Draws it\n    as before.\"\"\"\n    return '#'  # fine\n";
  const std::vector<std::string> p = comment_offences("f.py", py, Syntax::Python);
  ASSERT_EQ(p.size(), 1u) << ::testing::PrintToString(p);
  EXPECT_NE(p[0].find("f.py:3:"), std::string::npos) << p[0];
}

// A date in a document stands only under a "measured on" column.
TEST(HouseRules, TextCheckerAllowsMeasuredOnColumns) {
  const std::string ok =
      "| figure | value | measured on |\n"
      "|---|---|---|\n"
      "| frame | 3.1 ms | 2026-11-27 |\n";
  EXPECT_TRUE(doc_offences("d.md", ok).empty());
  const std::string other_column =
      "| figure | value | measured on |\n"
      "|---|---|---|\n"
      "| frame, 2026-11-20 | 3.1 ms | 2026-11-27 |\n";
  EXPECT_EQ(doc_offences("d.md", other_column).size(), 1u);
  const std::string no_column =
      "| figure | value | machine |\n"
      "|---|---|---|\n"
      "| frame | 3.1 ms | 2026-11-27 |\n";
  EXPECT_EQ(doc_offences("d.md", no_column).size(), 1u);
  const std::string prose = ok + "\nRun on 27 November 2026.\n";
  EXPECT_EQ(doc_offences("d.md", prose).size(), 1u);
}

}  // namespace
