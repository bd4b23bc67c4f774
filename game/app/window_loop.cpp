// The live game in a window: run_window() and WindowSession's frame (set-up, devices, ticks, drawing).
#include "game/app/key_remap.h"
#include "game/app/quick_battle_files.h"
#include "game/app/window_loop.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/data_layers.h"
#include "core/error.h"
#include "game/app/campaign.h"
#include "game/app/frame_time_log.h"
#include "game/app/run_files.h"
#include "game/app/scene_resources.h"
#include "game/app/window_session.h"
#include "game/render/menu_layout.h"
#include "game/render/render_view_builder.h"
#include "game/sim/world.h"
#include "gfx/screenshot.h"
#include "platform/platform.h"
#include "platform/stop_request.h"

namespace arc {

WindowSession::~WindowSession() {
  if (recorder_) recorder_->stop(*game_, "");
  if (net_ && net_->peer_ready() && window_) end_net("The window closed");  // the match record is kept
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
    notices_.show(shot.error, window_ ? window_->time_seconds() : 0.0, 8.0);
  }
}

void WindowSession::setup() {
  load_user_files_and_bindings();
  input_.emplace(bindings_);
  hud_.key_names = key_names(bindings_);
  hud_.rules = load_hud_rules(data_file(game_options_.root_dir, "assets/settings/hud.json"));
  level_ = options_.level;
  if (!options_.level_given) {
    level_ = data_file(game_options_.root_dir, "levels/attract.json");
    Bindings defaults = load_bindings(data_file(game_options_.root_dir, "assets/settings/bindings.json"));
    menu_.emplace(load_catalog_with_campaign(game_options_.root_dir), user_, bindings_,
                  defaults, data_file(game_options_.root_dir, "assets/settings/quality.json"));
    offer_quick_battle(*menu_, game_options_.root_dir, user_.dir);
  } else {
    menu_.emplace(user_);  // the pause screen only
  }
  start_game(std::make_unique<Game>(Game::load_level(level_, game_options_)));
  RunFiles files = options_.files;  // the level's classes, models and effects are known now
  add_level_inputs(files, game_->world(), game_options_.root_dir);
  files.check();
  // From the menu, the recording starts with the first mission launched (launch()); a second
  // arcfire recording to the same file is refused here, before a window opens.
  if (!options_.record_path.empty() && !menu_->has_main())
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
  menu_->set_machine(renderer_->gl_renderer());  // the Graphics page rates the presets for it
  adopt_device_look();
  panel_ = std::make_unique<GamePanel>(game_options_.root_dir);
  load_sprites(*renderer_, game_options_.root_dir);
  models_ = scene_models_.of(*renderer_, game_->world(), game_options_.root_dir);
  if (menu_->has_main()) warm_launches();
  clock_.emplace(int(std::lround(1.0 / game_->tick_seconds())));
  hud_.show_fps = options_.show_fps;
  mouse_captured_ = !menu_->open();
  window_->set_mouse_captured(mouse_captured_);
  if (!audio_->engine().active()) notices_.show("Sound off: " + audio_->engine().notice(), window_->time_seconds(), 6.0);
  if (!user_.message.empty() && !menu_->has_main()) notices_.show(user_.message, window_->time_seconds(), 15.0);
  // The menu launches any level: watch them all (a file first watched later would count as changed).
  // Each folder is watched in the data root and in every mod that has it.
  const std::string& root = game_options_.root_dir;
  if (!menu_->has_main()) reload_.watch(level_, HotReload::Group::Data);
  for (const char* dir : {"levels", "assets/ships", "assets/effects", "shaders"})
    for (const std::string& d : data_dirs(root, dir))
      if (menu_->has_main() || std::string(dir) != "levels")
        reload_.watch(d, std::string(dir) == "shaders" ? HotReload::Group::Shaders : HotReload::Group::Data);
  reload_.watch(options_.sounds_path, HotReload::Group::Sounds);
  reload_.update(window_->time_seconds());
  if (menu_->has_main()) menu_->set_net_missions(net_missions());
  if (options_.net.active()) {
    NetMatch::Config c;
    c.host = options_.net.host, c.level = options_.level, c.join = options_.net.join, c.port = options_.net.port;
    c.players = options_.net.players;
    c.name = options_.net.name.empty() ? user_.settings.net_name : options_.net.name;
    start_net(c, true);
  }
}

void WindowSession::update(double frame_seconds) {
  window_->poll(devices_);
  // Capturing or releasing the cursor moves it (virtual and real positions differ): not a
  // move of the player's that should hover a menu item.
  if (cursor_jumped_) previous_devices_.mouse_x = devices_.mouse_x, previous_devices_.mouse_y = devices_.mouse_y;
  cursor_jumped_ = false;
  if (panel_->wants_mouse()) devices_.mouse_buttons = {}, devices_.mouse_presses = {};  // clicks on the panel
  input_->set_screen_height(window_->framebuffer_height());
  input_->sample(devices_);
  sync_pause_screen();
  const bool menu_open = menu_->open();
  handle_actions(menu_->over_game());
  if (menu_->open() || shown_game().paused()) input_->close_comms();  // the menu has the keys
  if (menu_open) update_menu();
  update_net();
  prepare_launch();
  handle_sound_keys(menu_open);
  const bool f1 = presses_between(previous_devices_, devices_, key_code("F1")) > 0;
  if (f1 && f1_toggles_panel(options_.dev, menu_->settings().developer_panel, panel_->open())) panel_->toggle();
  if (auto c = panel_gate_.follow(panel_->open(), !menu_->over_game(), shown_game().paused())) pending_.push_back(*c);
  const bool capture = !shown_game().paused() && !menu_->open() && !panel_->open();
  if (capture != mouse_captured_) {
    window_->set_mouse_captured(capture);
    mouse_captured_ = capture;
    cursor_jumped_ = true;
    input_->discard_mouse_motion();
  }
  if (panel_->open()) input_->discard_mouse_motion();  // the cursor is the panel's
  previous_devices_ = devices_;
  reload_.update(window_->time_seconds());
  step_ticks(frame_seconds);
  // The menu theme under the title and settings; a decided fight's results keep its stinger.
  audio_->set_menu(menu_->over_game() && shown_game().world().outcome == Outcome::Undecided);
  audio_->frame(shown_game().world(), frame_seconds);
  show_results_when_decided();
  notices_.count_frame(frame_seconds);
  hud_.fps = notices_.fps();
}

// The pause screen follows the simulation's pause, which a command sets at the next tick. The
// developer panel has the keys while it is open: the pause screen waits until it closes.
void WindowSession::sync_pause_screen() {
  if (game_->paused() && !panel_->open()) menu_->pause(pause_state());
  else menu_->close_pause();
}

// M toggles mute (not while the menu waits for a key to remap); a menu move or choice clicks.
void WindowSession::handle_sound_keys(bool menu_open) {
  auto hits = [&](const char* key) { return presses_between(previous_devices_, devices_, key_code(key)); };
  if (menu_open && hits("UP") + hits("DOWN") + hits("ENTER") + hits("ESCAPE") > 0) audio_->ui("ui_click");
  if (menu_->capturing() || hits("M") == 0) return;
  notices_.show(audio_->toggle_mute() ? "Sound muted (M)" : "Sound on (M)", window_->time_seconds(), 2.0);
}

// With the main menu (or the results) open only the screenshot and FPS keys act; the rest is
// the menu's. The pause key toggles the pause screen too.
void WindowSession::handle_actions(bool over_game) {
  for (AppAction a : input_->take_actions()) {
    switch (a) {
      case AppAction::Screenshot: want_screenshot_ = true; break;
      case AppAction::ToggleFps: hud_.show_fps = !hud_.show_fps; break;
      case AppAction::ToggleCamera:
        if (!over_game) pending_.push_back(Command::CameraToggle);
        break;
      case AppAction::TogglePadlock:
        if (!over_game) pending_.push_back(Command::CameraPadlock);
        break;
      case AppAction::TogglePause:
        if (net_playing()) net_escape();  // no pause in a network match
        else if (!over_game) pending_.push_back(game_->paused() ? Command::Resume : Command::Pause);
        break;
    }
  }
}

void WindowSession::step_ticks(double frame_seconds) {
  if (net_playing()) return step_net_ticks(frame_seconds);
  const int ticks = clock_->advance(frame_seconds);
  for (int i = 0; i < ticks; ++i) {
    InputFrame frame = input_->take_frame(ticks - i);
    std::vector<Command> commands = input_->take_commands();
    if (menu_->over_game()) frame = InputFrame{}, commands.clear();  // the menu has the devices
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

void WindowSession::draw() {
  const World& w = shown_game().world();
  sync_pause_screen();  // what the frame's ticks and requests changed: the volume, a resume
  hud_.error_banner = reload_.banner();
  if (net_playing()) fill_net_hud();  // a desync's line takes the banner
  else hud_.net = NetHud{};
  hud_.notice = notices_.notice(window_->time_seconds());
  const std::optional<Subtitle> line = audio_->subtitle();
  hud_.subtitle = line ? line->speaker + ": " + line->text : "";
  const bool menu_open = menu_->open();
  const MouseReticle r = input_->reticle();
  hud_.reticle = {r.shown && !w.paused && !menu_open, r.x, r.y, r.radius, r.deadzone};
  hud_.comms_open = input_->comms_open() && !w.paused && !menu_open;
  hud_.show_hud = !menu_->over_game();
  hud_.show_outcome = !menu_open;  // the pause screen and the results have it as their title
  CameraSettings camera;  // the player's field of view, except for a level's fixed camera
  if (w.camera_mode != CameraMode::Fixed) camera.fov_deg = menu_->settings().fov;
  const int width = window_->framebuffer_width(), height = window_->framebuffer_height();
  if (width > 0 && height > 0) {
    build_render_view(w, models_, clock_->alpha(), camera, hud_, width, height, view_);
    menu_boxes_.clear();
    if (menu_open) layout_menu(menu_->page(), width, height, view_.hud, &menu_boxes_);
    renderer_->render(view_, width, height);
    warm_prepared_launch();
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
    if (drawn) session.frame_done(now - last);
    session.update(now - last);
    session.draw();
    drawn = true;
    last = now;
  }
  frame_times.finish();
  if (stop_requested()) report_stop("at tick " + std::to_string(session.tick()));  // ~WindowSession ends the recording
  if (session.write_failed()) return kExitCheckFailed;
  if (session.net_failed()) return kExitBadInput;
  return stop_requested() ? stop_exit_code() : kExitOk;
}

}  // namespace arc
