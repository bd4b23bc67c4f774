#include "game/app/window_loop.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>

#include "core/clock.h"
#include "core/error.h"
#include "game/app/file_watcher.h"
#include "game/app/input_bindings.h"
#include "game/app/replay_cli.h"
#include "game/app/scene_resources.h"
#include "game/render/render_view_builder.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "gfx/renderer.h"
#include "gfx/screenshot.h"
#include "platform/platform.h"

namespace arc {
namespace {

const char* difficulty_name(Difficulty d) {
  switch (d) {
    case Difficulty::Easy: return "easy";
    case Difficulty::Normal: return "normal";
    case Difficulty::Hard: return "hard";
  }
  return "normal";
}

// Pause menu: Resume, Restart, Difficulty (cycles; applies on restart), Quit.
struct PauseMenu {
  enum Item { Resume = 0, Restart = 1, DifficultyItem = 2, Quit = 3 };
  int selection = 0;
  std::vector<std::string> items(Difficulty d) const {
    return {"Resume", "Restart", std::string("Difficulty: ") + difficulty_name(d), "Quit"};
  }
};

std::string screenshot_path() {
  std::filesystem::create_directories("out/screenshots");
  for (int i = 1;; ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "out/screenshots/arcfire_%04d.png", i);
    if (!std::filesystem::exists(name)) return name;
  }
}

// The live session: one Game, its renderer resources, and an optional recorder.
struct Session {
  std::unique_ptr<Game> game;
  std::unique_ptr<SessionRecorder> recorder;
};

Session start_session(const AppOptions& o, const GameOptions& game_options, Renderer& renderer, bool first) {
  Session s;
  s.game = std::make_unique<Game>(Game::load_level(o.level, game_options));
  if (first) load_scene_resources(renderer, s.game->world(), game_options.root_dir);
  // A restart ends the recording: one script describes one uninterrupted session.
  if (first && !o.record_path.empty()) s.recorder = std::make_unique<SessionRecorder>(o.record_path, o.level, *s.game);
  return s;
}

}  // namespace

int run_window(const AppOptions& o) {
  if (!display_available()) {
    std::fprintf(stderr, "arcfire: no display available (DISPLAY is not set or cannot be opened); "
                         "use --headless, or ./tools/play.sh which runs the headless demo\n");
    return kExitBadInput;
  }
  Bindings bindings = load_bindings(o.bindings_path);
  GameOptions game_options = o.game;
  // Validate the level before opening a window, so a bad file is one line and exit 2.
  Game::load_level(o.level, game_options);

  WindowDesc wd;
  wd.width = o.width;
  wd.height = o.height;
  wd.vsync = o.vsync;
  wd.fullscreen = o.fullscreen;
  wd.title = "Arcfire — " + std::filesystem::path(o.level).stem().string();
  std::unique_ptr<Window> window = open_window(wd);
  RendererDesc rd;
  rd.shader_dir = game_options.root_dir + "/shaders";
  auto make_renderer = [&]() {
    auto r = std::make_unique<Renderer>(rd);
    r->apply_settings(o.settings);
    return r;
  };
  std::unique_ptr<Renderer> renderer = make_renderer();

  Session session = start_session(o, game_options, *renderer, true);
  LiveInput input(bindings);
  FixedStepClock clock(int(std::lround(1.0 / session.game->tick_seconds())));
  PauseMenu menu;
  HudState hud;
  hud.show_fps = o.show_fps;
  window->set_mouse_captured(true);
  bool mouse_captured = true;

  // Hot reload: tweakers edit levels, ships, effects and shaders while the game runs.
  FileWatcher watcher;
  watcher.watch(o.level, "data");
  watcher.watch(game_options.root_dir + "/assets/ships", "data");
  watcher.watch(game_options.root_dir + "/assets/effects", "data");
  watcher.watch(game_options.root_dir + "/shaders", "shaders");
  watcher.poll();
  std::string reload_error;  // shown on screen until a reload succeeds
  double next_watch = 0;

  double last = window->time_seconds();
  double fps_time = last, fps = 0;
  int fps_frames = 0;
  RenderView view;
  InputState devices, prev;
  std::vector<Command> pending;
  bool want_screenshot = false;
  while (!window->should_close()) {
    window->poll(devices);
    input.sample(devices);
    bool paused = session.game->paused();
    std::vector<Command> menu_commands;
    for (AppAction a : input.take_actions()) {
      switch (a) {
        case AppAction::Screenshot: want_screenshot = true; break;
        case AppAction::ToggleFps: hud.show_fps = !hud.show_fps; break;
        case AppAction::ToggleCamera: menu_commands.push_back(Command::CameraToggle); break;
        case AppAction::TogglePause:
          menu_commands.push_back(paused ? Command::Resume : Command::Pause);
          menu.selection = 0;
          break;
      }
    }
    if (paused == mouse_captured) {
      window->set_mouse_captured(!paused);
      mouse_captured = !paused;
      input.discard_mouse_motion();
    }
    if (paused) {
      // Menu navigation reads the raw keys, edge-triggered by the InputState history.
      auto hit = [&](int key) { return devices.keys[size_t(key)] && !prev.keys[size_t(key)]; };
      static const int up = key_code("UP"), down = key_code("DOWN");
      static const int enter = key_code("ENTER"), space = key_code("SPACE");
      if (hit(up)) menu.selection = (menu.selection + 3) % 4;
      if (hit(down)) menu.selection = (menu.selection + 1) % 4;
      if (hit(enter) || hit(space)) {
        switch (menu.selection) {
          case PauseMenu::Resume: menu_commands.push_back(Command::Resume); break;
          case PauseMenu::Restart:
            if (session.recorder) session.recorder->finish(*session.game);
            session = start_session(o, game_options, *renderer, false);
            break;
          case PauseMenu::DifficultyItem:
            game_options.difficulty = Difficulty((int(game_options.difficulty) + 1) % 3);
            game_options.difficulty_override = true;
            break;
          case PauseMenu::Quit: window->request_close(); break;
        }
      }
    }
    prev = devices;

    if (window->time_seconds() >= next_watch) {
      next_watch = window->time_seconds() + 0.5;
      for (const std::string& group : watcher.poll()) {
        if (group == "shaders") {
          reload_error = renderer->reload();
          std::printf("arcfire: shaders reloaded%s\n", reload_error.empty() ? "" : " with errors (kept the old ones)");
        } else {
          try {
            Session fresh = start_session(o, game_options, *renderer, false);
            if (fresh.game->world().model_paths != session.game->world().model_paths) {
              // Model indices are positions in the level's model list: reload them all.
              renderer = make_renderer();
              load_scene_resources(*renderer, fresh.game->world(), game_options.root_dir);
            }
            if (session.recorder) session.recorder->finish(*session.game);
            session = std::move(fresh);
            reload_error.clear();
            std::printf("arcfire: data changed, level restarted\n");
          } catch (const InputError& e) {
            reload_error = e.what();  // keep playing the last good version
          }
        }
        std::fflush(stdout);
      }
    }
    // Menu commands wait for the next tick rather than being lost on a frame that runs none.
    pending.insert(pending.end(), menu_commands.begin(), menu_commands.end());
    double now = window->time_seconds();
    int ticks = clock.advance(now - last);
    last = now;
    for (int i = 0; i < ticks; ++i) {
      InputFrame frame = input.take_frame();
      std::vector<Command> commands = input.take_commands();
      if (i == 0) {
        commands.insert(commands.end(), pending.begin(), pending.end());
        pending.clear();
      }
      if (session.recorder) session.recorder->record(*session.game, frame, commands);
      session.game->step(frame, commands);
    }

    ++fps_frames;
    if (now - fps_time >= 0.5) {
      fps = fps_frames / (now - fps_time);
      fps_frames = 0;
      fps_time = now;
    }
    hud.fps = fps;
    hud.pause_selection = menu.selection;
    hud.pause_items = menu.items(game_options.difficulty);
    int w = window->framebuffer_width(), h = window->framebuffer_height();
    if (w > 0 && h > 0) {
      build_render_view(session.game->world(), clock.alpha(), CameraSettings{}, hud, w, h, view);
      if (!reload_error.empty()) {
        view.hud.quads.push_back({0.0f, float(h) - 34.0f, float(w), 34.0f, {0.35f, 0.02f, 0.02f, 0.85f}});
        view.hud.texts.push_back({12.0f, float(h) - 26.0f, 1.2f, {1.0f, 0.85f, 0.8f, 1.0f}, "reload failed: " + reload_error});
      }
      renderer->render(view, w, h);
      if (want_screenshot) {
        // Read the frame just drawn, before the swap leaves the back buffer undefined.
        std::string path = screenshot_path();
        save_image(path, read_window_pixels(w, h));
        std::printf("arcfire: screenshot %s\n", path.c_str());
        want_screenshot = false;
      }
    }
    window->swap();
  }
  if (session.recorder) {
    session.recorder->finish(*session.game);
    std::printf("arcfire: recorded %s\n", session.recorder->path().c_str());
  }
  return kExitOk;
}

}  // namespace arc
