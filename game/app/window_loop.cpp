// The live game in a window, as a WindowSession: set-up once, then update and draw per frame.
#include "game/app/window_loop.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "core/clock.h"
#include "core/error.h"
#include "game/app/file_watcher.h"
#include "game/app/input_bindings.h"
#include "game/app/scene_resources.h"
#include "game/app/session_recorder.h"
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

// The live session: one Game (restarted from the pause menu, or when its files change), the
// window and renderer that show it, live input, and an optional recorder.
class WindowSession {
 public:
  explicit WindowSession(const AppOptions& options) : options_(options), game_options_(options.game) {}
  ~WindowSession();
  // Loads the bindings, the HUD settings and the level (bad files are one line and exit 2
  // before any window opens), opens the window, makes the renderer and starts the game and the
  // recording.
  void setup();
  bool open() const { return !window_->should_close(); }
  double time() const { return window_->time_seconds(); }
  // One frame's work before drawing: devices to input and actions, the pause menu, reloads of
  // changed files, and the fixed-step ticks that `frame_seconds` of wall clock owe.
  void update(double frame_seconds);
  // The game at the clock's alpha, any reload error, a requested screenshot; then the swap.
  void draw();

 private:
  std::unique_ptr<Renderer> make_renderer() const;
  void end_recording();
  void handle_actions(std::vector<Command>& menu_commands);
  void navigate_pause_menu(std::vector<Command>& menu_commands);
  void reload_changed_files();
  void step_ticks(double frame_seconds);
  void count_fps(double frame_seconds);

  const AppOptions& options_;
  GameOptions game_options_;  // the pause menu's difficulty changes it for the next restart
  std::unique_ptr<Window> window_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<Game> game_;
  std::unique_ptr<SessionRecorder> recorder_;
  std::optional<LiveInput> input_;
  std::optional<FixedStepClock> clock_;
  InputState devices_, previous_devices_;
  std::vector<Command> pending_;  // menu commands wait for the next tick rather than being lost
  PauseMenu menu_;
  HudState hud_;
  RenderView view_;
  bool mouse_captured_ = true;
  bool want_screenshot_ = false;
  FileWatcher watcher_;       // hot reload: levels, ships, effects and shaders
  std::string reload_error_;  // shown on screen until a reload succeeds
  double next_watch_ = 0;     // window time of the next poll of the watched files
  double fps_seconds_ = 0;    // frames and time since the FPS counter was last updated
  int fps_frames_ = 0;
};

WindowSession::~WindowSession() {
  if (!recorder_) return;
  recorder_->finish(*game_);
  std::printf("arcfire: recorded %s\n", recorder_->path().c_str());
}

void WindowSession::setup() {
  input_.emplace(load_bindings(options_.bindings_path));
  hud_.rules = load_hud_rules(game_options_.root_dir + "/assets/settings/hud.json");
  game_ = std::make_unique<Game>(Game::load_level(options_.level, game_options_));
  WindowDesc wd;
  wd.width = options_.width;
  wd.height = options_.height;
  wd.vsync = options_.vsync;
  wd.fullscreen = options_.fullscreen;
  wd.title = "Arcfire — " + std::filesystem::path(options_.level).stem().string();
  window_ = open_window(wd);
  renderer_ = make_renderer();
  load_scene_resources(*renderer_, game_->world(), game_options_.root_dir);
  if (!options_.record_path.empty())
    recorder_ = std::make_unique<SessionRecorder>(options_.record_path, options_.level, *game_);
  clock_.emplace(int(std::lround(1.0 / game_->tick_seconds())));
  hud_.show_fps = options_.show_fps;
  window_->set_mouse_captured(true);
  watcher_.watch(options_.level, "data");
  watcher_.watch(game_options_.root_dir + "/assets/ships", "data");
  watcher_.watch(game_options_.root_dir + "/assets/effects", "data");
  watcher_.watch(game_options_.root_dir + "/shaders", "shaders");
  watcher_.poll();
}

std::unique_ptr<Renderer> WindowSession::make_renderer() const {
  RendererDesc rd;
  rd.shader_dir = game_options_.root_dir + "/shaders";
  auto r = std::make_unique<Renderer>(rd);
  r->apply_settings(options_.settings);
  return r;
}

// One script describes one uninterrupted session: a restart or a reload ends the recording.
void WindowSession::end_recording() {
  if (recorder_) recorder_->finish(*game_);
  recorder_.reset();
}

void WindowSession::update(double frame_seconds) {
  window_->poll(devices_);
  input_->sample(devices_);
  std::vector<Command> menu_commands;
  handle_actions(menu_commands);
  const bool paused = game_->paused();
  if (paused == mouse_captured_) {
    window_->set_mouse_captured(!paused);
    mouse_captured_ = !paused;
    input_->discard_mouse_motion();
  }
  if (paused) navigate_pause_menu(menu_commands);
  previous_devices_ = devices_;
  if (window_->time_seconds() >= next_watch_) {
    next_watch_ = window_->time_seconds() + 0.5;
    reload_changed_files();
  }
  pending_.insert(pending_.end(), menu_commands.begin(), menu_commands.end());
  step_ticks(frame_seconds);
  count_fps(frame_seconds);
}

void WindowSession::handle_actions(std::vector<Command>& menu_commands) {
  for (AppAction a : input_->take_actions()) {
    switch (a) {
      case AppAction::Screenshot: want_screenshot_ = true; break;
      case AppAction::ToggleFps: hud_.show_fps = !hud_.show_fps; break;
      case AppAction::ToggleCamera: menu_commands.push_back(Command::CameraToggle); break;
      case AppAction::TogglePause:
        menu_commands.push_back(game_->paused() ? Command::Resume : Command::Pause);
        menu_.selection = 0;
        break;
    }
  }
}

// Menu navigation reads the raw keys, edge-triggered against the previous frame's devices.
void WindowSession::navigate_pause_menu(std::vector<Command>& menu_commands) {
  auto hit = [&](int key) { return devices_.keys[size_t(key)] && !previous_devices_.keys[size_t(key)]; };
  static const int up = key_code("UP"), down = key_code("DOWN");
  static const int enter = key_code("ENTER"), space = key_code("SPACE");
  if (hit(up)) menu_.selection = (menu_.selection + 3) % 4;
  if (hit(down)) menu_.selection = (menu_.selection + 1) % 4;
  if (!hit(enter) && !hit(space)) return;
  switch (menu_.selection) {
    case PauseMenu::Resume: menu_commands.push_back(Command::Resume); break;
    case PauseMenu::Restart:
      end_recording();
      game_ = std::make_unique<Game>(Game::load_level(options_.level, game_options_));
      break;
    case PauseMenu::DifficultyItem:
      game_options_.difficulty = Difficulty((int(game_options_.difficulty) + 1) % 3);
      game_options_.difficulty_override = true;
      break;
    case PauseMenu::Quit: window_->request_close(); break;
  }
}

// Shaders reload in place; a changed level, ship or effect restarts the level. A file that
// fails to load keeps the last good version playing and shows its error.
void WindowSession::reload_changed_files() {
  for (const std::string& group : watcher_.poll()) {
    if (group == "shaders") {
      reload_error_ = renderer_->reload();
      std::printf("arcfire: shaders reloaded%s\n", reload_error_.empty() ? "" : " with errors (kept the old ones)");
    } else {
      try {
        auto fresh = std::make_unique<Game>(Game::load_level(options_.level, game_options_));
        if (fresh->world().model_paths != game_->world().model_paths) {
          // Model indices are positions in the level's model list: reload them all.
          renderer_ = make_renderer();
          load_scene_resources(*renderer_, fresh->world(), game_options_.root_dir);
        }
        end_recording();
        game_ = std::move(fresh);
        reload_error_.clear();
        std::printf("arcfire: data changed, level restarted\n");
      } catch (const InputError& e) {
        reload_error_ = e.what();
      }
    }
    std::fflush(stdout);
  }
}

void WindowSession::step_ticks(double frame_seconds) {
  const int ticks = clock_->advance(frame_seconds);
  for (int i = 0; i < ticks; ++i) {
    InputFrame frame = input_->take_frame();
    std::vector<Command> commands = input_->take_commands();
    if (i == 0) {
      commands.insert(commands.end(), pending_.begin(), pending_.end());
      pending_.clear();
    }
    if (recorder_) recorder_->record(*game_, frame, commands);
    game_->step(frame, commands);
  }
}

void WindowSession::count_fps(double frame_seconds) {
  ++fps_frames_;
  fps_seconds_ += frame_seconds;
  if (fps_seconds_ < 0.5) return;
  hud_.fps = fps_frames_ / fps_seconds_;
  fps_frames_ = 0;
  fps_seconds_ = 0;
}

void WindowSession::draw() {
  hud_.pause_selection = menu_.selection;
  hud_.pause_items = menu_.items(game_options_.difficulty);
  const int w = window_->framebuffer_width(), h = window_->framebuffer_height();
  if (w > 0 && h > 0) {
    build_render_view(game_->world(), clock_->alpha(), CameraSettings{}, hud_, w, h, view_);
    if (!reload_error_.empty()) {
      view_.hud.quads.push_back({0.0f, float(h) - 34.0f, float(w), 34.0f, {0.35f, 0.02f, 0.02f, 0.85f}});
      view_.hud.texts.push_back(
          {12.0f, float(h) - 26.0f, 1.2f, {1.0f, 0.85f, 0.8f, 1.0f}, "reload failed: " + reload_error_});
    }
    renderer_->render(view_, w, h);
    if (want_screenshot_) {
      // Read the frame just drawn, before the swap leaves the back buffer undefined.
      std::string path = screenshot_path();
      save_image(path, read_window_pixels(w, h));
      std::printf("arcfire: screenshot %s\n", path.c_str());
      want_screenshot_ = false;
    }
  }
  window_->swap();
}

}  // namespace

int run_window(const AppOptions& o) {
  if (!display_available()) {
    std::fprintf(stderr, "arcfire: no display available (DISPLAY is not set or cannot be opened); "
                         "use --headless, or ./tools/play.sh which runs the headless demo\n");
    return kExitBadInput;
  }
  WindowSession session(o);
  session.setup();
  double last = session.time();
  while (session.open()) {
    const double now = session.time();
    session.update(now - last);
    last = now;
    session.draw();
  }
  return kExitOk;
}

}  // namespace arc
