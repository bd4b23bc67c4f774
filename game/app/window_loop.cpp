// The live game in a window, as a WindowSession: set-up once, then update and draw per frame.
#include "game/app/window_loop.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "assets/screenshot_writer.h"
#include "core/clock.h"
#include "core/error.h"
#include "game/app/audio_session.h"
#include "game/app/file_watcher.h"
#include "game/app/frame_time_log.h"
#include "game/app/input_bindings.h"
#include "game/app/menu.h"
#include "game/app/menu_input.h"
#include "game/app/scene_resources.h"
#include "game/app/user_settings.h"
#include "game/app/session_recorder.h"
#include "game/render/menu_layout.h"
#include "game/render/render_view_builder.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "game/workbench/game_panel.h"
#include "gfx/renderer.h"
#include "gfx/screenshot.h"
#include "platform/platform.h"
#include "platform/stop_request.h"

namespace arc {
namespace {

// The pause menu. After victory or defeat Retry comes first. The AI's difficulty is part of
// the simulated game, fixed when it starts, so a change says that it waits for the restart.
// Started from the main menu, it also leads back there.
struct PauseMenu {
  enum class Item { Resume, Restart, Difficulty, Sound, Volume, MainMenu, Quit };
  int selection = 0;
  static std::vector<Item> items(bool decided, bool has_main_menu) {
    std::vector<Item> v = decided ? std::vector<Item>{Item::Restart, Item::Resume, Item::Difficulty}
                                  : std::vector<Item>{Item::Resume, Item::Restart, Item::Difficulty};
    v.push_back(Item::Sound);
    v.push_back(Item::Volume);
    if (has_main_menu) v.push_back(Item::MainMenu);
    v.push_back(Item::Quit);
    return v;
  }
  static std::string label(Item item, bool decided, Difficulty chosen, int playing, bool recording, bool muted,
                           double volume) {
    const char* restart = decided ? "Retry" : "Restart";
    switch (item) {
      case Item::Resume: return "Resume";
      case Item::Restart: return std::string(restart) + (recording ? " (ends the recording)" : "");
      case Item::Difficulty:
        return std::string("Difficulty: ") + difficulty_name(chosen) +
               (int(chosen) != playing ? std::string(" (applies on ") + (decided ? "retry)" : "restart)") : "");
      case Item::Sound: return muted ? "Sound: muted (M)" : "Sound: on (M)";
      case Item::Volume: return "Volume: < " + std::to_string(int(std::lround(volume * 100))) + "% >";
      case Item::MainMenu: return std::string("Main menu") + (recording ? " (ends the recording)" : "");
      case Item::Quit: return "Quit";
    }
    return "";
  }
};

// The live session: one Game (restarted from the pause menu, or when its files change), the
// window and renderer that show it, live input, and an optional recorder. Without --level it
// opens on the main menu (game/app/menu.h) over the attract demo, launches the missions the
// menu picks and shows their results; the player's settings and progress are kept in
// user_config_dir() either way.
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
  int64_t tick() const { return int64_t(game_->world().tick); }
  FrameStats frame_stats() const { return renderer_->last_stats(); }
  bool write_failed() const { return write_failed_ || (recorder_ && recorder_->failed()); }
  // One frame's work before drawing: devices to input and actions, the pause menu, reloads of
  // changed files, and the fixed-step ticks that `frame_seconds` of wall clock owe.
  void update(double frame_seconds);
  // The game at the clock's alpha, any reload error, a requested screenshot; then the swap.
  void draw();

 private:
  std::unique_ptr<Renderer> make_renderer() const;
  void load_user_files_and_bindings();
  Settings user_render_settings() const;
  void start_game(std::unique_ptr<Game> fresh);
  void launch(const std::string& level, Difficulty difficulty);
  void back_to_main_menu();
  void update_menu();
  void carry_out(const std::vector<MenuRequest>& requests);
  void apply_changed_settings();
  void show_results_when_decided();
  void end_recording(const char* why);
  void handle_actions(std::vector<Command>& menu_commands, bool in_menu);
  void set_flight_scale();
  std::string attract_level() const;
  void navigate_pause_menu(std::vector<Command>& menu_commands);
  void reload_changed_files();
  void step_ticks(double frame_seconds);
  void count_fps(double frame_seconds);
  void handle_sound_keys(bool in_menu);
  void report_screenshots(const std::vector<ScreenshotWriter::Done>& shots);

  const AppOptions& options_;
  GameOptions game_options_;  // the pause menu's difficulty changes it for the next restart
  std::string level_;         // the level playing: --level, the attract demo or a menu pick
  Settings settings_;         // render and simulation settings: the user's preset, then --quality and --set
  UserFiles user_;            // the player's settings and progress as loaded (the menu keeps them after)
  Bindings bindings_;         // flown with: the bindings file, the user's settings over it
  std::optional<Menu> menu_;  // without --level: the main menu, mission select, results
  std::vector<HudBox> menu_boxes_;  // the menu items as last drawn, for the mouse
  bool mission_running_ = false;    // a level launched from the menu: its end shows the results
  double results_at_ = -1;          // window time at which the decided mission's results open
  bool recording_started_ = false;  // --record from the menu: only the first launched mission
  std::unique_ptr<Window> window_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<GamePanel> panel_;  // F1: every setting live, and the effects (game/workbench/game_panel.h)
  std::vector<ModelId> models_;  // the renderer's id of each of the level's model slots
  std::unique_ptr<Game> game_;
  std::unique_ptr<SessionRecorder> recorder_;
  std::unique_ptr<AudioSession> audio_;  // sounds.json is checked before the window opens
  std::optional<LiveInput> input_;
  std::optional<FixedStepClock> clock_;
  InputState devices_, previous_devices_;
  std::vector<Command> pending_;  // menu commands wait for the next tick rather than being lost
  PauseMenu pause_menu_;
  HudState hud_;
  std::string notice_;        // a line shown on screen until notice_until_ (window time)
  double notice_until_ = 0;
  RenderView view_;
  bool mouse_captured_ = true;
  bool want_screenshot_ = false;
  ScreenshotWriter screenshots_{"out/screenshots", "arcfire"};  // F12, written in the background
  FileWatcher watcher_;       // hot reload: levels, ships, effects and shaders
  std::string reload_error_;  // shown on screen until a reload succeeds
  double next_watch_ = 0;     // window time of the next poll of the watched files
  double fps_seconds_ = 0;    // frames and time since the FPS counter was last updated
  int fps_frames_ = 0;
  bool write_failed_ = false;  // a recording failed to write: the session exits 1
};

WindowSession::~WindowSession() {
  if (recorder_) recorder_->stop(*game_, "");
  report_screenshots(screenshots_.wait());
}

// Each written screenshot is one line on stdout; a failed one (a full disk) is said on screen,
// and on stderr, not fatal.
void WindowSession::report_screenshots(const std::vector<ScreenshotWriter::Done>& shots) {
  for (const ScreenshotWriter::Done& shot : shots) {
    if (shot.error.empty()) {
      std::printf("arcfire: screenshot %s\n", shot.path.c_str());
      std::fflush(stdout);
      continue;
    }
    std::fprintf(stderr, "arcfire: %s\n", shot.error.c_str());
    notice_ = shot.error;
    if (window_) notice_until_ = window_->time_seconds() + 8.0;
  }
}

void WindowSession::setup() {
  load_user_files_and_bindings();
  input_.emplace(bindings_);
  hud_.rules = load_hud_rules(game_options_.root_dir + "/assets/settings/hud.json");
  level_ = options_.level;
  if (!options_.level_given) {
    level_ = game_options_.root_dir + "/levels/attract.json";
    Bindings defaults = load_bindings(game_options_.root_dir + "/assets/settings/bindings.json");
    menu_.emplace(load_mission_catalog(game_options_.root_dir + "/levels", game_options_.root_dir), user_, bindings_,
                  defaults, game_options_.root_dir + "/assets/settings/quality.json");
  }
  start_game(std::make_unique<Game>(Game::load_level(level_, game_options_)));
  // From the menu, the recording starts with the first mission launched (launch()); a second
  // arcfire recording to the same file is refused here, before a window opens.
  if (!options_.record_path.empty() && !menu_)
    recorder_ = std::make_unique<SessionRecorder>(options_.record_path, level_, *game_);
  audio_ = std::make_unique<AudioSession>(options_.sounds_path, settings_, false);
  WindowDesc wd;
  wd.width = options_.width;
  wd.height = options_.height;
  wd.vsync = options_.vsync && user_.settings.vsync;
  wd.fullscreen = options_.fullscreen || user_.settings.fullscreen;
  wd.title = "Arcfire" + (options_.level_given ? " — " + std::filesystem::path(level_).stem().string() : "");
  window_ = open_window(wd);
  renderer_ = make_renderer();
  panel_ = std::make_unique<GamePanel>(game_options_.root_dir);
  models_ = load_scene_resources(*renderer_, game_->world(), game_options_.root_dir);
  clock_.emplace(int(std::lround(1.0 / game_->tick_seconds())));
  hud_.show_fps = options_.show_fps;
  window_->set_mouse_captured(!menu_);
  mouse_captured_ = !menu_;
  if (!audio_->engine().active()) {
    notice_ = "Sound off: " + audio_->engine().notice();
    notice_until_ = window_->time_seconds() + 6.0;
  }
  if (!user_.message.empty() && !menu_) {
    notice_ = user_.message;
    notice_until_ = window_->time_seconds() + 15.0;
  }
  // The menu launches any level: watch them all (a file first watched later would count as changed).
  watcher_.watch(menu_ ? game_options_.root_dir + "/levels" : level_, "data");
  watcher_.watch(game_options_.root_dir + "/assets/ships", "data");
  watcher_.watch(game_options_.root_dir + "/assets/effects", "data");
  watcher_.watch(game_options_.root_dir + "/shaders", "shaders");
  watcher_.watch(options_.sounds_path, "sounds");
  watcher_.poll();
}

// The player's files (a bad one is kept as .bak and reported), and the bindings they change:
// the bindings file with the user's keys, sensitivity and inversion over it, unless the file
// was named with --bindings, which wins.
void WindowSession::load_user_files_and_bindings() {
  user_ = load_user_files(user_config_dir(), game_options_.root_dir + "/assets/settings/quality.json");
  if (!user_.message.empty()) std::fprintf(stderr, "arcfire: %s\n", user_.message.c_str());
  bindings_ = load_bindings(options_.bindings_path);
  if (!options_.bindings_given) apply_user_settings(user_.settings, bindings_);
  settings_ = user_render_settings();
  apply_simulation_settings(settings_, game_options_);
}

// The user's quality preset and own render values with the command line's --set over them;
// --quality wins over both.
Settings WindowSession::user_render_settings() const {
  if (options_.quality_given) return options_.settings;
  const UserSettings& us = menu_ ? menu_->settings() : user_.settings;
  Settings s;
  try {
    s = user_quality_settings(us, game_options_.root_dir + "/assets/settings/quality.json");
    for (const std::string& set : options_.setting_overrides) s.set_from_text(set, "--set " + set);
  } catch (const InputError&) {
    return options_.settings;  // a preset the quality file no longer has: the command line's settings
  }
  return s;
}

std::unique_ptr<Renderer> WindowSession::make_renderer() const {
  RendererDesc rd;
  rd.shader_dir = game_options_.root_dir + "/shaders";
  auto r = std::make_unique<Renderer>(rd);
  r->apply_settings(settings_);
  return r;
}

// A fresh game: zero throttle, and the flown ship's turn rates for the mouse.
void WindowSession::start_game(std::unique_ptr<Game> fresh) {
  game_ = std::move(fresh);
  input_->reset_throttle();
  set_flight_scale();
}

void WindowSession::set_flight_scale() {
  const World& w = game_->world();
  FlightScale scale;
  scale.tick_seconds = w.dt;
  if (w.player) {
    scale.pitch_rate_degrees = w.ship(w.player).cls->turn_rate[0];
    scale.yaw_rate_degrees = w.ship(w.player).cls->turn_rate[1];
  }
  input_->set_flight_scale(scale);
}

// One script describes one uninterrupted session: a restart or a reload ends the recording,
// which stays replayable, and the screen says so.
void WindowSession::end_recording(const char* why) {
  if (!recorder_) return;
  notice_ = recorder_->stop(*game_, why);
  notice_until_ = window_->time_seconds() + 8.0;
  write_failed_ = write_failed_ || recorder_->failed();
  recorder_.reset();
}

void WindowSession::update(double frame_seconds) {
  window_->poll(devices_);
  if (panel_->wants_mouse()) devices_.mouse_buttons = {}, devices_.mouse_presses = {};  // clicks on the panel
  input_->set_screen_height(window_->framebuffer_height());
  input_->sample(devices_);
  std::vector<Command> menu_commands;
  const bool in_menu = menu_ && menu_->open();
  handle_actions(menu_commands, in_menu);
  if (in_menu) update_menu();
  handle_sound_keys(in_menu);
  if (presses_between(previous_devices_, devices_, key_code("F1")) > 0) panel_->toggle();
  const bool paused = game_->paused();
  const bool capture = !paused && !(menu_ && menu_->open()) && !panel_->open();
  if (capture != mouse_captured_) {
    window_->set_mouse_captured(capture);
    mouse_captured_ = capture;
    input_->discard_mouse_motion();
  }
  if (panel_->open()) input_->discard_mouse_motion();  // the cursor is the panel's
  if (paused && !in_menu) navigate_pause_menu(menu_commands);
  previous_devices_ = devices_;
  if (window_->time_seconds() >= next_watch_) {
    next_watch_ = window_->time_seconds() + 0.5;
    reload_changed_files();
  }
  pending_.insert(pending_.end(), menu_commands.begin(), menu_commands.end());
  step_ticks(frame_seconds);
  audio_->frame(game_->world(), frame_seconds);
  show_results_when_decided();
  count_fps(frame_seconds);
}

// M toggles mute (not while the menu waits for a key to remap); a menu move or choice clicks.
void WindowSession::handle_sound_keys(bool in_menu) {
  auto hits = [&](const char* key) { return presses_between(previous_devices_, devices_, key_code(key)); };
  const bool paused_menu = game_->paused() && !in_menu;
  if ((in_menu || paused_menu) && hits("UP") + hits("DOWN") + hits("ENTER") + hits("ESCAPE") > 0)
    audio_->ui("ui_click");
  if ((menu_ && menu_->capturing()) || hits("M") == 0) return;
  notice_ = audio_->toggle_mute() ? "Sound muted (M)" : "Sound on (M)";
  notice_until_ = window_->time_seconds() + 2.0;
}

// With the main menu open only the screenshot and FPS keys act; the rest is the menu's.
void WindowSession::handle_actions(std::vector<Command>& menu_commands, bool in_menu) {
  for (AppAction a : input_->take_actions()) {
    switch (a) {
      case AppAction::Screenshot: want_screenshot_ = true; break;
      case AppAction::ToggleFps: hud_.show_fps = !hud_.show_fps; break;
      case AppAction::ToggleCamera:
        if (!in_menu) menu_commands.push_back(Command::CameraToggle);
        break;
      case AppAction::TogglePause:
        if (in_menu) break;
        menu_commands.push_back(game_->paused() ? Command::Resume : Command::Pause);
        pause_menu_.selection = 0;
        break;
    }
  }
}

void WindowSession::update_menu() {
  for (const UiInput& in : menu_inputs(previous_devices_, devices_, menu_->capturing(), menu_boxes_)) {
    carry_out(menu_->handle(in));
    if (!menu_->open()) return;
  }
  // Back on the main menu after a mission (its results' "Menu"): the demo plays behind again.
  if (menu_->screen() == MenuScreen::Main && level_ != attract_level()) back_to_main_menu();
}

// What the menu asks for. A file that cannot be written is said on the menu, not fatal.
void WindowSession::carry_out(const std::vector<MenuRequest>& requests) {
  for (const MenuRequest& r : requests) {
    try {
      switch (r.kind) {
        case MenuRequest::Kind::Launch: launch(r.level, r.difficulty); break;
        case MenuRequest::Kind::Quit: window_->request_close(); break;
        case MenuRequest::Kind::SaveSettings:
          save_settings(user_.dir, menu_->settings());
          apply_changed_settings();
          break;
        case MenuRequest::Kind::SaveProgress: save_progress(user_.dir, menu_->progress()); break;
        case MenuRequest::Kind::ApplyBindings:
          bindings_ = menu_->bindings();
          apply_user_settings(menu_->settings(), bindings_);
          input_.emplace(bindings_);
          set_flight_scale();
          break;
      }
    } catch (const InputError& e) {
      menu_->set_message(e.what());
    }
  }
}

// Vsync and fullscreen at once; the quality preset for the renderer at once and for the
// simulation (particle budget, sub-steps) at the next launch.
void WindowSession::apply_changed_settings() {
  const UserSettings& s = menu_->settings();
  window_->set_vsync(options_.vsync && s.vsync);
  if (window_->fullscreen() != s.fullscreen) window_->toggle_fullscreen();
  settings_ = user_render_settings();
  renderer_->apply_settings(settings_);
  apply_simulation_settings(settings_, game_options_);
  audio_->apply_settings(settings_);
}

std::string WindowSession::attract_level() const { return game_options_.root_dir + "/levels/attract.json"; }

void WindowSession::launch(const std::string& level, Difficulty difficulty) {
  end_recording("launch of another level");
  game_options_.difficulty = difficulty;
  game_options_.difficulty_override = true;
  auto fresh = std::make_unique<Game>(Game::load_level(level, game_options_));
  if (fresh->world().model_paths != game_->world().model_paths) {
    renderer_ = make_renderer();
    models_ = load_scene_resources(*renderer_, fresh->world(), game_options_.root_dir);
  }
  level_ = level;
  start_game(std::move(fresh));
  clock_.emplace(int(std::lround(1.0 / game_->tick_seconds())));
  mission_running_ = level != attract_level();
  results_at_ = -1;
  if (!options_.record_path.empty() && mission_running_ && !recording_started_) {
    // As --level would name it: relative to the working folder when the level is inside it.
    const std::string named = std::filesystem::proximate(level_).string();
    recorder_ = std::make_unique<SessionRecorder>(options_.record_path, named, *game_);
    recording_started_ = true;
  }
}

void WindowSession::back_to_main_menu() {
  launch(attract_level(), Difficulty::Normal);
  menu_->open_main();
}

// A decided mission shows its outcome for a moment, then the results screen over it. The
// attract demo behind the menu starts again when it is decided.
void WindowSession::show_results_when_decided() {
  const World& w = game_->world();
  if (!menu_ || w.outcome == Outcome::Undecided) return;
  const double now = window_->time_seconds();
  if (results_at_ < 0) results_at_ = now + (mission_running_ ? 3.0 : 5.0);
  if (now < results_at_) return;
  results_at_ = -1;
  if (!mission_running_) {
    if (level_ == attract_level() && menu_->open()) launch(attract_level(), Difficulty::Normal);
    return;
  }
  mission_running_ = false;
  if (game_->paused()) pending_.push_back(Command::Resume);
  carry_out(menu_->show_results(level_, Difficulty(w.difficulty), mission_result(w)));
}

// Menu navigation reads the raw keys: every press counts, two taps within a frame too.
void WindowSession::navigate_pause_menu(std::vector<Command>& menu_commands) {
  auto hits = [&](const char* key) { return presses_between(previous_devices_, devices_, key_code(key)); };
  const auto items = PauseMenu::items(game_->world().outcome != Outcome::Undecided, menu_.has_value());
  const int count = int(items.size());
  pause_menu_.selection = ((pause_menu_.selection + hits("DOWN") - hits("UP")) % count + count) % count;
  if (items[size_t(pause_menu_.selection)] == PauseMenu::Item::Volume) {
    if (const int steps = hits("RIGHT") - hits("LEFT")) audio_->step_volume(steps);
  }
  if (hits("ENTER") + hits("SPACE") == 0) return;
  switch (items[size_t(pause_menu_.selection)]) {
    case PauseMenu::Item::Resume: menu_commands.push_back(Command::Resume); break;
    case PauseMenu::Item::Restart:
      end_recording("restart");
      start_game(std::make_unique<Game>(Game::load_level(level_, game_options_)));
      pause_menu_.selection = 0;
      results_at_ = -1;
      break;
    case PauseMenu::Item::Difficulty:
      game_options_.difficulty = Difficulty((int(game_options_.difficulty) + 1) % 3);
      game_options_.difficulty_override = true;
      break;
    case PauseMenu::Item::Sound: audio_->toggle_mute(); break;
    case PauseMenu::Item::Volume: audio_->step_volume(audio_->volume() >= 1.0 ? -10 : 1); break;  // Enter: up, wrapping
    case PauseMenu::Item::MainMenu:
      try {
        back_to_main_menu();
      } catch (const InputError& e) {
        reload_error_ = e.what();  // the demo's level no longer loads: say so, keep playing
      }
      break;
    case PauseMenu::Item::Quit: window_->request_close(); break;
  }
}

// Shaders reload in place; a changed level, ship or effect restarts the level. A file that
// fails to load keeps the last good version playing and shows its error.
void WindowSession::reload_changed_files() {
  for (const std::string& group : watcher_.poll()) {
    if (group == "shaders") {
      reload_error_ = renderer_->reload();
      std::printf("arcfire: shaders reloaded%s\n", reload_error_.empty() ? "" : " with errors (kept the old ones)");
    } else if (group == "sounds") {
      reload_error_ = audio_->reload();
      std::printf("arcfire: sounds reloaded%s\n", reload_error_.empty() ? "" : " with errors (kept the old ones)");
    } else {
      try {
        auto fresh = std::make_unique<Game>(Game::load_level(level_, game_options_));
        if (fresh->world().model_paths != game_->world().model_paths) {
          // Model slots are positions in the level's model list: reload them all.
          renderer_ = make_renderer();
          models_ = load_scene_resources(*renderer_, fresh->world(), game_options_.root_dir);
        }
        end_recording("reload of changed files");
        start_game(std::move(fresh));
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
    InputFrame frame = input_->take_frame(ticks - i);
    std::vector<Command> commands = input_->take_commands();
    if (menu_ && menu_->open()) frame = InputFrame{}, commands.clear();  // the menu has the devices
    if (i == 0) {
      commands.insert(commands.end(), pending_.begin(), pending_.end());
      pending_.clear();
    }
    if (recorder_) recorder_->record(*game_, frame, commands);
    if (recorder_ && recorder_->failed()) end_recording("write error");  // on screen; the file stays valid
    game_->step(frame, commands);
    audio_->after_tick(game_->world());
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
  const World& w = game_->world();
  const bool decided = w.outcome != Outcome::Undecided;
  hud_.pause_selection = pause_menu_.selection;
  hud_.pause_items.clear();
  for (PauseMenu::Item item : PauseMenu::items(decided, menu_.has_value()))
    hud_.pause_items.push_back(
        PauseMenu::label(item, decided, game_options_.difficulty, w.difficulty, recorder_ != nullptr, audio_->muted(),
                        audio_->volume()));
  hud_.error_banner = reload_error_.empty() ? "" : "reload failed: " + reload_error_;
  hud_.notice = window_->time_seconds() < notice_until_ ? notice_ : "";
  const bool menu_open = menu_ && menu_->open();
  const MouseReticle r = input_->reticle();
  hud_.reticle = {r.shown && !w.paused && !menu_open, r.x, r.y, r.radius, r.deadzone};
  hud_.show_hud = !menu_open;
  hud_.show_outcome = !menu_open;
  CameraSettings camera;  // the player's field of view, except for a level's fixed camera
  if (w.camera_mode != CameraMode::Fixed) camera.fov_deg = menu_ ? menu_->settings().fov : user_.settings.fov;
  const int width = window_->framebuffer_width(), height = window_->framebuffer_height();
  if (width > 0 && height > 0) {
    build_render_view(w, models_, clock_->alpha(), camera, hud_, width, height, view_);
    if (menu_open) layout_menu(menu_->page(), width, height, view_.hud, &menu_boxes_);
    renderer_->render(view_, width, height);
    if (hud_.show_fps) hud_.frame_stats = describe_particle_stats(renderer_->last_stats());
    // Read the frame just drawn, before the swap leaves the back buffer undefined; the PNG is
    // encoded and written by a worker (about 100 ms at 1280x720, a hitch on this thread).
    if (want_screenshot_) screenshots_.save(read_window_pixels(width, height));
    want_screenshot_ = false;
  }
  report_screenshots(screenshots_.finished());
  if (panel_->frame(settings_, renderer_->last_stats()))
    renderer_->apply_settings(settings_), audio_->apply_settings(settings_), apply_simulation_settings(settings_, game_options_);
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
  FrameTimeLog frame_times(o.frame_times_path);
  double last = session.time();
  bool drawn = false;
  while (session.open() && !stop_requested()) {  // Ctrl+C or a kill closes as the close button does
    const double now = session.time();
    // The frame that just ended: its whole interval (update, draw, swap) beside what the
    // renderer timed of it and the tick it showed.
    if (drawn && frame_times.enabled()) frame_times.frame(now - last, now, session.tick(), session.frame_stats());
    session.update(now - last);
    session.draw();
    drawn = true;
    last = now;
  }
  frame_times.finish();
  if (stop_requested()) report_stop("at tick " + std::to_string(session.tick()));  // ~WindowSession ends the recording
  if (session.write_failed()) return kExitCheckFailed;
  return stop_requested() ? stop_exit_code() : kExitOk;
}

}  // namespace arc
