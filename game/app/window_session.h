// game/app/window_session.h — WindowSession, the live game in a window: set-up once, then
// update and draw per frame (run_window() in window_loop.cpp drives it).
//
// One Game (restarted from the pause screen, or when its files change), the window and
// renderer that show it, live input, and an optional recorder. Without --level it opens on
// the main menu (menu.h) over the attract demo, launches the missions the menu picks and shows
// their results; with --level the Menu holds only the pause screen. The player's settings and
// progress are kept in user_config_dir() either way. window_loop.cpp has the frame (devices,
// ticks, drawing); window_session.cpp the games it starts and what the menus ask for.
#pragma once
#include <atomic>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assets/screenshot_writer.h"
#include "core/clock.h"
#include "game/app/app_options.h"
#include "game/app/audio_session.h"
#include "game/app/dev_panel_gate.h"
#include "game/app/hot_reload.h"
#include "game/app/input_bindings.h"
#include "game/app/menu.h"
#include "game/app/net_match.h"
#include "game/app/scene_resources.h"
#include "game/app/screen_notices.h"
#include "game/app/session_recorder.h"
#include "game/app/user_settings.h"
#include "game/render/hud_layout.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "game/workbench/game_panel.h"
#include "gfx/renderer.h"
#include "particles/particle_store.h"
#include "platform/platform.h"

namespace arc {

class WindowSession {
 public:
  explicit WindowSession(const AppOptions& options);
  ~WindowSession();
  // Loads the bindings, the HUD settings and the level (bad files are one line and exit 2
  // before any window opens), opens the window, makes the renderer and starts the game and the
  // recording.
  void setup();
  bool open() const { return !window_->should_close(); }
  double time() const { return window_->time_seconds(); }
  int64_t tick() const { return int64_t(shown_game().world().tick); }
  FrameStats frame_stats() const { return renderer_->last_stats(); }
  // The frame just shown took `seconds` (its whole interval): render.target_frame_ms follows it.
  void frame_done(double seconds) { renderer_->report_frame_time(seconds * 1000.0); }
  bool write_failed() const { return write_failed_ || (recorder_ && recorder_->failed()); }
  bool net_failed() const { return net_failed_; }
  // One frame's work before drawing: devices to input and actions, the menu or pause screen,
  // reloads of changed files, and the fixed-step ticks that `frame_seconds` of wall clock owe.
  void update(double frame_seconds);
  // The game at the clock's alpha, the menu over it, a requested screenshot; then the swap.
  void draw();

 private:
  // window_loop.cpp: the frame.
  void handle_actions(bool over_game);
  void handle_sound_keys(bool menu_open);
  void sync_pause_screen();
  void step_ticks(double frame_seconds);
  void report_screenshots(const std::vector<ScreenshotWriter::Done>& shots);
  // window_net.cpp: a network match (net_match.h) in the window, from the command line or the menu.
  bool net_playing() const { return net_ && net_->peer_ready(); }
  const Game& shown_game() const { return net_playing() ? net_->peer().session().game() : *game_; }
  void start_net(NetMatch::Config c, bool standalone);
  void update_net();
  void step_net_ticks(double frame_seconds);
  void net_view(bool on);  // the local slot's ship as the player and its own chase camera
  void fill_net_hud();
  void end_net(const std::string& why);
  void net_escape();
  std::vector<NetMission> net_missions() const;
  // window_session.cpp: the games and the menus' requests.
  std::unique_ptr<Renderer> make_renderer() const;
  void adopt_device_look();  // the first start's preset by device (device_look.h)
  void load_user_files_and_bindings();
  Settings user_render_settings() const;
  void start_game(std::unique_ptr<Game> fresh);
  void load_models_for(const Game& fresh);
  void warm_launches();
  void prepare_launch();
  void warm_prepared_launch();
  std::unique_ptr<Game> take_prepared(const std::string& level);
  void set_flight_scale();
  // `ship` and `loadout`: the briefing's choice for the player ("": the level's own).
  void launch(const std::string& level, Difficulty difficulty, const std::string& ship = "", const std::string& loadout = "");
  void restart();
  std::string reload_level();
  void back_to_main_menu();
  void update_menu();
  void carry_out(const std::vector<MenuRequest>& requests);
  void apply_changed_settings();
  void show_results_when_decided();
  void end_recording(const char* why);
  std::string attract_level() const;
  PauseState pause_state() const;

  const AppOptions& options_;
  GameOptions game_options_;  // the pause screen's difficulty changes it for the next restart
  std::string level_;         // the level playing: --level, the attract demo or a menu pick
  Settings settings_;         // render and simulation settings: the user's preset, then --quality and --set
  UserFiles user_;            // the player's settings and progress as loaded (the menu keeps them after)
  Bindings bindings_;         // flown with: the bindings file, the user's settings over it
  std::optional<Menu> menu_;  // the main menu, mission select, results (not with --level) and the pause screen
  std::vector<HudBox> menu_boxes_;  // the menu items as last drawn, for the mouse
  bool mission_running_ = false;    // a level launched from the menu: its end shows the results
  double results_at_ = -1;          // window time at which the decided mission's results open
  bool recording_started_ = false;  // --record from the menu: only the first launched mission
  std::unique_ptr<Window> window_;
  std::unique_ptr<Renderer> renderer_;
  DevPanelGate panel_gate_;            // the panel pauses the fight while it is open
  std::unique_ptr<GamePanel> panel_;  // F1: every setting live, and the effects (game/workbench/game_panel.h)
  std::vector<ModelId> models_;  // the renderer's id of each of the level's model slots
  SceneModels scene_models_;     // every model the renderer holds, by path
  // A particle store written through ahead of the next launch (the last game's, once free), so
  // a launch does not allocate and clear one in its first frame.
  std::shared_ptr<ParticleStore> spare_store_;
  // The game the briefing on screen would launch, loading on a worker (prepare_launch()), and
  // those no longer wanted, kept until their worker is done so that dropping one never waits.
  struct PreparedLaunch {
    std::string level;
    GameOptions options;
    std::future<std::unique_ptr<Game>> game;
    // The loaded level's seed, set by the worker once it is known: its sky is baked ahead, a
    // face a frame, while the briefing is read.
    struct Seed {
      uint64_t value = 0;
      std::atomic<bool> known{false};  // value is written first
    };
    std::shared_ptr<Seed> seed;
    bool sky_ready = false;
  };
  std::optional<PreparedLaunch> prepared_;
  std::vector<std::future<std::unique_ptr<Game>>> retired_;
  std::unique_ptr<Game> game_;
  std::unique_ptr<SessionRecorder> recorder_;
  std::unique_ptr<AudioSession> audio_;  // sounds.json is checked before the window opens
  std::optional<LiveInput> input_;
  std::optional<FixedStepClock> clock_;
  InputState devices_, previous_devices_;
  std::vector<Command> pending_;  // menu commands wait for the next tick rather than being lost
  HudState hud_;
  ScreenNotices notices_;  // the notice line and the FPS counter
  RenderView view_;
  bool mouse_captured_ = true;
  bool cursor_jumped_ = false;  // captured or released since the last poll
  bool want_screenshot_ = false;
  ScreenshotWriter screenshots_{"out/screenshots", "arcfire"};  // F12, written in the background
  HotReload reload_;           // levels, ships, effects, shaders and sounds
  bool write_failed_ = false;  // a recording failed to write: the session exits 1
  // The network match: the lobby, then the match the window shows (window_net.cpp).
  std::unique_ptr<NetMatch> net_;
  bool net_standalone_ = false;  // --host / --join: the window closes when the match ends
  bool net_view_on_ = false;
  ShipId net_saved_player_;
  CameraRig net_saved_camera_, net_saved_prev_camera_, net_camera_, net_prev_camera_;
  bool net_camera_known_ = false;
  std::vector<std::pair<double, uint64_t>> net_rollback_samples_;  // window time, rollbacks so far
  double net_escape_at_ = -1e9;
  double net_over_at_ = -1;      // when the match ended (the window closes or returns 4 s later)
  bool net_results_shown_ = false;
  bool net_reported_ = false;
  bool net_failed_ = false;      // refused or no host (command line): the session exits 2
};

}  // namespace arc
