// game/app/user_settings.h — the player's own settings and progress, kept between runs.
//
// Two JSON files in user_config_dir() ($XDG_CONFIG_HOME/arcfire, default ~/.config/arcfire):
//   settings.json  quality preset and single render settings over it, mouse sensitivity and Y
//                  inversion, gamepad dead zone, field of view, fullscreen, vsync, the
//                  developer panel's switch, the keys the player remapped (action → key)
//                  the mod folders to play with, the pilot's network name ("net_name")
//                  and the hosts last joined ("recent_hosts")
//   progress.json  the best result per mission and difficulty
// (quick_battle.json beside them, the last quick battle setup, is game/app/quick_battle.h's.)
// Both are written atomically (core/file_writer.h write_file_atomic). A file that does not parse or
// validate is never lost silently: load_user_files() copies it to NAME.bak, writes the defaults
// in its place and returns the message the menu shows on screen. No GL: the menu's tests drive
// it in a temporary folder.
//
// Example, compiled as AppExamples.UserFiles in tests/unit/app/test_app_examples.cpp:
//   UserFiles files = load_user_files(user_config_dir(), "assets/settings/quality.json");
//   if (!files.message.empty()) notices.push_back(files.message);
//   files.settings.mouse_sensitivity = 0.2;
//   save_settings(files.dir, files.settings);
#pragma once
#include <map>
#include <string>
#include <vector>

#include "core/settings.h"
#include "game/app/input_bindings.h"

namespace arc {

inline constexpr size_t kMaxUserMods = 16;

// The quality choice that applies no preset: all_settings().
inline constexpr const char* kDefaultQuality = "default";

struct UserSettings {
  // A preset of assets/settings/quality.json, or "default": the built-in settings (made for a
  // software rasteriser: the look's presets cost more than a 60 Hz frame on llvmpipe).
  std::string quality = "default";
  double mouse_sensitivity = 0.12;  // degrees per pixel (relative mouse mode)
  bool invert_y = false;            // mouse and gamepad
  double pad_deadzone = 0.12;
  double fov = 60.0;                // degrees, vertical, for chase and cockpit cameras
  bool fullscreen = false;
  bool vsync = true;
  bool developer_panel = false;     // F1 opens the tweak panel in the game (always with --dev)
  std::map<std::string, std::string> keys;  // remap action id (key_remap.h) → key name
  std::map<std::string, std::string> render;  // setting key (core/settings.h) → value, over the preset
  std::vector<std::string> mods;  // mod folders laid over the data in a window (core/data_layers.h) unless --mod is given
  std::string net_name = "Pilot";          // the pilot's name in network matches (1..24 printable ASCII)
  std::vector<std::string> recent_hosts;   // the addresses last joined, newest first (at most 5)
  bool operator==(const UserSettings&) const = default;
};

// One mission's best: a victory beats any defeat; between victories the one with more bonus
// objectives done, then the quicker; between defeats the one that dealt more damage.
struct MissionResult {
  bool victory = false;
  double seconds = 0;
  int kills = 0;
  double damage_dealt = 0, damage_taken = 0;
  double beam_accuracy = 0, missile_accuracy = 0;
  // Objectives of levels that have them: primary and secondary (bonus; hidden ones count once
  // revealed) done, of how many.
  int primary_done = 0, primary_total = 0, bonus_done = 0, bonus_total = 0;
  bool operator==(const MissionResult&) const = default;
};
bool better_result(const MissionResult& a, const MissionResult& than);

// progress.json: format 2 adds the objectives to each result; format 1 files still load.
struct Progress {
  std::map<std::string, MissionResult> best;  // progress_key(level, difficulty) → best result
  bool operator==(const Progress&) const = default;
};
// "duel/normal": the level file's stem and the difficulty.
std::string progress_key(const std::string& level_path, const std::string& difficulty);
// Keeps `r` as the best of its mission when it beats the one kept (or there is none); true if kept.
bool record_result(Progress& p, const std::string& key, const MissionResult& r);

struct UserFiles {
  std::string dir;
  UserSettings settings;
  Progress progress;
  std::string message;  // why a file was replaced by defaults (and where its copy is); "" if none
  bool settings_found = false;  // settings.json was there: its preset was chosen (device_look.h)
};

// $XDG_CONFIG_HOME/arcfire, else $HOME/.config/arcfire (else ./.arcfire-config).
std::string user_config_dir();
// Reads both files; a missing file gives defaults, a bad one is kept as .bak and replaced.
// `quality_file` lists the allowed quality presets.
UserFiles load_user_files(const std::string& dir, const std::string& quality_file);
// The mod folders of `dir`/settings.json; none when it is missing or does not load.
std::vector<std::string> user_mods(const std::string& dir);
// Positioned InputError for a bad file (load_user_files catches it).
UserSettings parse_settings(const std::string& text, const std::string& path,
                            const std::vector<std::string>& quality_presets);
Progress parse_progress(const std::string& text, const std::string& path);
std::string settings_json(const UserSettings& s);
std::string progress_json(const Progress& p);
// Copies a bad file to NAME.bak and writes `defaults` in its place; the one-line message for the
// screen (load_user_files and the quick battle setup).
std::string replace_bad_file(const std::string& path, const std::string& defaults, const std::string& error);
// Atomic writes into `dir` (made if missing); InputError when it cannot be written.
void save_settings(const std::string& dir, const UserSettings& s);
void save_progress(const std::string& dir, const Progress& p);

// The render and simulation settings the user chose: the defaults, their quality preset from
// `quality_file`, then their own values of single settings. InputError for a bad preset or value.
Settings user_quality_settings(const UserSettings& s, const std::string& quality_file);

// The bindings a session flies with: the bindings file, then the user's settings over it,
// unless the file was named with --bindings (it overrides the user's settings then).
void apply_user_settings(const UserSettings& s, Bindings& b);

}  // namespace arc
