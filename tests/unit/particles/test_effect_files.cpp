// Effect files: the shipped ones load; each bad case gives one positioned line.
#include <gtest/gtest.h>

#include <regex>

#include "core/error.h"
#include "particles/effect_library.h"
#include "core/data_layers.h"
#include "core/data_root.h"

namespace arc {
namespace {

std::string load_error(const std::string& text) {
  EffectLibrary lib;
  try {
    lib.load_text(text, "bad.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kGood = R"({
  "clusters": [
    { "sprite": "spark", "animation": { "type": "linear", "drag": 1 },
      "emitter": { "shape": "point", "burst": 3 },
      "particles": { "lifetime": [0.5, 1] } }
  ]
})";

std::string with(const std::string& from, const std::string& to) {
  std::string s = kGood;
  const size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

// "line:col" of the n-th occurrence of a token in the text (1-based), where the error must point.
std::string position_of(const std::string& text, const std::string& token, int occurrence = 1) {
  size_t at = std::string::npos;
  for (int i = 0; i < occurrence; ++i) at = text.find(token, at == std::string::npos ? 0 : at + 1);
  EXPECT_NE(at, std::string::npos) << token;
  int line = 1, col = 1;
  for (size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') ++line, col = 1;
    else ++col;
  }
  return std::to_string(line) + ":" + std::to_string(col);
}

void expect_error(const std::string& text, const std::string& token, const std::string& words) {
  const std::string position = position_of(text, token);
  const std::string e = load_error(text);
  ASSERT_FALSE(e.empty()) << "no error for:\n" << text;
  EXPECT_EQ(e.rfind("bad.json:" + position + ": ", 0), 0u) << e;
  EXPECT_NE(e.find(words), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST(EffectFiles, ShippedEffectsLoad) {
  EffectLibrary lib;
  lib.load_directory("assets/effects");
  for (const char* n : {"lightning_beam", "shield_sphere", "shield_hit", "hull_sparks", "ship_explosion", "engine_exhaust",
                        "missile_trail", "plasma_bolt", "flare"})
    EXPECT_TRUE(lib.has(n)) << n;
  const EffectDef& boom = lib.get("ship_explosion");
  bool burns_to_smoke = false;
  for (const ClusterDef& c : boom.clusters)
    burns_to_smoke |= c.burn.exact(0.0f) == 1.0f && c.burn.exact(1.0f) == 0.0f;
  EXPECT_TRUE(burns_to_smoke);
}

// The example mod (examples/mods/red_rally) laid over the data: its shield hit replaces the
// game's blue one with gold, its rally beacon joins the game's effects, the rest stay the game's.
TEST(EffectFiles, ExampleModReplacesAndAddsEffects) {
  const std::string root = arc::data_root();
  DataLayers layers(root);
  layers.add_mod(arc::build_source_tree() + "/examples/mods/red_rally");
  use_data_layers(layers);
  EffectLibrary lib;
  lib.load_directory(root + "/assets/effects");
  use_data_layers(DataLayers());
  ASSERT_TRUE(lib.has("rally_beacon"));
  EXPECT_TRUE(lib.has("ship_explosion"));
  const ClusterDef& flash = lib.get("shield_hit").clusters.at(0);
  EXPECT_GT(flash.red.exact(0.0f), flash.blue.exact(0.0f));  // gold: the base file's is blue-white
  EffectLibrary base;
  base.load_directory(root + "/assets/effects");
  EXPECT_FALSE(base.has("rally_beacon"));
  const ClusterDef& blue = base.get("shield_hit").clusters.at(0);
  EXPECT_LT(blue.red.exact(0.0f), blue.blue.exact(0.0f));
}

TEST(EffectFiles, GoodTextLoads) {
  EXPECT_EQ(load_error(kGood), "");
}

TEST(EffectFiles, UnknownKey) { expect_error(with("\"drag\": 1", "\"darg\": 1"), "\"darg\"", "unknown key 'darg'"); }

TEST(EffectFiles, WrongType) { expect_error(with("\"drag\": 1", "\"drag\": \"fast\""), "\"fast\"", "must be a number"); }

TEST(EffectFiles, NegativeLifetime) {
  expect_error(with("\"lifetime\": [0.5, 1]", "\"lifetime\": [-0.5, 1]"), "-0.5", "must be in [0, 3600]");
}

TEST(EffectFiles, ZeroLinearLifetime) {
  expect_error(with("\"lifetime\": [0.5, 1]", "\"lifetime\": 0"), "\"particles\"", "need a 'lifetime' in (0, 600]");
}

TEST(EffectFiles, BurnOutsideZeroOne) {
  expect_error(with("\"lifetime\": [0.5, 1] }", "\"lifetime\": [0.5, 1] }, \"curves\": { \"burn\": [[0, 1.5]] }"), "1.5",
               "'clusters[0].curves.burn' values must be in [0, 1]");
}

// Curves run in float: times apart in the file but one float would be a step nobody wrote.
// Equal times (a step written as one) stay allowed.
TEST(EffectFiles, KeyTimesEqualInFloatAreRefused) {
  const std::string alpha = "\"curves\": { \"alpha\": [[0, 1], [0.1000000001, 1], [0.1000000002, 0.5], [1, 0]] }";
  expect_error(with("\"lifetime\": [0.5, 1] }", "\"lifetime\": [0.5, 1] }, " + alpha), "0.1000000002",
               "'clusters[0].curves.alpha[2][0]': key times 0.1000000001 and 0.1000000002 are the same in single "
               "precision; allowed: times equal (a step) or apart as floats (about 1e-7 near 1)");
  const std::string step = "\"curves\": { \"alpha\": [[0, 1], [0.5, 1], [0.5, 0.2], [1, 0]] }";
  EXPECT_EQ(load_error(with("\"lifetime\": [0.5, 1] }", "\"lifetime\": [0.5, 1] }, " + step)), "");
}

TEST(EffectFiles, ZeroLengthSeedSegment) {
  const std::string text = R"({ "clusters": [ { "sprite": "spark",
    "animation": { "type": "lightning", "seed_length": 0, "max_length": 100 } } ] })";
  expect_error(text, "0, \"max", "zero-length seed");
}

TEST(EffectFiles, NaNIsRejected) { expect_error(with("\"drag\": 1", "\"drag\": NaN"), "NaN", "invalid JSON"); }

TEST(EffectFiles, InfinityIsRejected) {
  expect_error(with("\"drag\": 1", "\"drag\": 1e999"), "1e999", "finite");
}

TEST(EffectFiles, UnknownSpriteListsAllowed) {
  expect_error(with("\"spark\"", "\"sparkle\""), "\"sparkle\"", "\"blob\", \"flare\"");
}

TEST(EffectFiles, UnknownShapeAndSoftEdge) {
  expect_error(with("\"point\"", "\"donut\""), "\"donut\"", "\"mesh\"");
  expect_error(with("\"sprite\": \"spark\",", "\"sprite\": \"spark\", \"soft_edge\": \"fuzzy\","), "\"fuzzy\"",
               "\"density_extent\"");
}

TEST(EffectFiles, ScreenPriorityIsLowNormalOrHigh) {
  expect_error(with("\"sprite\": \"spark\",", "\"sprite\": \"spark\", \"screen_priority\": \"urgent\","), "\"urgent\"",
               "\"low\", \"normal\"");
  EffectLibrary lib;
  lib.load_directory(arc::data_root() + "/assets/effects");
  EXPECT_EQ(lib.get("lightning_beam").clusters[0].screen_priority, ScreenPriority::High);
  EXPECT_EQ(lib.get("hull_sparks").clusters[0].screen_priority, ScreenPriority::Low);
  EXPECT_EQ(lib.get("shield_sphere").clusters[0].screen_priority, ScreenPriority::Normal);
}

TEST(EffectFiles, KeyframesMustNotGoBack) {
  expect_error(with("\"lifetime\": [0.5, 1] }", "\"lifetime\": [0.5, 1] }, \"curves\": { \"alpha\": [[0.5, 1], [0.2, 0]] }"),
               "0.2, 0]", "must not decrease");
}

TEST(EffectFiles, MeshNeedsWholeTriangles) {
  expect_error(with("\"shape\": \"point\"", "\"shape\": \"mesh\", \"triangles\": [[0,0,0],[1,0,0]]"), "[[0,0,0]",
               "3 vertices [x, y, z] per triangle");
}

TEST(EffectFiles, EmitterNeedsRateBurstOrSpacing) {
  expect_error(with("\"burst\": 3", "\"rate\": 0"), "{ \"shape\"", "'rate', 'burst' or 'spacing' > 0");
}

TEST(EffectFiles, SpacingIsForWorldSpaceLinearClustersAndNotTooFine) {
  expect_error(with("\"burst\": 3", "\"spacing\": 0.001"), "\"spacing\"", "at least 0.01 m");
  expect_error(with("\"burst\": 3", "\"spacing\": -1"), "-1", "must be in [0,");
  const std::string owner_space = R"({ "clusters": [ { "sprite": "smoke", "space": "owner", "animation": { "type": "linear" },
    "emitter": { "spacing": 1 }, "particles": { "lifetime": 1 } } ] })";
  expect_error(owner_space, "\"spacing\"", "needs a world-space linear cluster");
}

TEST(EffectFiles, VelocityBillboardsAndTheirStretch) {
  EXPECT_EQ(load_error(with("\"sprite\": \"spark\",", "\"sprite\": \"spark\", \"billboard\": \"velocity\", \"stretch\": 0.02,")), "");
  expect_error(with("\"sprite\": \"spark\",", "\"sprite\": \"spark\", \"billboard\": \"sideways\","), "\"sideways\"",
               "\"camera\" or \"velocity\"");
  expect_error(with("\"sprite\": \"spark\",", "\"sprite\": \"spark\", \"stretch\": 0.02,"), "\"stretch\"",
               "applies to \"billboard\": \"velocity\" only");
  expect_error(with("\"sprite\": \"spark\",", "\"sprite\": \"spark\", \"billboard\": \"velocity\", \"stretch\": -1,"), "-1",
               "must be in [0, 10]");
  expect_error(with("\"sprite\": \"spark\",", "\"sprite\": \"spark\", \"billboard\": \"velocity\", \"space\": \"owner\","),
               "\"billboard\"", "needs a world-space linear cluster");
}

TEST(EffectFiles, FreeLightningNeedsALifetime) {
  const std::string text = R"({ "clusters": [ { "sprite": "flare",
    "animation": { "type": "lightning", "seed_length": 5, "max_length": 100, "free_lifetime": 0 } } ] })";
  expect_error(text, "0 }", "'clusters[0].animation.free_lifetime' must be in [0.01");
}

TEST(EffectFiles, MissingFileAndFolder) {
  EffectLibrary lib;
  EXPECT_THROW(lib.load_file("assets/effects/none.json"), InputError);
  EXPECT_THROW(lib.load_directory("assets/no_such_folder"), InputError);
  EXPECT_THROW(lib.get("none"), InputError);
}

}  // namespace
}  // namespace arc
