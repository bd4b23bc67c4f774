// The usage example of engine/replay/script.h's banner as a test (HeaderExamples.MatchTheirTests
// in tests/unit/core keeps the two the same text).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "game/app/all_settings.h"
#include "replay/script.h"
#include "core/data_root.h"

namespace arc::replay {
namespace {

TEST(ScriptExample, LoadWalkWrite) {
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(arc::build_source_tree());
  std::vector<uint64_t> ticks;

  const Settings known = all_settings();                        // game/app/all_settings.h
  Script s = load_script("tests/replays/range_course.replay", known);  // or parse_script(text, path, known)
  for (const InputEvent& e : s.inputs) ticks.push_back(e.tick);  // in tick order
  std::string text = write_script(s);                           // parse(write(s)) == s

  std::filesystem::current_path(cwd);
  EXPECT_FALSE(ticks.empty());
  EXPECT_TRUE(std::is_sorted(ticks.begin(), ticks.end()));
  const Script again = parse_script(text, s.path, known);  // the canonical text is a fixed point
  EXPECT_EQ(again.inputs.size(), s.inputs.size());
  EXPECT_EQ(write_script(again), text);
}

}  // namespace
}  // namespace arc::replay
