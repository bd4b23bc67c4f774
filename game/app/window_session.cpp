// WindowSession's games: the user's files and settings, starting, launching, restarting and
// reloading a level, the recording's end, and what the menu and the pause screen ask for.
#include "game/app/campaign.h"
#include "game/app/key_remap.h"
#include "game/app/window_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/data_layers.h"
#include "core/error.h"
#include "game/app/device_look.h"
#include "game/app/menu_input.h"
#include "game/app/quick_battle_files.h"
#include "game/app/scene_resources.h"
#include "game/sim/world.h"

namespace arc {

WindowSession::WindowSession(const AppOptions& options)
    : options_(options),
      game_options_(options.game),
      reload_({[this] { return renderer_->reload(); }, [this] { return audio_->reload(); },
               [this] { return reload_level(); }}) {}

// The player's files (a bad one is kept as .bak and reported), and the bindings they change:
// the bindings file with the user's keys, sensitivity and inversion over it, unless the file
// was named with --bindings, which wins.
void WindowSession::load_user_files_and_bindings() {
  user_ = load_user_files(user_config_dir(), data_file(game_options_.root_dir, "assets/settings/quality.json"));
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
    s = user_quality_settings(us, data_file(game_options_.root_dir, "assets/settings/quality.json"));
    for (const std::string& set : options_.setting_overrides) s.set_from_text(set, "--set " + set);
  } catch (const InputError&) {
    return options_.settings;  // a preset the quality file no longer has: the command line's settings
  }
  return s;
}

// First start (no settings.json) without --quality: the preset follows the device that draws.
// The look changes at once; the simulation keys of the preset apply to the games launched next.
void WindowSession::adopt_device_look() {
  if (options_.quality_given || user_.settings_found) return;
  const QualityChoice c = device_default_quality(renderer_->gl_renderer());
  std::fprintf(stderr, "arcfire: quality %s\n", c.why.c_str());
  if (c.preset == user_.settings.quality) {
    menu_->adopt_device_quality(c.preset, c.why);
    return;
  }
  user_.settings.quality = c.preset;
  menu_->adopt_device_quality(c.preset, c.why);
  settings_ = user_render_settings();
  renderer_->apply_settings(settings_);
  apply_simulation_settings(settings_, game_options_);
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

// Model slots are positions in the level's model list; the renderer keeps every model it has
// loaded (and its compiled shaders), so only a model it lacks is loaded here.
void WindowSession::load_models_for(const Game& fresh) {
  models_ = scene_models_.of(*renderer_, fresh.world(), game_options_.root_dir);
}

// At the menu, what a launch would otherwise load in its first frame: every listed level's
// models, and a particle store written through.
void WindowSession::warm_launches() {
  std::vector<std::string> levels;
  for (const MissionInfo& m : load_catalog_with_campaign(game_options_.root_dir))
    levels.push_back(m.path);
  scene_models_.warm(*renderer_, levels, game_options_.root_dir);
  spare_store_ = std::make_shared<ParticleStore>(game_options_.particle_budget);
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
  notices_.show(recorder_->stop(*game_, why), window_->time_seconds(), 8.0);
  write_failed_ = write_failed_ || recorder_->failed();
  recorder_.reset();
}

std::string WindowSession::attract_level() const { return data_file(game_options_.root_dir, "levels/attract.json"); }

// On a mission's briefing, the game Launch would start is loaded on a worker thread (a Game is
// plain data, no GL), at the difficulty shown: the launch frame only takes it.
void WindowSession::prepare_launch() {
  std::erase_if(retired_, [](std::future<std::unique_ptr<Game>>& f) {
    return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
  });
  const std::string level = menu_ && menu_->has_main() ? menu_->briefing_level() : "";
  if (level.empty()) return;
  GameOptions o = game_options_;
  o.difficulty = menu_->difficulty();
  o.difficulty_override = true;
  o.ship = menu_->chosen_ship();
  o.loadout = menu_->chosen_loadout();
  if (prepared_ && prepared_->level == level && prepared_->options == o) return;
  if (prepared_) retired_.push_back(std::move(prepared_->game));  // not waited for here
  auto seed = std::make_shared<PreparedLaunch::Seed>();
  prepared_ = PreparedLaunch{level, o, std::async(std::launch::async, [level, o, seed] {
                               auto g = std::make_unique<Game>(Game::load_level(level, o));
                               seed->value = g->world().seed;
                               seed->known.store(true, std::memory_order_release);
                               return g;
                             }), seed};
}

// While the briefing is read: the prepared mission's sky, a slice a frame (in the render step,
// where the GL context is current).
void WindowSession::warm_prepared_launch() {
  if (!prepared_ || prepared_->sky_ready) return;
  const PreparedLaunch::Seed& seed = *prepared_->seed;
  if (seed.known.load(std::memory_order_acquire)) prepared_->sky_ready = renderer_->warm_sky(seed.value);
}

// The prepared game when it is the one asked for (same level and options); else nothing, and a
// level that failed to load there is loaded again to report its error.
std::unique_ptr<Game> WindowSession::take_prepared(const std::string& level) {
  std::optional<PreparedLaunch> p = std::move(prepared_);
  prepared_.reset();
  if (!p || p->level != level || !(p->options == game_options_)) {
    if (p) retired_.push_back(std::move(p->game));
    return nullptr;
  }
  try {
    return p->game.get();
  } catch (const InputError&) {
    return nullptr;
  }
}

void WindowSession::launch(const std::string& level, Difficulty difficulty, const std::string& ship,
                           const std::string& loadout) {
  end_recording("launch of another level");
  game_options_.difficulty = difficulty;
  game_options_.difficulty_override = true;
  game_options_.ship = ship;
  game_options_.loadout = loadout;
  std::unique_ptr<Game> fresh = take_prepared(level);
  if (!fresh) fresh = std::make_unique<Game>(Game::load_level(level, game_options_, std::move(spare_store_)));
  load_models_for(*fresh);
  level_ = level;
  std::shared_ptr<ParticleStore> last = game_->world().particles->store();
  start_game(std::move(fresh));
  // The last game is gone: its store, every block given back, waits for the next launch.
  if (last.use_count() == 1 && last->in_use() == 0) spare_store_ = std::move(last);
  clock_.emplace(int(std::lround(1.0 / game_->tick_seconds())));
  mission_running_ = level != attract_level();
  results_at_ = -1;
  if (!options_.record_path.empty() && mission_running_ && !recording_started_) {
    // As --level would name it: relative to the working folder when the level is inside it.
    std::string named = std::filesystem::proximate(level_).string();
    // A generated quick battle travels with its recording: the script names the copy beside it.
    if (is_quick_level(level_)) named = std::filesystem::proximate(copy_beside_recording(level_, options_.record_path)).string();
    recorder_ = std::make_unique<SessionRecorder>(options_.record_path, named, *game_);
    recording_started_ = true;
  }
}

// The pause screen's Restart (Retry): the level again, at the difficulty chosen there.
void WindowSession::restart() {
  end_recording("restart");
  start_game(std::make_unique<Game>(Game::load_level(level_, game_options_)));
  results_at_ = -1;
  menu_->close_pause();
}

// Hot reload's data action: a changed level, ship or effect restarts the level; a file that
// fails to load keeps the last good version playing, and its error is returned.
std::string WindowSession::reload_level() {
  try {
    auto fresh = std::make_unique<Game>(Game::load_level(level_, game_options_));
    load_models_for(*fresh);
    end_recording("reload of changed files");
    start_game(std::move(fresh));
    return "";
  } catch (const InputError& e) {
    return e.what();
  }
}

void WindowSession::back_to_main_menu() {
  launch(attract_level(), Difficulty::Normal);
  menu_->open_main();
}

PauseState WindowSession::pause_state() const {
  PauseState s = pause_state_of(game_->world());
  s.next = game_options_.difficulty;
  s.recording = recorder_ != nullptr;
  s.muted = audio_->muted();
  s.volume = audio_->volume();
  return s;
}

void WindowSession::update_menu() {
  for (const UiInput& in : menu_inputs(previous_devices_, devices_, menu_->capturing(), menu_boxes_)) {
    carry_out(menu_->handle(in));
    if (!menu_->open()) return;
  }
  // Back on the main menu after a mission (its results' "Menu"): the demo plays behind again.
  if (menu_->screen() == MenuScreen::Main && level_ != attract_level()) back_to_main_menu();
}

// What the menu asks for. A file that cannot be written or a level that no longer loads is
// said on the menu, not fatal.
void WindowSession::carry_out(const std::vector<MenuRequest>& requests) {
  using K = MenuRequest::Kind;
  for (const MenuRequest& r : requests) {
    try {
      switch (r.kind) {
        case K::Launch:
          if (!r.generated.empty()) write_generated_level(r.level, r.generated);
          launch(r.level, r.difficulty, r.ship, r.loadout);
          break;
        case K::SaveQuickBattle: save_quick_setup(user_.dir, menu_->quick_setup()); break;
        case K::Quit: window_->request_close(); break;
        case K::SaveSettings:
          save_settings(user_.dir, menu_->settings());
          apply_changed_settings();
          break;
        case K::SaveProgress: save_progress(user_.dir, menu_->progress()); break;
        case K::ApplyBindings:
          bindings_ = menu_->bindings();
          apply_user_settings(menu_->settings(), bindings_);
          input_.emplace(bindings_);
          hud_.key_names = key_names(bindings_);
          set_flight_scale();
          break;
        case K::Resume:  // Esc is both the pause key and the screen's Back: one resume
          if (std::find(pending_.begin(), pending_.end(), Command::Resume) == pending_.end())
            pending_.push_back(Command::Resume);
          break;
        case K::Restart: restart(); break;
        case K::SetDifficulty:
          game_options_.difficulty = r.difficulty;
          game_options_.difficulty_override = true;
          break;
        case K::ToggleMute: audio_->toggle_mute(); break;
        case K::StepVolume: audio_->step_volume(r.steps); break;
        case K::MainMenu: back_to_main_menu(); break;
        case K::NetHost: {
          NetMatch::Config c;
          c.host = true, c.level = r.level, c.port = r.steps;
          c.name = options_.net.name.empty() ? menu_->settings().net_name : options_.net.name;
          c.game.difficulty = r.difficulty, c.game.difficulty_override = true;
          start_net(c, false);
          break;
        }
        case K::NetJoin: {
          NetMatch::Config c;
          c.join = r.level;
          c.name = options_.net.name.empty() ? menu_->settings().net_name : options_.net.name;
          start_net(c, false);
          break;
        }
        case K::NetPick:
          if (net_) net_->pick_slot(r.steps);
          break;
        case K::NetLaunch:
          if (net_) net_->launch();
          break;
        case K::NetLeave:
          if (net_ && net_->peer_ready()) end_net("You left the match");
          net_view(false);
          net_.reset();
          load_models_for(*game_);
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

// A decided mission shows its outcome for a moment, then the results screen over it. The
// attract demo behind the menu starts again when it is decided.
void WindowSession::show_results_when_decided() {
  const World& w = game_->world();
  if (!menu_->has_main() || w.outcome == Outcome::Undecided) return;
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

}  // namespace arc
