// The arcfire command line: options defined with CLI11, then checked and resolved.
#include "game/app/app_options.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>

#include "audio/sound_library.h"
#include "core/data_layers.h"
#include "core/data_root.h"
#include "core/error.h"
#include "core/file_writer.h"
#include "core/input_file.h"
#include "core/input_limits.h"
#include "core/json.h"
#include "game/app/effect_preview.h"
#include "game/app/input_bindings.h"
#include "game/app/user_settings.h"
#include "replay/script.h"

namespace arc {
namespace {

// "1280x720" → width, height; sizes from 16 to 8192.
bool parse_size(const std::string& text, int& w, int& h) {
  auto x = text.find('x');
  if (x == std::string::npos) return false;
  try {
    size_t a = 0, b = 0;
    int pw = std::stoi(text.substr(0, x), &a);
    int ph = std::stoi(text.substr(x + 1), &b);
    if (a != x || b != text.size() - x - 1) return false;
    if (pw < 16 || ph < 16 || pw > 8192 || ph > 8192) return false;
    w = pw;
    h = ph;
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

void apply_simulation_settings(const Settings& s, GameOptions& game) {
  game.particle_budget = uint32_t(s.integer("particles.budget"));
  game.lightning_interval = int(s.integer("particles.lightning_interval"));
  game.substeps = int(s.integer("sim.substeps"));
  game.autopilot = s.integer("sim.autopilot") != 0;
  game.sim_threads = int(s.integer("sim.threads"));
  game.cull_distance = s.number("particles.cull_distance");
}

std::string resolve_data_path(const std::string& path, const std::string& option, const std::string& root) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const std::string in_root = data_file(root, path);  // a mod's file first, then the data root's
  const bool relative = fs::path(path).is_relative();
  // Named from inside the data root itself (levels/duel.json run in the source tree): a mod
  // that replaces that file wins, as it does for every file the game finds itself.
  if (relative && !data_layers().mod_of(in_root).empty() && fs::equivalent(path, fs::path(root) / path, ec))
    return in_root;
  // What the name finds first is used, or refused with what it is (a folder, a FIFO, a loop...).
  const std::string found = input_path_exists(path) ? path : relative && input_path_exists(in_root) ? in_root : "";
  if (found.empty()) throw InputError(option + " " + path + ": no such file");
  if (const std::string problem = input_path_problem(found); !problem.empty())
    throw InputError(option + " " + found + ": " + problem + "; allowed: a regular file");
  return found;
}

namespace {

// Options as written on the command line, before they are checked and resolved.
struct CommandLineText {
  std::string data;
  std::vector<std::string> mods;
  bool version = false;
  std::string size = "1280x720";
  std::string quality;
  std::vector<std::string> sets;
  std::string difficulty;
  int64_t seed = -1;
  bool list_settings = false;
  bool no_vsync = false;
};

void define_options(CLI::App& app, AppOptions& o, CommandLineText& t) {
  app.add_option("--data", t.data,
                 "the data folder (assets/, levels/, shaders/); default: ARCFIRE_DATA, else ../share/arcfire "
                 "beside the program, else the source tree of a development build");
  app.add_option("--level", o.level, "level file to play or simulate (default levels/duel.json)");
  app.add_flag("--headless", o.headless, "run without a window (EGL, no display needed)");
  app.add_flag("--demo", o.demo, "headless attract demo: AI against AI, frames and a contact sheet in --out");
  app.add_option("--ticks", o.ticks, "headless: number of simulation ticks to run")->check(CLI::Range(int64_t(1), int64_t(100000000)));
  app.add_option("--every", o.every, "headless: write a PNG frame every N ticks into --out")->check(CLI::Range(int64_t(1), int64_t(100000000)));
  app.add_option("--size", t.size, "frame size for headless rendering, WIDTHxHEIGHT (16..8192)");
  app.add_option("--out", o.out_dir, "folder for frames, snapshots and reports (created if missing)");
  app.add_flag("--no-render", o.no_render, "headless: simulate only, create no GL context");
  app.add_option("--summary", o.summary_path, "headless: write the final world state as JSON to this file");
  app.add_option("--record", o.record_path, "record the live session to a replay script");
  app.add_option("--replay", o.replay_path, "headless: replay a script and check its expectations");
  app.add_option("--menu-script", o.menu_script,
                 "headless: drive the menu with a script of UI inputs, a snapshot of each screen in --out");
  app.add_flag("--update-golden", o.update_golden, "replay: write snapshots as the new golden images");
  app.add_option("--serialization-test", o.serialization_test,
                 "save and reload the world every N ticks beside the original; fail at the first differing hash")
      ->check(CLI::Range(int64_t(1), int64_t(1000000)));
  app.add_option("--quality", t.quality, "quality preset: low, medium, high or reference");
  app.add_option("--set", t.sets, "override one setting, key=value (repeatable; see --list-settings)");
  app.add_flag("--list-settings", t.list_settings, "list every setting: value, allowed range, what it does and its cost");
  app.add_option("--difficulty", t.difficulty, "AI difficulty: easy, normal or hard (default: the level's)");
  app.add_option("--ship", o.game.ship, "the player's ship class (a file stem of assets/ships; default: the level's)");
  app.add_option("--loadout", o.game.loadout,
                 "the player's weapons, PRIMARY+SECONDARY: beam or plasma, then plasma, missile or torpedo (e.g. beam+torpedo)");
  app.add_option("--seed", t.seed, "override the level's random seed")->check(CLI::Range(int64_t(0), int64_t(4294967295)));
  app.add_option("--bindings", o.bindings_path,
                 "key and gamepad bindings file; a missing file is created with the defaults to edit");
  app.add_option("--sounds", o.sounds_path, "sound definitions, synthesised at start-up (default assets/sounds/sounds.json)");
  app.add_option("--audio-out", o.audio_out,
                 "headless or replay: render the session's sound through OpenAL's loopback device into this WAV file");
  app.add_option("--preview", o.preview_path,
                 "headless: a filmstrip of one effect file (assets/effects/NAME.json) and stats.json into --out");
  app.add_option("--frames", o.preview_frames, "preview: moments of the effect's life in the filmstrip (default 8)")
      ->check(CLI::Range(1, 64));
  app.add_option("--backdrop", o.preview_backdrop, "preview: space (default), wall or a model of assets/models");
  app.add_flag("--fullscreen", o.fullscreen, "start in fullscreen (F11 or Alt+Enter toggles)");
  app.add_flag("--no-vsync", t.no_vsync, "do not wait for vertical sync");
  app.add_flag("--fps", o.show_fps, "show the FPS counter (F3 toggles)");
  app.add_flag("--dev", o.dev, "F1 opens the developer panel (else only with Settings > Advanced > Developer panel)");
  app.add_option("--frame-times", o.frame_times_path, "window: write each frame's time to this CSV file and print the percentiles at exit");
  app.add_option("--workbench", o.workbench_effect,
                 "open the effect workbench on an effect file (default: the first in assets/effects)")
      ->expected(0, 1);
  app.add_flag("--version", t.version, "print the version and the data folder in use, then exit");
  app.add_option("--mod", t.mods,
                 "lay a mod folder over the data (repeatable; later mods over earlier ones); a window without "
                 "--mod uses the mods of the player's settings");
  define_net_options(app, o.net);
}

void resolve_preview_options(const CLI::App& app, AppOptions& o) {
  const bool frames = app.get_option("--frames")->count() > 0, backdrop = app.get_option("--backdrop")->count() > 0;
  if (o.preview_path.empty()) {
    if (frames || backdrop) throw InputError(std::string(frames ? "--frames" : "--backdrop") + ": only with --preview");
    return;
  }
  if (!o.headless) throw InputError("--preview: only with --headless");
  if (o.out_dir.empty()) throw InputError("--preview: needs --out DIR for the filmstrip and stats.json");
  o.preview_path = resolve_data_path(o.preview_path, "--preview", o.game.root_dir);
  const std::string bad_backdrop = check_preview_backdrop(o.preview_backdrop, o.game.root_dir);
  if (!bad_backdrop.empty()) throw InputError(bad_backdrop);
}

// An option given an empty value (`--quality ""`) is refused with what it takes instead.
void refuse_empty_values(const CLI::App& app) {
  static const std::map<std::string, std::string> allowed = {
      {"--quality", "low, medium, high or reference"}, {"--difficulty", "easy, normal or hard"},
      {"--ship", "a ship class name"}, {"--loadout", "PRIMARY+SECONDARY"},
      {"--backdrop", "space, wall or a model of assets/models"}, {"--size", "WIDTHxHEIGHT"},
      {"--set", "key=value"}, {"--data", "a folder"}, {"--mod", "a folder"}, {"--out", "a folder"}};
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->count() == 0 || opt->get_expected_min() == 0) continue;  // --workbench alone: its first effect
    for (const std::string& value : opt->results()) {
      if (!value.empty()) continue;
      const auto it = allowed.find(opt->get_name());
      throw InputError(opt->get_name() + ": empty value; allowed: " + (it != allowed.end() ? it->second : "a file name"));
    }
  }
}

// Modes exclude each other, and an option the chosen mode would ignore is refused, not dropped.
void refuse_contradictions(const CLI::App& app, const AppOptions& o) {
  auto given = [&](const char* name) { return app.get_option(name)->count() > 0; };
  std::vector<std::string> modes;
  for (const char* m : {"--replay", "--serialization-test", "--menu-script", "--preview", "--workbench", "--demo"})
    if (given(m)) modes.push_back(m);
  if (modes.size() > 1)
    throw InputError(modes[0] + " and " + modes[1] + ": one mode at a time (--replay, --serialization-test, "
                     "--menu-script, --preview, --workbench or --demo)");
  const bool replay = given("--replay"), serialization = given("--serialization-test");
  const bool headless_run = (o.headless || o.demo) && modes.size() == (o.demo ? 1u : 0u);
  const bool window = !o.headless && modes.empty();
  const struct {
    const char* option;
    bool ok;
    const char* allowed;
  } rules[] = {
      {"--level", !replay, "not with --replay: the script names its level"},
      {"--ticks", !replay, "not with --replay: the script decides how many ticks"},
      {"--seed", !replay, "not with --replay: the script decides the seed"},
      {"--difficulty", !replay, "not with --replay: the script decides the difficulty"},
      {"--ship", !replay, "not with --replay: the script names the ship"},
      {"--loadout", !replay, "not with --replay: the script names the loadout"},
      {"--size", !replay, "not with --replay: the script decides the snapshot size"},
      {"--ticks", headless_run || serialization || o.net.active(), "only with --headless, --demo, --serialization-test, --host or --join"},
      {"--summary", headless_run, "only with --headless or --demo"},
      {"--every", headless_run && !o.no_render && (o.demo || given("--out")),
       "only with --headless and --out, drawing frames (not with --no-render)"},
      {"--out", !(headless_run && o.no_render), "not with --no-render: a headless run writes only frames there"},
      {"--demo", !o.no_render, "not with --no-render: the demo is its frames"},
      {"--record", window, "only in a window (it records the live session)"},
      {"--fullscreen", window, "only in a window"},
      {"--fps", window, "only in a window"},
      {"--dev", window, "only in a window"},
      {"--no-vsync", window || given("--workbench"), "only in a window"},
  };
  for (const auto& r : rules)
    if (given(r.option) && !r.ok) throw InputError(std::string(r.option) + ": " + r.allowed);
}

// The files named on the command line, read and written: no output may be an input.
void name_command_line_files(const CLI::App& app, AppOptions& o) {
  RunFiles& f = o.files;
  if (o.replay_path.empty()) f.input("--level", o.level);
  f.input("--bindings", o.bindings_path);
  f.input("--sounds", o.sounds_path);
  f.input("--replay", o.replay_path);
  f.input("--menu-script", o.menu_script);
  f.input("--preview", o.preview_path);
  f.input("--workbench", o.workbench_effect);
  if (o.quality_given || o.demo) f.input("quality presets", data_file(o.game.root_dir, "assets/settings/quality.json"));
  f.output("--summary", o.summary_path);
  f.output("--audio-out", o.audio_out);
  f.output("--record", o.record_path);
  f.output("--frame-times", o.frame_times_path);
  if (app.get_option("--out")->count() > 0 && o.replay_path.empty()) {
    auto ends = [](const std::string& name, const char* tail) { return name.ends_with(tail); };
    if (!o.menu_script.empty())
      f.output_folder("--out", o.out_dir, [=](const std::string& n) { return ends(n, ".png") || ends(n, ".txt"); });
    else if (!o.preview_path.empty())
      f.output_folder("--out", o.out_dir, [=](const std::string& n) { return ends(n, ".png") || n == "stats.json"; });
    else
      f.output_folder("--out", o.out_dir, [=](const std::string& n) {
        return (n.starts_with("frame_") && ends(n, ".png")) || n == "contact_sheet.png";
      });
  }
  f.check();
}

// The mods over the data root: --mod's, else in a window the player's (settings.json "mods"). A
// bad --mod is bad input; a player's mod that no longer loads is skipped with a line, so a
// deleted folder cannot lock the player out of the game.
void lay_mods(const std::vector<std::string>& named, bool headless, const std::string& root) {
  DataLayers layers(root);
  for (const std::string& dir : named) layers.add_mod(dir);
  if (named.empty() && !headless) {
    for (const std::string& dir : user_mods(user_config_dir())) {
      try {
        layers.add_mod(dir);
      } catch (const InputError& e) {
        std::fprintf(stderr, "arcfire: settings.json: mod skipped: %s\n", e.what());
      }
    }
  }
  use_data_layers(std::move(layers));
}

// Files, settings and choices of the parsed command line checked and resolved into `o`;
// InputError for anything wrong.
void resolve_options(const CLI::App& app, const CommandLineText& t, AppOptions& o) {
  const std::string& root = o.game.root_dir;
  // A default file is the data root's; a named one is looked for as given, then under the root.
  auto resolve = [&](const std::string& path, const std::string& option) {
    const bool given = app.get_option(option)->count() > 0;
    return given ? resolve_data_path(path, option, root) : resolve_data_path(data_file(root, path), option, root);
  };
  o.level = resolve(o.level, "--level");
  if (!o.replay_path.empty()) check_input_path(o.replay_path, kMaxScriptFileBytes, "a replay script");
  if (!o.menu_script.empty()) check_input_path(o.menu_script, kMaxScriptFileBytes, "a menu script");
  if (app.get_option("--bindings")->count() > 0 && !input_path_exists(o.bindings_path)) {
    // A new bindings file starts as a copy of the defaults, written atomically.
    write_file_atomic(o.bindings_path, read_text_file(data_file(root, "assets/settings/bindings.json")));
    std::printf("arcfire: wrote default bindings to %s; edit it to remap keys\n", o.bindings_path.c_str());
  }
  o.bindings_path = resolve(o.bindings_path, "--bindings");
  load_bindings(o.bindings_path);  // a bad bindings file is bad input in every mode
  o.sounds_path = resolve(o.sounds_path, "--sounds");
  load_sound_library(o.sounds_path);  // so is a bad sound file
  if (!parse_size(t.size, o.width, o.height))
    throw InputError("--size: expected WIDTHxHEIGHT with each in 16..8192, got '" + t.size + "'");
  // The attract demo renders offline frames for people to look at: the full look (the high
  // preset) unless a preset is named.
  const std::string preset = !t.quality.empty() ? t.quality : o.demo ? "high" : "";
  if (!preset.empty())
    o.settings.apply_preset_file(data_file(root, "assets/settings/quality.json"), preset);
  for (const auto& s : t.sets) o.settings.set_from_text(s, "--set " + s);
  if (!t.difficulty.empty()) {
    if (t.difficulty == "easy") o.game.difficulty = Difficulty::Easy;
    else if (t.difficulty == "normal") o.game.difficulty = Difficulty::Normal;
    else if (t.difficulty == "hard") o.game.difficulty = Difficulty::Hard;
    else throw InputError("--difficulty: must be easy, normal or hard, got '" + t.difficulty + "'");
    o.game.difficulty_override = true;
  }
  if (t.seed >= 0) {
    o.game.seed_override = true;
    o.game.seed = uint64_t(t.seed);
  }
  if (o.no_render && !o.headless && o.replay_path.empty())
    throw InputError("--no-render: only with --headless or --replay");
  if (!o.audio_out.empty() && !o.headless && o.replay_path.empty())
    throw InputError("--audio-out: only with --headless or --replay");
  if (o.update_golden && o.replay_path.empty()) throw InputError("--update-golden: only with --replay");
  // Output files are checked before any run starts (core/file_writer.h); --out and --summary
  // are checked by the modes that write them.
  if (!o.audio_out.empty()) check_output_file(o.audio_out, "--audio-out");
  if (!o.record_path.empty()) check_output_file(o.record_path, "--record");
  if (!o.frame_times_path.empty() && (o.headless || !o.replay_path.empty()))
    throw InputError("--frame-times: only in a window, not with --headless or --replay");
  if (!o.frame_times_path.empty()) check_output_file(o.frame_times_path, "--frame-times");
  resolve_preview_options(app, o);
  o.workbench = app.get_option("--workbench")->count() > 0;
  if (o.workbench && (o.headless || !o.replay_path.empty())) throw InputError("--workbench: a window of its own, not with --headless or --replay");
  if (!o.workbench_effect.empty()) o.workbench_effect = resolve_data_path(o.workbench_effect, "--workbench", root);
  name_command_line_files(app, o);
}

}  // namespace

std::optional<int> parse_command_line(int argc, char** argv, AppOptions& o) {
  CLI::App app{"Arcfire: a small 3-D space-combat demo. Without options it opens a window and plays "
               "levels/duel.json.",
               "arcfire"};
  CommandLineText text;
  define_options(app, o, text);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    app.exit(e);
    return 0;
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    std::fprintf(stderr, "arcfire: %s (see arcfire --help)\n", msg.c_str());
    return int(kExitBadInput);
  }
  try {
    refuse_empty_values(app);
    refuse_contradictions(app, o);
  } catch (const InputError& e) {
    std::fprintf(stderr, "arcfire: %s\n", e.what());
    return int(kExitBadInput);
  }
  o.vsync = !text.no_vsync;
  o.size_given = app.get_option("--size")->count() > 0;
  o.level_given = app.get_option("--level")->count() > 0;
  o.bindings_given = app.get_option("--bindings")->count() > 0;
  o.quality_given = !text.quality.empty();
  o.setting_overrides = text.sets;
  if (o.demo && !o.level_given) o.level = "levels/attract.json";
  try {
    const DataRoot root = resolve_data_root(text.data, std::getenv("ARCFIRE_DATA"), executable_path());
    set_data_root(root.dir);
    o.game.root_dir = root.dir;
    lay_mods(text.mods, o.headless, root.dir);
    if (text.version) {
      std::printf("arcfire %s\ndata: %s (%s)\n", ARCFIRE_VERSION, root.dir.c_str(), root.source.c_str());
      for (const ModLayer& m : data_layers().mods())
        std::printf("mod: %s %s (%s)\n", m.name.c_str(), replay::hex64(m.hash).c_str(), m.dir.c_str());
      return 0;
    }
    resolve_options(app, text, o);
  } catch (const InputError& e) {
    std::fprintf(stderr, "arcfire: %s\n", e.what());
    return int(kExitBadInput);
  }
  apply_simulation_settings(o.settings, o.game);
  if (text.list_settings) {
    std::cout << "Settings (arcfire --set key=value; presets with --quality):\n" << o.settings.describe();
    return 0;
  }
  return std::nullopt;
}

}  // namespace arc
