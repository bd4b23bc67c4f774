// The player's settings and progress files (game/app/user_settings.h) and key remapping
// (game/app/key_remap.h): round trips, atomic writes, bad files kept as .bak, conflicts.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/file_writer.h"
#include "core/json.h"
#include "game/app/key_remap.h"
#include "game/app/user_settings.h"
#include "platform/platform.h"
#include "core/data_root.h"

namespace arc {
namespace {

namespace fs = std::filesystem;
const std::string kRoot = arc::data_root();
const std::string kQuality = kRoot + "/assets/settings/quality.json";

// A fresh folder under the build's temp dir for each test.
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name) {
    path = fs::temp_directory_path() / ("arcfire_user_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string str() const { return path.string(); }
};

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(UserSettings, RoundTripThroughTheFolder) {
  TempDir dir("roundtrip");
  UserSettings s;
  s.quality = "high";
  s.mouse_sensitivity = 0.31;
  s.invert_y = true;
  s.pad_deadzone = 0.2;
  s.fov = 75;
  s.fullscreen = true;
  s.vsync = false;
  s.developer_panel = true;
  s.keys["fire_primary"] = "SPACE";
  s.keys["strafe_up"] = "NONE";
  s.render["render.sorting"] = "cluster";
  s.render["render.scale"] = "0.75";
  Progress p;
  record_result(p, progress_key("levels/duel.json", "hard"), {true, 42.5, 1, 300, 80, 0.5, 0.25});
  save_settings(dir.str(), s);
  save_progress(dir.str(), p);
  UserFiles f = load_user_files(dir.str(), kQuality);
  EXPECT_EQ(f.message, "");
  EXPECT_EQ(f.settings, s);
  EXPECT_EQ(f.progress, p);
  EXPECT_EQ(f.progress.best.count("duel/hard"), 1u);
  EXPECT_NE(read(dir.path / "settings.json").find("\"developer_panel\": true"), std::string::npos);
}

// The developer panel's switch is a boolean; anything else is refused at its position.
TEST(UserSettings, DeveloperPanelIsAFlag) {
  EXPECT_FALSE(parse_settings("{\"format\": 1}", "s.json", {}).developer_panel);
  EXPECT_TRUE(parse_settings("{\"format\": 1, \"developer_panel\": true}", "s.json", {}).developer_panel);
  EXPECT_THROW(parse_settings("{\"format\": 1, \"developer_panel\": \"yes\"}", "s.json", {}), InputError);
}

TEST(UserSettings, MissingFilesGiveDefaultsWithoutAMessage) {
  TempDir dir("missing");
  UserFiles f = load_user_files((dir.path / "not_yet").string(), kQuality);
  EXPECT_EQ(f.message, "");
  EXPECT_EQ(f.settings, UserSettings{});
  EXPECT_TRUE(f.progress.best.empty());
}

TEST(UserSettings, ConfigFolderFollowsXdg) {
  const char* old = std::getenv("XDG_CONFIG_HOME");
  const std::string keep = old ? old : "";
  ::setenv("XDG_CONFIG_HOME", "/tmp/xdg_test", 1);
  EXPECT_EQ(user_config_dir(), "/tmp/xdg_test/arcfire");
  ::unsetenv("XDG_CONFIG_HOME");
  ::setenv("HOME", "/home/pilot", 1);
  EXPECT_EQ(user_config_dir(), "/home/pilot/.config/arcfire");
  if (old) ::setenv("XDG_CONFIG_HOME", keep.c_str(), 1);
}

// A crash between writing the temporary file and renaming it leaves the old file whole.
TEST(UserSettings, AnInterruptedAtomicWriteLeavesTheOldFile) {
  TempDir dir("atomic");
  UserSettings old_settings;
  old_settings.mouse_sensitivity = 0.2;
  save_settings(dir.str(), old_settings);
  const fs::path file = dir.path / "settings.json";
  const std::string before = read(file);
  UserSettings changed = old_settings;
  changed.mouse_sensitivity = 0.4;
  struct Crash {};
  EXPECT_THROW(write_file_atomic(file.string(), settings_json(changed), [] { throw Crash{}; }), Crash);
  EXPECT_EQ(read(file), before);
  EXPECT_EQ(load_user_files(dir.str(), kQuality).settings.mouse_sensitivity, 0.2);
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir.path)) files += e.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 1) << "the temporary file is removed";
}

TEST(UserSettings, ACorruptFileIsKeptAsBakAndReplacedByDefaults) {
  TempDir dir("corrupt");
  const fs::path file = dir.path / "settings.json";
  const std::string broken = "{ \"format\": 1, \"mouse_sensitivity\": 0.3,\n  \"fov\": \"wide\" }\n";
  std::ofstream(file) << broken;
  UserFiles f = load_user_files(dir.str(), kQuality);
  EXPECT_EQ(f.settings, UserSettings{});
  EXPECT_NE(f.message.find("settings.json:2:10: 'fov' must be a number"), std::string::npos) << f.message;
  EXPECT_NE(f.message.find("settings.json.bak"), std::string::npos) << f.message;
  EXPECT_EQ(read(dir.path / "settings.json.bak"), broken);
  EXPECT_EQ(parse_settings(read(file), file.string(), {}), UserSettings{}) << "the defaults are written in its place";
  // A progress file that is not even JSON.
  std::ofstream(dir.path / "progress.json") << "{ \"best\": ";
  UserFiles g = load_user_files(dir.str(), kQuality);
  EXPECT_NE(g.message.find("progress.json"), std::string::npos) << g.message;
  EXPECT_TRUE(fs::exists(dir.path / "progress.json.bak"));
}

TEST(UserSettings, ValuesAreValidated) {
  auto error = [](const std::string& text) {
    try {
      parse_settings(text, "s.json", {"low", "high"});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error(R"({ "format": 1, "quality": "high" })"), "");
  EXPECT_NE(error(R"({ "format": 1, "quality": "ultra" })").find("'quality' must be one of"), std::string::npos);
  EXPECT_NE(error(R"({ "format": 1, "fov": 300 })").find("s.json:1:23: 'fov' must be in [30, 120], got 300"),
            std::string::npos)
      << error(R"({ "format": 1, "fov": 300 })");
  EXPECT_NE(error(R"({ "format": 1, "keys": { "fire": "A" } })").find("unknown action 'fire'"), std::string::npos);
  EXPECT_NE(error(R"({ "format": 1, "keys": { "fire_primary": "BANANA" } })").find("must be a key name"),
            std::string::npos);
  EXPECT_NE(error(R"({ "format": 1, "render": { "render.sorting": "random" } })")
                .find("s.json:1:46: 'render[\"render.sorting\"]' must be one of"),
            std::string::npos)
      << error(R"({ "format": 1, "render": { "render.sorting": "random" } })");
  EXPECT_NE(error(R"({ "format": 1, "render": { "render.fancy": true } })").find("unknown setting 'render.fancy'"),
            std::string::npos);
  EXPECT_NE(error(R"({ "format": 2 })").find("s.json:1:13: 'format' must be 1 (the format this version writes), got 2"),
            std::string::npos);
}

TEST(UserProgress, AVictoryBeatsADefeatAndQuickerBeatsSlower) {
  Progress p;
  EXPECT_TRUE(record_result(p, "duel/normal", {false, 30, 0, 100}));
  EXPECT_FALSE(record_result(p, "duel/normal", {false, 50, 0, 50}));
  EXPECT_TRUE(record_result(p, "duel/normal", {true, 90, 1, 300}));
  EXPECT_FALSE(record_result(p, "duel/normal", {false, 10, 0, 900}));
  EXPECT_TRUE(record_result(p, "duel/normal", {true, 60, 1, 300}));
  EXPECT_EQ(p.best["duel/normal"].seconds, 60);
}

// Binding a key that another action has swaps them; nothing is left silently without a key.
TEST(KeyRemap, AConflictSwapsTheKeys) {
  Bindings b = load_bindings(kRoot + "/assets/settings/bindings.json");
  const Bindings defaults = b;
  ASSERT_EQ(bound_key(b, "strafe_up"), key_code("SPACE"));
  RemapOutcome r = remap_key(b, "fire_primary", key_code("SPACE"));
  EXPECT_TRUE(r.changed);
  EXPECT_EQ(r.conflict, "strafe_up");
  EXPECT_EQ(r.message, "SPACE was on Strafe up: Strafe up now uses MOUSE_LEFT");
  EXPECT_EQ(bound_key(b, "fire_primary"), key_code("SPACE"));
  EXPECT_EQ(bound_key(b, "strafe_up"), key_code("MOUSE_LEFT"));
  // The same key again changes nothing; a free key is no conflict.
  EXPECT_FALSE(remap_key(b, "fire_primary", key_code("SPACE")).changed);
  RemapOutcome free_key = remap_key(b, "camera", key_code("K"));
  EXPECT_EQ(free_key.conflict, "");
  EXPECT_EQ(free_key.message, "Camera: K");
  // What is saved: only what differs from the defaults, and it applies back.
  const auto overrides = key_overrides(b, defaults);
  EXPECT_EQ(overrides.size(), 3u);
  EXPECT_EQ(overrides.at("strafe_up"), "MOUSE_LEFT");
  Bindings again = defaults;
  apply_key_overrides(overrides, again);
  for (const RemapAction& a : remap_actions()) EXPECT_EQ(bound_key(again, a.id), bound_key(b, a.id)) << a.id;
  EXPECT_THROW(bound_key(b, "warp"), InputError);
}

// Gamepad actions take gamepad buttons (and swap among themselves); keys are refused for them.
TEST(KeyRemap, GamepadButtonsRemapAmongTheGamepadActions) {
  Bindings b = load_bindings(kRoot + "/assets/settings/bindings.json");
  const Bindings defaults = b;
  const int pad_a = code_of_label("PAD_A");
  ASSERT_EQ(pad_a, kPadButtonBase + gamepad_button_code("A"));
  ASSERT_EQ(bound_key(b, "pad_afterburner"), pad_a);
  RemapOutcome r = remap_key(b, "pad_fire_primary", pad_a);
  EXPECT_EQ(r.conflict, "pad_afterburner");
  EXPECT_EQ(r.message, "PAD_A was on Gamepad: afterburner: Gamepad: afterburner now uses PAD_RIGHT_BUMPER");
  EXPECT_EQ(b.pad_fire_primary, gamepad_button_code("A"));
  EXPECT_EQ(b.pad_afterburner, gamepad_button_code("RIGHT_BUMPER"));
  RemapOutcome refused = remap_key(b, "pad_camera", key_code("C"));
  EXPECT_FALSE(refused.changed);
  EXPECT_EQ(refused.message, "Gamepad: camera takes a gamepad button, not C");
  EXPECT_FALSE(remap_key(b, "camera", pad_a).changed);
  const auto overrides = key_overrides(b, defaults);
  EXPECT_EQ(overrides.at("pad_fire_primary"), "PAD_A");
  Bindings again = defaults;
  apply_key_overrides(overrides, again);
  EXPECT_EQ(again.pad_afterburner, b.pad_afterburner);
  // settings.json checks which kind of name each action takes.
  EXPECT_THROW(parse_settings(R"({ "format": 1, "keys": { "pad_camera": "SPACE" } })", "s.json", {}), InputError);
  EXPECT_THROW(parse_settings(R"({ "format": 1, "keys": { "camera": "PAD_A" } })", "s.json", {}), InputError);
  EXPECT_EQ(parse_settings(R"({ "format": 1, "keys": { "pad_camera": "PAD_Y" } })", "s.json", {}).keys.at("pad_camera"),
            "PAD_Y");
}

TEST(KeyRemap, UserSettingsApplyOverTheBindingsFile) {
  Bindings b = load_bindings(kRoot + "/assets/settings/bindings.json");
  UserSettings s;
  s.mouse_sensitivity = 0.3;
  s.invert_y = true;
  s.pad_deadzone = 0.2;
  s.keys["fire_secondary"] = "NONE";
  apply_user_settings(s, b);
  EXPECT_EQ(b.mouse_sensitivity, 0.3);
  EXPECT_TRUE(b.mouse_invert_y);
  EXPECT_TRUE(b.pad_invert_y);
  EXPECT_EQ(b.pad_deadzone, 0.2);
  EXPECT_EQ(b.fire_secondary, -1);
}

}  // namespace
}  // namespace arc
