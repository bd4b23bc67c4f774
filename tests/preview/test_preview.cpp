// Filmstrips of two effects against their goldens, and what stats.json says about them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "assets/image.h"
#include "core/json.h"
#include "game/app/effect_preview.h"
#include "gfx/image_compare.h"
#include "core/data_root.h"

namespace arc {
namespace {

const std::string kRoot = arc::data_root();

std::string out_dir(const std::string& name) {
  const char* base = std::getenv("ARCFIRE_PREVIEW_OUT");
  return (std::filesystem::path(base ? base : "build/preview-out") / name).string();
}

// Renders the filmstrip and compares it with tests/preview/golden/<name>.png (or rewrites the
// golden under ARCFIRE_UPDATE_GOLDEN=1); returns stats.json.
nlohmann::json filmstrip_matches_golden(const std::string& name, PreviewOptions o) {
  o.out_dir = out_dir(name);
  std::filesystem::remove_all(o.out_dir);
  EXPECT_EQ(run_preview(o), 0);
  const Image actual = load_image(o.out_dir + "/filmstrip.png");
  const std::string golden = arc::build_source_tree() + "/tests/preview/golden/" + name + ".png";
  const char* update = std::getenv("ARCFIRE_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") save_image(golden, actual);
  const ImageDiff d = compare_images(load_image(golden), actual);
  if (!d.passed) write_failure_images(o.out_dir + "/filmstrip", actual, load_image(golden));
  EXPECT_TRUE(d.passed) << name << ": " << d.summary() << "; actual and diff in " << o.out_dir;
  return nlohmann::json::parse(read_text_file(o.out_dir + "/stats.json"));
}

TEST(Preview, ShieldHitFilmstripMatchesItsGolden) {
  PreviewOptions o;
  o.effect_path = kRoot + "/assets/effects/shield_hit.json";
  const nlohmann::json stats = filmstrip_matches_golden("shield_hit", o);
  ASSERT_EQ(stats["frames"].size(), 8u);
  EXPECT_EQ(stats["frames"][0]["clusters"]["flash"], 24);  // the flash's burst, all alive early on
  EXPECT_GT(stats["frames"][0]["blended_pixels"].get<int64_t>(), 0);
  EXPECT_TRUE(stats["ends"].get<bool>());
  int64_t last_tick = 0;
  for (const auto& f : stats["frames"]) {
    EXPECT_GT(f["tick"].get<int64_t>(), last_tick);
    last_tick = f["tick"].get<int64_t>();
  }
}

TEST(Preview, ShipExplosionOnTheWallMatchesItsGolden) {
  PreviewOptions o;
  o.effect_path = kRoot + "/assets/effects/ship_explosion.json";
  o.backdrop = "wall";
  o.frames = 5;
  o.frame_width = 256;
  o.frame_height = 192;
  const nlohmann::json stats = filmstrip_matches_golden("ship_explosion_wall", o);
  ASSERT_EQ(stats["frames"].size(), 5u);
  EXPECT_EQ(stats["frame_size"], nlohmann::json::array({256, 192}));
  EXPECT_GT(stats["frames"][0]["particles"].get<int64_t>(), stats["frames"][4]["particles"].get<int64_t>());
}

// A trail laid along the emitter's path is previewed behind an owner flying a circle.
TEST(Preview, MissileTrailMatchesItsGolden) {
  PreviewOptions o;
  o.effect_path = kRoot + "/assets/effects/missile_trail.json";
  o.frames = 5;
  o.frame_width = 256;
  o.frame_height = 192;
  const nlohmann::json stats = filmstrip_matches_golden("missile_trail", o);
  ASSERT_EQ(stats["frames"].size(), 5u);
  EXPECT_FALSE(stats["ends"].get<bool>());
  EXPECT_GT(stats["frames"][4]["clusters"]["smoke"].get<int64_t>(), stats["frames"][0]["clusters"]["smoke"].get<int64_t>());
}

TEST(Preview, BackdropsAreSpaceTheWallOrAModel) {
  EXPECT_EQ(check_preview_backdrop("space", kRoot), "");
  EXPECT_EQ(check_preview_backdrop("viper", kRoot), "");
  EXPECT_EQ(check_preview_backdrop("moon", kRoot),
            "--backdrop: must be space, wall, asteroid, corvette, dart, viper or warden, got 'moon'");
}

}  // namespace
}  // namespace arc
