#include <gtest/gtest.h>

#include <functional>

#include "core/error.h"
#include "core/json.h"

using arc::InputError;
using arc::JsonDoc;
using arc::JsonObject;

namespace {
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}
JsonObject root_of(const std::shared_ptr<const JsonDoc>& d) { return JsonObject(d, "", &d->root()); }
}  // namespace

TEST(JsonDoc, SyntaxErrorNamesFileLineAndColumn) {
  std::string e = error_of([] { JsonDoc::parse("{\n  \"a\": 1,\n  \"b\": }\n", "x.json"); });
  EXPECT_EQ(e.rfind("x.json:3:", 0), 0u) << e;
}

// A key written twice in one object is refused with both places; the same key in two objects
// (or in two elements of an array) is not a repeat.
TEST(JsonDoc, DuplicateKeysNameBothPlaces) {
  const std::string e = error_of([] {
    JsonDoc::parse("{\n  \"rate\": 1,\n  \"inner\": { \"rate\": 2 },\n  \"rate\": 3\n}", "fx.json");
  });
  EXPECT_EQ(e, "fx.json:4:3: key 'rate' appears twice in this object (first at 2:3); allowed: each key once");
  EXPECT_NO_THROW(JsonDoc::parse("[{\"a\": 1}, {\"a\": 2}]", "list.json"));
  EXPECT_NO_THROW(JsonDoc::parse("{\"a\": {\"k\": 1}, \"b\": {\"k\": 1}}", "two.json"));
}

TEST(JsonDoc, CommentsAreAllowed) {
  auto d = JsonDoc::parse("// header\n{ /* inline */ \"a\": 1 }", "c.json");
  EXPECT_EQ(d->root()["a"], 1);
}

TEST(JsonObject, OutOfRangeValueIsReportedAtItsKey) {
  auto d = JsonDoc::parse("{\n  \"seed\": 1,\n  \"hull\": -5\n}", "lvl.json");
  std::string e = error_of([&] {
    auto r = root_of(d);
    r.number("hull", 100, 1, 1000);
  });
  EXPECT_EQ(e, "lvl.json:3:11: 'hull' must be in [1, 1000], got -5");
}

TEST(JsonObject, UnknownKeyIsRejectedWithTheAllowedOnes) {
  auto d = JsonDoc::parse("{\n  \"seed\": 1,\n    \"sede\": 2\n}", "lvl.json");
  std::string e = error_of([&] {
    auto r = root_of(d);
    r.integer("seed", 0, 0, 10);
    r.finish();
  });
  EXPECT_EQ(e, "lvl.json:3:5: unknown key 'sede'; allowed: seed");
}

TEST(JsonObject, WrongTypeMissingKeyAndHugeNumbers) {
  EXPECT_EQ(error_of([] { JsonDoc::parse("{\n \"b\": 1e999}", "h.json"); }).rfind("h.json:2:7: invalid JSON: number overflow", 0), 0u);
  auto d = JsonDoc::parse("{\"a\": \"x\", \"v\": [1, 2], \"n\": [{\"k\": true}]}", "t.json");
  EXPECT_NE(error_of([&] { root_of(d).number("a", 0, 0, 1); }).find("must be a number"), std::string::npos);
  EXPECT_NE(error_of([&] { root_of(d).vec3("v", {}, -1, 1); }).find("3 numbers"), std::string::npos);
  EXPECT_NE(error_of([&] { root_of(d).require("zz"); }).find("missing required key 'zz'"), std::string::npos);
  std::string e = error_of([&] { root_of(d).objects("n")[0].number("k", 0, 0, 1); });
  EXPECT_EQ(e.rfind("t.json:1:", 0), 0u) << e;
  EXPECT_EQ(e, "t.json:1:37: 'n[0].k' must be a number in [0, 1], got a boolean");
}

// Messages name a value by its whole key path (ships[3].position[1]), worked out from the
// document so an object key made of digits is not taken for an index.
TEST(JsonObject, KeyPathsNameTheWholeWayFromTheTop) {
  auto d = JsonDoc::parse(R"({"beam": {"mounts": [[0, 0, 0], [1, 2, 3]]}, "byid": {"7": [5]},
                              "render.scale": 1, "two words": {"a/b": [0]}})", "p.json");
  EXPECT_EQ(arc::json_key_path(d->root(), "/beam/mounts/1/0"), "beam.mounts[1][0]");
  EXPECT_EQ(arc::json_key_path(d->root(), "/byid/7/0"), "byid.7[0]");
  EXPECT_EQ(arc::json_key_path(d->root(), "/render.scale"), "[\"render.scale\"]");
  EXPECT_EQ(arc::json_key_path(d->root(), "/two words/a~1b/0"), "[\"two words\"][\"a/b\"][0]");
  EXPECT_EQ(arc::json_key_path(d->root(), ""), "document");
  const std::string e = error_of([&] {
    arc::JsonObject beam = root_of(d).require_object("beam");
    for (const arc::JsonValue& m : beam.require("mounts").array()) m.vec3(-1, 1);
  });
  EXPECT_EQ(e, "p.json:1:37: 'beam.mounts[1][1]' must be in [-1, 1], got 2");
}

TEST(JsonObject, IntegersRejectFractions) {
  auto d = JsonDoc::parse("{\"n\": 2.5, \"m\": 3.0}", "i.json");
  EXPECT_NE(error_of([&] { root_of(d).integer("n", 0, 0, 10); }).find("integer"), std::string::npos);
  EXPECT_EQ(root_of(d).integer("m", 0, 0, 10), 3);
}

TEST(JsonObject, ChoiceListsAllowedValues) {
  auto d = JsonDoc::parse("{\"mode\": \"fast\"}", "m.json");
  std::string e = error_of([&] { root_of(d).choice("mode", "a", {"a", "b"}); });
  EXPECT_NE(e.find("one of \"a\" or \"b\""), std::string::npos) << e;
}

TEST(JsonFiles, MissingFileIsAnInputError) {
  EXPECT_NE(error_of([] { JsonDoc::load_file("/nonexistent/x.json"); }).find("/nonexistent/x.json"),
            std::string::npos);
}

// Byte spans of keys and values, for edits that splice text in place (the effect workbench).
TEST(JsonDoc, RecordsTheByteSpanOfEveryKeyAndValue) {
  const std::string text = "// c\n{ \"a\": [1.5,-2e3], \"b\": {\"s\": \"x\\\"y\", \"t\": true} /* d */, \"n\": null}";
  auto d = JsonDoc::parse(text, "s.json");
  auto value = [&](const std::string& p) {
    arc::TextSpan s;
    EXPECT_TRUE(d->value_span(p, s)) << p;
    return text.substr(s.begin, s.end - s.begin);
  };
  EXPECT_EQ(value("/a/0"), "1.5");
  EXPECT_EQ(value("/a/1"), "-2e3");  // a number straight before ']'
  EXPECT_EQ(value("/a"), "[1.5,-2e3]");
  EXPECT_EQ(value("/b/s"), "\"x\\\"y\"");
  EXPECT_EQ(value("/b/t"), "true");
  EXPECT_EQ(value("/b"), "{\"s\": \"x\\\"y\", \"t\": true}");
  EXPECT_EQ(value("/n"), "null");
  EXPECT_EQ(value(""), text.substr(5));
  arc::TextSpan k;
  ASSERT_TRUE(d->key_span("/b/t", k));
  EXPECT_EQ(text.substr(k.begin, k.end - k.begin), "\"t\"");
  EXPECT_FALSE(d->value_span("/zz", k));
}
