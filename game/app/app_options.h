// game/app/app_options.h — the arcfire command line, parsed once into plain options.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/settings.h"
#include "game/app/all_settings.h"
#include "game/app/net_options.h"
#include "game/app/run_files.h"
#include "game/sim/game.h"

namespace arc {

struct AppOptions {
  std::string level = "levels/duel.json";
  bool level_given = false;  // --level was on the command line
  bool headless = false;
  bool demo = false;        // attract demo: AI vs AI frames and a contact sheet
  bool no_render = false;
  int64_t ticks = -1;       // headless: ticks to simulate (-1 = the mode's default)
  int64_t every = 0;        // headless: write a frame every N ticks (0 = only with --out: every 30)
  int width = 1280, height = 720;
  std::string out_dir;
  std::string summary_path;
  std::string record_path;
  std::string frame_times_path;  // --frame-times: one CSV line per window frame (app/frame_time_log.h)
  std::string replay_path;
  std::string menu_script;  // --menu-script: the menu headless, driven by scripted UI inputs
  bool workbench = false;   // --workbench: the effect workbench window
  std::string workbench_effect;  // its effect file ("" = the first of assets/effects)
  bool update_golden = false;
  int64_t serialization_test = 0;  // N > 0: save/load every N ticks
  std::string bindings_path = "assets/settings/bindings.json";
  std::string sounds_path = "assets/sounds/sounds.json";  // --sounds: checked at start in every mode
  std::string audio_out;    // --audio-out: headless and replay sound through the loopback device, as WAV
  bool bindings_given = false;  // --bindings: that file wins over the user's settings
  bool quality_given = false;   // --quality: that preset wins over the user's settings
  std::vector<std::string> setting_overrides;  // the --set texts, applied again over the user's preset
  std::string preview_path;           // --preview: an effect file's filmstrip into --out (headless)
  int preview_frames = 8;             // --frames
  std::string preview_backdrop = "space";  // --backdrop
  bool size_given = false;            // --size was on the command line
  bool fullscreen = false;
  bool vsync = true;
  bool show_fps = false;
  bool dev = false;         // --dev: F1 opens the developer panel whatever the player's settings say
  Settings settings = all_settings();
  GameOptions game;
  NetOptions net;  // network matches (net_run.h)
  RunFiles files;  // the files named on the command line, read and written (no output may be an input)
};

// The simulation keys of the settings (particles.budget, particles.lightning_interval,
// particles.cull_distance, sim.substeps) copied into the options a Game is loaded with.
void apply_simulation_settings(const Settings& s, GameOptions& game);

// A data file named on the command line: as given, or else relative to the data root `root`, so
// `arcfire --level levels/arena.json` works from any folder. InputError if neither exists.
std::string resolve_data_path(const std::string& path, const std::string& option, const std::string& root);

// Parses argv. Returns an exit code to stop with (0 after --help, 2 on bad usage), or nullopt
// to go on. Errors are one line on stderr.
std::optional<int> parse_command_line(int argc, char** argv, AppOptions& out);

}  // namespace arc
