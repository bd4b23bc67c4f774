// Mod folders over the data root: a mod's file replaces the base's, new files add, listings
// are the union with the topmost file winning, and bad mod folders are refused in one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "core/data_layers.h"
#include "core/data_root.h"
#include "core/error.h"

namespace arc {
namespace {
namespace fs = std::filesystem;

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

struct DataLayersTest : ::testing::Test {
  fs::path dir = fs::temp_directory_path() / ("arcfire_layers_" + std::to_string(::getpid()));
  fs::path base = dir / "base", mod_a = dir / "mod_a", mod_b = dir / "mod_b";
  void SetUp() override {
    fs::remove_all(dir);
    write(base / "assets/effects/spark.json", "base spark");
    write(base / "assets/effects/smoke.json", "base smoke");
    write(base / "levels/duel.json", "base duel");
    write(mod_a / "assets/effects/spark.json", "a spark");
    write(mod_a / "assets/effects/flare.json", "a flare");
    write(mod_b / "assets/effects/spark.json", "b spark");
    write(mod_b / "levels/rally.json", "b rally");
  }
  void TearDown() override {
    use_data_layers(DataLayers());
    fs::remove_all(dir);
  }
};

TEST_F(DataLayersTest, TopmostFileWinsAndNewFilesAdd) {
  DataLayers layers(base.string());
  layers.add_mod(mod_a.string());
  layers.add_mod(mod_b.string());
  EXPECT_EQ(layers.file("assets/effects/spark.json"), (mod_b / "assets/effects/spark.json").string());
  EXPECT_EQ(layers.file("assets/effects/flare.json"), (mod_a / "assets/effects/flare.json").string());
  EXPECT_EQ(layers.file("assets/effects/smoke.json"), (base / "assets/effects/smoke.json").string());
  EXPECT_EQ(layers.file("assets/effects/none.json"), (base / "assets/effects/none.json").string());
  const std::vector<std::string> effects = layers.files("assets/effects", ".json");
  ASSERT_EQ(effects.size(), 3u);
  EXPECT_EQ(effects[0], (mod_a / "assets/effects/flare.json").string());
  EXPECT_EQ(effects[1], (base / "assets/effects/smoke.json").string());
  EXPECT_EQ(effects[2], (mod_b / "assets/effects/spark.json").string());
  EXPECT_EQ(layers.dirs("levels").size(), 2u);  // base and mod_b
  EXPECT_EQ(layers.mod_of((mod_b / "levels/rally.json").string()), "mod_b");
  EXPECT_EQ(layers.mod_of((base / "levels/duel.json").string()), "");
}

TEST_F(DataLayersTest, OnlyTheBaseInUseSeesTheMods) {
  DataLayers layers(base.string());
  layers.add_mod(mod_a.string());
  use_data_layers(layers);
  EXPECT_EQ(data_file(base.string() + "/", "assets/effects/spark.json"), (mod_a / "assets/effects/spark.json").string());
  EXPECT_EQ(data_file(mod_b.string(), "assets/effects/spark.json"), (mod_b / "assets/effects/spark.json").string());
  EXPECT_EQ(data_files(base.string(), "assets/effects", ".json").size(), 3u);
  // A folder within the base (the renderer's shaders/) resolves through the layers too.
  EXPECT_EQ(data_file((base / "assets/effects").string(), "spark.json"), (mod_a / "assets/effects/spark.json").string());
  EXPECT_EQ(data_file((base / "assets/effects").string(), "smoke.json"), (base / "assets/effects/smoke.json").string());
  EXPECT_EQ(data_file(base.string() + "_other", "levels/duel.json"), base.string() + "_other/levels/duel.json");
}

TEST_F(DataLayersTest, ContentHashFollowsEveryByteAndName) {
  DataLayers one(base.string());
  one.add_mod(mod_a.string());
  const uint64_t before = one.mods()[0].hash;
  write(mod_a / "assets/effects/flare.json", "a flarf");
  DataLayers two(base.string());
  two.add_mod(mod_a.string());
  EXPECT_NE(two.mods()[0].hash, before);
  fs::rename(mod_a / "assets/effects/flare.json", mod_a / "assets/effects/flarf.json");
  DataLayers three(base.string());
  three.add_mod(mod_a.string());
  EXPECT_NE(three.mods()[0].hash, two.mods()[0].hash);
}

TEST_F(DataLayersTest, BadModFoldersAreRefused) {
  DataLayers layers(base.string());
  EXPECT_THROW(layers.add_mod((dir / "missing").string()), InputError);
  write(dir / "file_mod", "not a folder");
  EXPECT_THROW(layers.add_mod((dir / "file_mod").string()), InputError);
  fs::create_directories(dir / "empty_mod/other");
  try {
    layers.add_mod((dir / "empty_mod").string());
    FAIL() << "a folder without data folders was taken as a mod";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("assets/, levels/, shaders/"), std::string::npos) << e.what();
  }
  layers.add_mod(mod_a.string());
  EXPECT_THROW(layers.add_mod(mod_a.string() + "/"), InputError);  // the same name twice
}

// The banner's example, with the example mod of examples/mods.
TEST(DataLayersExample, LayAMod) {
  const std::string mod_dir = build_source_tree() + "/examples/mods/red_rally";
  DataLayers layers(data_root());
  layers.add_mod(mod_dir);  // InputError: not a folder, not a mod
  use_data_layers(layers);
  const std::string ship = data_file(data_root(), "assets/ships/viper_mk2.json");  // the mod's
  use_data_layers(DataLayers());
  EXPECT_NE(ship.find("examples/mods/red_rally/assets/ships/viper_mk2.json"), std::string::npos) << ship;
}

TEST_F(DataLayersTest, LinkLoopInAModIsNoTrap) {
  fs::create_directory_symlink(mod_a, mod_a / "assets/loop");
  DataLayers layers(base.string());
  layers.add_mod(mod_a.string());
  EXPECT_EQ(layers.files("assets/effects", ".json").size(), 3u);
}

}  // namespace
}  // namespace arc
