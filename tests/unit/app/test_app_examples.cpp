// The usage examples of game/app's and game/render's header banners that need the app's
// libraries, as tests (HeaderExamples.MatchTheirTests keeps each banner and its test the same
// text).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <glm/geometric.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "core/data_root.h"
#include "core/error.h"
#include "audio/audio_engine.h"
#include "game/app/all_settings.h"
#include "game/app/audio_session.h"
#include "game/render/hud_layout.h"
#include "game/app/input_bindings.h"
#include "game/app/key_remap.h"
#include "game/app/menu.h"
#include "game/app/menu_input.h"
#include "game/app/mission_catalog.h"
#include "game/app/run_files.h"
#include "game/app/user_settings.h"
#include "game/render/menu_layout.h"
#include "game/render/sound_events.h"
#include "game/sim/game.h"
#include "game/workbench/effect_document.h"
#include "game/workbench/orbit_camera.h"
#include "game/workbench/workbench_stage.h"

namespace arc {
namespace {

const std::string kRoot = arc::data_root();

Menu make_menu() {
  Bindings b = load_bindings(kRoot + "/assets/settings/bindings.json");
  return Menu(load_mission_catalog(kRoot + "/levels", kRoot), UserFiles{}, b, b, kRoot + "/assets/settings/quality.json");
}

TEST(AppExamples, LayOutAMenu) {
  const Menu menu = make_menu();
  RenderView view;
  MenuPage page = menu.page();
  std::vector<HudBox> boxes;
  layout_menu(page, 1280, 720, view.hud, &boxes);   // appended to the frame's HUD layer
  EXPECT_FALSE(view.hud.texts.empty());
  EXPECT_FALSE(boxes.empty());
}

TEST(AppExamples, SoundsOfATick) {
  Game game = Game::load_level(kRoot + "/levels/duel.json", GameOptions{});
  const InputFrame input{};
  AudioDesc desc;
  desc.loopback = true;
  AudioEngine audio(desc);
  SoundEventTracker sounds;
  for (int tick = 0; tick < 30; ++tick) {
    game.step(input);
    for (const SoundEvent& e : sounds.collect(game.world())) audio.play(sound_cue(e));
  }
  EXPECT_EQ(game.tick(), 30u);
}

TEST(AppExamples, AudioSession) {
  const std::string root = kRoot;
  const Settings settings = all_settings();
  Game game = Game::load_level(kRoot + "/levels/duel.json", GameOptions{});
  const InputFrame frame{};
  const std::vector<Command> commands;
  const double frame_seconds = 1.0 / 60.0;
  AudioSession audio(root + "/assets/sounds/sounds.json", settings, false);
  game.step(frame, commands);  audio.after_tick(game.world());
  audio.frame(game.world(), frame_seconds);
  SUCCEED();
}

TEST(AppExamples, RadioLine) {
  AudioSession audio(kRoot + "/assets/sounds/sounds.json", all_settings(), true);
  HudState hud;
  audio.say("objective_done");          // unknown ids: false, and nothing is said
  if (auto s = audio.subtitle()) hud.subtitle = s->speaker + ": " + s->text;
  SUCCEED();
}

TEST(AppExamples, RemapAKey) {
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(kRoot);
  Bindings b = load_bindings("assets/settings/bindings.json");
  RemapOutcome r = remap_key(b, "fire_primary", key_code("SPACE"));
  // r.conflict == "strafe_up": strafe up now has MOUSE_LEFT
  std::filesystem::current_path(cwd);
  EXPECT_TRUE(r.changed);
  EXPECT_EQ(r.conflict, "strafe_up");
}

TEST(AppExamples, MenuInputs) {
  const Menu menu = make_menu();
  InputState previous, now;
  now.keys[key_code("DOWN")] = true;
  now.key_presses[key_code("DOWN")] = 1;
  std::vector<HudBox> boxes;
  std::vector<UiInput> in = menu_inputs(previous, now, menu.capturing(), boxes);
  EXPECT_FALSE(in.empty());
}

TEST(AppExamples, NextMission) {
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(kRoot);
  std::vector<MissionInfo> all = load_mission_catalog("levels", ".");
  const MissionInfo* next = next_mission(all, "levels/duel.json");   // skirmish
  std::filesystem::current_path(cwd);
  EXPECT_FALSE(all.empty());
  EXPECT_NE(next, nullptr);
}

TEST(AppExamples, UserFiles) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "app_examples_config";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const char* old = std::getenv("XDG_CONFIG_HOME");
  const std::string saved = old ? old : "";
  setenv("XDG_CONFIG_HOME", dir.c_str(), 1);
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(kRoot);
  std::vector<std::string> notices;
  UserFiles files = load_user_files(user_config_dir(), "assets/settings/quality.json");
  if (!files.message.empty()) notices.push_back(files.message);
  files.settings.mouse_sensitivity = 0.2;
  save_settings(files.dir, files.settings);
  const UserFiles again = load_user_files(user_config_dir(), "assets/settings/quality.json");
  std::filesystem::current_path(cwd);
  if (old) setenv("XDG_CONFIG_HOME", saved.c_str(), 1);
  else unsetenv("XDG_CONFIG_HOME");
  EXPECT_TRUE(notices.empty());
  EXPECT_DOUBLE_EQ(again.settings.mouse_sensitivity, 0.2);
}

TEST(AppExamples, OrbitCamera) {
  const double dx_pixels = 30, dy_pixels = -10, wheel_steps = 2, radius = 12;
  const glm::dvec3 centre{0, 0, -5};
  OrbitCamera cam;
  cam.drag(dx_pixels, dy_pixels);
  cam.zoom(wheel_steps);
  cam.frame(centre, radius);
  CameraView v = cam.view();
  EXPECT_GT(glm::length(v.position - centre), radius);
}

TEST(AppExamples, WorkbenchStage) {
  std::string error;
  const std::unique_ptr<EffectDocument> doc = EffectDocument::open(kRoot + "/assets/effects/plasma_bolt.json", error);
  ASSERT_TRUE(doc) << error;
  const double frame_seconds = 1.0 / 60.0;
  const int width = 640, height = 360;
  OrbitCamera orbit;
  const CameraView camera = orbit.view();
  RenderView view;
  WorkbenchStage stage;
  stage.set_effect(doc->library(), doc->name());
  stage.advance(frame_seconds);           // plays at the chosen speed
  stage.scrub(90);                         // tick 90 (1.5 s), exactly
  stage.build_view(camera, width, height, view);   // meshes and particles for the renderer
  SUCCEED() << view.particles.size() << " particles at tick 90";
}

TEST(AppExamples, RunFiles) {
  RunFiles files;
  files.input("--level", "levels/duel.json");
  files.output("--summary", "out/summary.json");
  files.output_folder("--out", "out/frames", [](const std::string& name) { return name.ends_with(".png"); });
  files.check();  // InputError when an output is one of the inputs
}

// The same file by another name, a symbolic link, a hard link or a file an output folder
// writes is refused, naming both; a file that merely sits beside an input is not.
TEST(RunFiles, AnOutputThatIsAnInputIsRefused) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("arcfire_run_files_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "sub");
  { std::ofstream(dir / "level.json") << "{}"; }
  fs::create_symlink("level.json", dir / "link.json");
  fs::create_hard_link(dir / "level.json", dir / "hard.json");
  auto refused = [&](const std::string& output) {
    RunFiles f;
    f.input("--level", (dir / "level.json").string());
    f.output("--summary", output);
    try {
      f.check();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--summary " + output + " is the same file as --level "), std::string::npos)
          << e.what();
      return true;
    }
    return false;
  };
  EXPECT_TRUE(refused((dir / "level.json").string()));
  EXPECT_TRUE(refused((dir / "sub" / ".." / "level.json").string()));
  EXPECT_TRUE(refused((dir / "link.json").string()));
  EXPECT_TRUE(refused((dir / "hard.json").string()));
  EXPECT_FALSE(refused((dir / "summary.json").string()));
  EXPECT_FALSE(refused((dir / "sub" / "level.json").string()));
  RunFiles frames;
  frames.input("--level", (dir / "frame_000030.png").string());
  frames.output_folder("--out", dir.string(), [](const std::string& n) { return n.starts_with("frame_"); });
  EXPECT_THROW(frames.check(), InputError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace arc
