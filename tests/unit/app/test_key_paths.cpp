// Every loader names a bad value by its whole key path from the top of the file
// (core/json.h JsonValue::name): an element of a nested array is `beam.mounts[1][0]`, not
// `'0[0]'`. One test per loader kind, each checking the exact line.
#include <gtest/gtest.h>

#include <string>

#include "core/data_root.h"
#include "core/error.h"
#include "core/settings.h"
#include "game/app/all_settings.h"
#include "game/app/input_bindings.h"
#include "game/sim/defs.h"
#include "particles/effect_library.h"

namespace arc {
namespace {

template <typename F>
std::string error_of(F load) {
  try {
    load();
  } catch (const InputError& e) {
    return e.what();
  }
  return "loaded";
}

TEST(KeyPaths, LevelNamesTheShipAndTheCoordinate) {
  const std::string text = R"({
  "name": "n", "objective": "o",
  "win": { "type": "destroy_all_hostiles" }, "lose": { "type": "player_destroyed" },
  "ships": [
    { "name": "P", "class": "viper", "team": "blue", "player": true },
    { "name": "R", "class": "viper", "team": "red", "position": [0, 5e9, 0] }
  ]
})";
  EXPECT_EQ(error_of([&] { parse_level_def(text, "l.json", data_root()); }),
            "l.json:6:69: 'ships[1].position[1]' must be in [-1073741824, 1073741824], got 5e+09");
}

TEST(KeyPaths, ShipClassNamesTheMountAndItsCoordinate) {
  const std::string text = R"({
  "model": "assets/models/viper.glb", "mass": 10, "thrust": 10, "max_speed": 10, "hull": 10,
  "collision_radius": 2,
  "beam": { "mounts": [[0, 0, 0], [500, 0, 0]] }
})";
  EXPECT_EQ(error_of([&] { parse_ship_class(text, "s.json", "s"); }),
            "s.json:4:36: 'beam.mounts[1][0]' must be in [-100, 100], got 500");
}

TEST(KeyPaths, EffectNamesTheClusterAndTheTriangleVertex) {
  const std::string text = R"({ "clusters": [
  { "sprite": "glow", "animation": { "type": "linear" }, "emitter": { "burst": 5 } },
  { "sprite": "glow", "animation": { "type": "linear" },
    "emitter": { "burst": 5, "shape": "mesh", "triangles": [[0, 0, 0], [1, 0, 0], [0, "x", 0]] } }
] })";
  EffectLibrary lib;
  EXPECT_EQ(error_of([&] { lib.load_text(text, "e.json"); }),
            "e.json:4:87: 'clusters[1].emitter.triangles[2][1]' must be a number in [-1e+06, 1e+06], got a string");
}

TEST(KeyPaths, QualityPresetNamesThePresetAndTheSetting) {
  const std::string text = R"({ "presets": {
  "low": { "render.scale": 0.5 },
  "high": { "render.scale": 1.0, "render.sky_resolution": 99999 }
} })";
  Settings s = all_settings();
  EXPECT_EQ(error_of([&] { s.apply_preset_text(text, "q.json", "high"); }),
            "q.json:3:34: 'presets.high[\"render.sky_resolution\"]' must be an integer in [16, 1024], got '99999'");
}

TEST(KeyPaths, BindingsNameTheAxisAndItsKey) {
  const std::string text = R"({ "keyboard": {
  "pitch": ["UP", "DOWNN"]
} })";
  EXPECT_EQ(error_of([&] { parse_bindings(text, "b.json"); }),
            "b.json:2:19: 'keyboard.pitch[1]': unknown key 'DOWNN' (see the list at the top of the bindings file)");
}

}  // namespace
}  // namespace arc
