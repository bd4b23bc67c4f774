// Splicing edits into JSON text: formatting of new values and the layouts edits meet.
#include <gtest/gtest.h>

#include "core/error.h"
#include "game/workbench/json_splice.h"

namespace arc {
namespace {

using nlohmann::json;

TEST(JsonSplice, FormatsWholeNumbersShortArraysAndLongObjects) {
  EXPECT_EQ(format_json(120.0, "", "  "), "120");
  EXPECT_EQ(format_json(0.25, "", "  "), "0.25");
  EXPECT_EQ(format_json(json::array({json::array({0, 1}), json::array({1, 0})}), "", "  "), "[[0, 1], [1, 0]]");
  EXPECT_EQ(format_json(json{{"burst", 3}, {"shape", "point"}}, "", "  "), "{ \"burst\": 3, \"shape\": \"point\" }");
  EXPECT_EQ(format_json(json{{"emitter", json{{"burst", 3}}}, {"name", "x"}}, "    ", "  "),
            "{\n      \"emitter\": { \"burst\": 3 },\n      \"name\": \"x\"\n    }");
}

TEST(JsonSplice, ReplacesOnlyTheValuesBytes) {
  const std::string text = "{\n  \"a\": 1, // one\n  \"b\": [1,2]\n}";
  EXPECT_EQ(splice_set(text, "t.json", "/a", 7), "{\n  \"a\": 7, // one\n  \"b\": [1,2]\n}");
  EXPECT_EQ(splice_set(text, "t.json", "/b/1", 2.5), "{\n  \"a\": 1, // one\n  \"b\": [1,2.5]\n}");
}

TEST(JsonSplice, AppendsAfterATrailingCommentWithoutSwallowingIt) {
  const std::string text = "{\n  \"a\": 1 // one\n}";
  EXPECT_EQ(splice_set(text, "t.json", "/b", true), "{\n  \"a\": 1, // one\n  \"b\": true\n}");
}

TEST(JsonSplice, InsertsIntoEmptyAndInlineArrays) {
  EXPECT_EQ(splice_insert("{ \"k\": [] }", "t.json", "/k", 0, 3), "{ \"k\": [3] }");
  EXPECT_EQ(splice_insert("{ \"k\": [1, 3] }", "t.json", "/k", 1, 2), "{ \"k\": [1, 2, 3] }");
  EXPECT_EQ(splice_insert("{ \"k\": [1, 3] }", "t.json", "/k", 0, 0), "{ \"k\": [0, 1, 3] }");
}

TEST(JsonSplice, RemovesInlineElementsWithTheirSeparator) {
  EXPECT_EQ(splice_remove("[1, 2, 3]", "t.json", "/0"), "[2, 3]");
  EXPECT_EQ(splice_remove("[1, 2, 3]", "t.json", "/2"), "[1, 2]");
  EXPECT_EQ(splice_remove("[1]", "t.json", "/0"), "[]");
  EXPECT_EQ(splice_remove("{ \"a\": 1, \"b\": 2 }", "t.json", "/b"), "{ \"a\": 1 }");
}

TEST(JsonSplice, MovesAndDuplicatesElementTextWithItsComments) {
  const std::string text = "[\n  { \"n\": 1 /* one */ },\n  { \"n\": 2 },\n  { \"n\": 3 }\n]";
  EXPECT_EQ(splice_move(text, "t.json", "", 0, 2), "[\n  { \"n\": 2 },\n  { \"n\": 3 },\n  { \"n\": 1 /* one */ }\n]");
  EXPECT_EQ(splice_move(text, "t.json", "", 2, 0), "[\n  { \"n\": 3 },\n  { \"n\": 1 /* one */ },\n  { \"n\": 2 }\n]");
  EXPECT_EQ(splice_duplicate(text, "t.json", "/0"),
            "[\n  { \"n\": 1 /* one */ },\n  { \"n\": 1 /* one */ },\n  { \"n\": 2 },\n  { \"n\": 3 }\n]");
}

TEST(JsonSplice, PointersThatNameNothingAreErrorsNamingTheFile) {
  EXPECT_THROW(splice_set("{}", "t.json", "no-slash", 1), InputError);
  EXPECT_THROW(splice_remove("{}", "t.json", "/missing"), InputError);
  EXPECT_THROW(splice_insert("{ \"a\": 1 }", "t.json", "/a", 0, 1), InputError);
  EXPECT_THROW(splice_move("[1, 2]", "t.json", "", 0, 2), InputError);
  try {
    splice_set("{ \"a\": [1] }", "t.json", "/a/3/b", 1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "t.json: no value at '/a/3/b'");
  }
}

}  // namespace
}  // namespace arc
