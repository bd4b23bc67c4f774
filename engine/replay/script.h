// replay/script.h — replay scripts: a line-based text format people write by hand and the
// game records, parsed into plain structs (no game types, no GL).
//
// A script is a header (format version, level, seed, tick rate, difficulty, build id; for a
// network match its slots and pilots) and then tick-stamped lines: input (press, release, axis;
// in a match per slot), commands, checks (expect, hash, full_hash, snapshot) and `end`. The full format, with an example of every line, is in
// tests/replays/README.md. Every malformed line throws InputError "path:line:col: message".
//
// Example, compiled as ScriptExample.LoadWalkWrite in tests/unit/replay/test_examples.cpp:
//   const Settings known = all_settings();                        // game/app/all_settings.h
//   Script s = load_script("tests/replays/range_course.replay", known);  // or parse_script(text, path, known)
//   for (const InputEvent& e : s.inputs) ticks.push_back(e.tick);  // in tick order
//   std::string text = write_script(s);                           // parse(write(s)) == s
//
// Tick semantics: lines stamped T apply to the state after T simulation steps (Game::step
// calls; a paused step counts although game time stands still). Checks at T look at that
// state; inputs and commands at T feed step T + 1. The run stops after the checks at `end`.
//
// Axes are quantised to signed bytes exactly like live input (game/sim/input.h), so a file
// written from recorded bytes parses back to the very same bytes.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace arc {
class Settings;
}

namespace arc::replay {

// Version 2 adds network matches (`slots`, `pilot`, `drop` and `slot K` lines); a script
// without them is written as version 1, and both versions load.
constexpr int kFormatVersion = 2;
constexpr int kFirstFormatVersion = 1;
constexpr int kMaxSlots = 8;

// Same order, bits and values as the game's InputFrame / InputButton / Command; game/app
// static_asserts the correspondence where it converts.
enum class Axis : uint8_t { Pitch = 0, Yaw, Roll, Throttle, StrafeX, StrafeY };
constexpr int kAxisCount = 6;
enum Button : uint16_t { kFirePrimary = 1 << 0, kFireSecondary = 1 << 1, kAfterburner = 1 << 2, kFlightAssist = 1 << 3 };
enum class ScriptCommand : uint8_t {
  TargetNext = 1, TargetNearest, TargetNextHostile, SwitchWeapon, CameraToggle, Pause, Resume, CameraPadlock,
  Countermeasure, OrderAttack, OrderCover, OrderFormUp, OrderEngage, TargetSubsystem
};

const char* axis_name(Axis a);
const char* button_name(Button b);  // "fire_primary", ...
const char* command_name(ScriptCommand c);

// −1..1 → −127..127, the live-input quantisation (non-finite → 0).
int8_t quantise_axis(double v);
// The shortest decimal text that quantises back to q ("0.5039" for 64).
std::string axis_text(int8_t q);

// Held input between ticks: what an InputFrame carries.
struct InputState {
  std::array<int8_t, kAxisCount> axes{};
  uint16_t buttons = 0;
  bool operator==(const InputState&) const = default;
};

struct SourceLine {
  int line = 0;       // 1-based line in the script
  std::string text;   // the line as written, for failure messages
  bool operator==(const SourceLine&) const = default;
};

// `quality NAME`: a preset of assets/settings/quality.json, applied before the `set` lines.
struct QualityLine {
  std::string preset;
  int line = 0, col = 0;  // where the name is written, for "unknown preset" errors
  bool operator==(const QualityLine&) const = default;
};

// `set key=value`: one setting, any key `arcfire --list-settings` shows, as `--set` sets it.
struct SettingLine {
  std::string key, value;  // checked against the parser's known settings
  int line = 0, col = 0;
  bool operator==(const SettingLine&) const = default;
};

// `mod NAME HASH`: a mod folder laid over the data root (core/data_layers.h) when the script was
// written, with its content hash; the replay refuses to run under other mods or other content.
struct ModLine {
  std::string name;
  uint64_t hash = 0;
  int line = 0, col = 0;
  bool operator==(const ModLine& o) const { return name == o.name && hash == o.hash; }
};

// `tolerance 5/255 99.9%`: how far a snapshot may differ from its golden image.
struct SnapshotTolerance {
  int max_channel_diff = 5;   // in 1/255 steps, 0..255
  double min_percent = 99.9;  // of pixels within max_channel_diff, (0, 100]
  bool operator==(const SnapshotTolerance&) const = default;
};

// `pilot SLOT NAME`: a pilot flew the slot's ship (its `slot K` lines); `drop SLOT TICK`: from
// step TICK + 1 on the AI flies it (the pilot left).
struct PilotLine {
  int slot = 0;
  std::string name;
  std::optional<uint64_t> drop;
  bool operator==(const PilotLine&) const = default;
};

struct Header {
  int version = kFirstFormatVersion;  // what the file says; a script with slots is version 2
  std::string level;                // required, relative to the working folder or the data root (or absolute)
  int level_line = 0;               // where the level line is, for "not found" messages
  std::optional<uint64_t> seed;     // absent: the level's own
  std::optional<int> tick_rate;     // absent: the level's own; present: must equal it
  std::optional<std::string> difficulty;  // "easy" | "normal" | "hard"; absent: the level's
  // The briefing's choice: the player's ship class and loadout ("beam+torpedo"); "": the level's.
  std::string ship;
  std::string loadout;
  std::string build;                // informational: the build that wrote the file
  int snapshot_width = 640, snapshot_height = 360;
  // Settings that change the simulation (--quality / --set); absent: the replay's own.
  std::optional<uint32_t> particle_budget;    // particles.budget, 1000..4000000
  std::optional<int> lightning_interval;      // particles.lightning_interval, 0..60
  std::optional<int> substeps;                // sim.substeps, 1..16
  // Settings the script runs under, on top of the command line's: the quality preset first,
  // then the `set` lines in order. Their simulation keys change the game as --set does; the
  // three keys above win over the preset, and a `set` line may not repeat them.
  std::optional<QualityLine> quality;
  std::vector<SettingLine> settings;
  std::optional<SnapshotTolerance> tolerance;  // absent: image_compare's 5/255 on 99.9 %
  std::vector<ModLine> mods;                   // in the order they were laid
  // `snapshots_like NAME`: snapshots compare with golden/NAME/ (another script's frames, which
  // this scene must look like) and --update-golden leaves those images alone. "": its own.
  std::string snapshots_like;
  // `slots N`: a network match over the level's N slots, each flown by the AI unless a `pilot`
  // line names it; 0: the single-player game.
  int slots = 0;
  std::vector<PilotLine> pilots;  // by slot
  // Equal content, ignoring where lines are written.
  bool same_content(const Header& other) const;
};

struct InputEvent {
  enum class Kind : uint8_t { Press, Release, Axis };
  uint64_t tick = 0;
  Kind kind = Kind::Press;
  Button button = kFirePrimary;  // Press / Release
  Axis axis = Axis::Pitch;       // Axis
  int8_t value = 0;              // Axis, quantised
  uint8_t slot = 0;              // the slot whose input it is (`slot K` lines; 0: the player's)
  SourceLine src;
  bool operator==(const InputEvent&) const = default;
};

struct CommandEvent {
  uint64_t tick = 0;
  ScriptCommand command = ScriptCommand::TargetNext;
  uint8_t slot = 0;
  SourceLine src;
  bool operator==(const CommandEvent&) const = default;
};

struct Range {
  double min = 0, max = 0;
  bool contains(double v) const { return v >= min && v <= max; }
  bool operator==(const Range&) const = default;
};

struct Expectation {
  enum class Kind : uint8_t {
    Alive, Destroyed, Hull, Shield, Position, Distance, Particles, Winner,
    Kills, DamageDealt, DamageTaken, Accuracy,  // the ship's combat counters
    Sound  // a sound event of that tick (game/render/sound_events.h), e.g. `expect sound explosion`
  };
  uint64_t tick = 0;
  Kind kind = Kind::Alive;
  std::string ship;   // Alive .. Distance
  std::string other;  // Distance: the second ship
  int ship_col = 0, other_col = 0;  // where the names are written, for "no such ship" errors
  std::string team;   // Winner: a team name, or "none" while undecided
  std::string weapon; // Accuracy: "beam" or "missile"
  std::string sound;  // Sound: the event's name, checked against the game's at load
  int sound_col = 0;
  Range range;        // Hull, Shield, Distance, Particles, Kills, DamageDealt, DamageTaken, Accuracy
  std::array<Range, 3> box{};  // Position: x, y, z
  SourceLine src;
  bool operator==(const Expectation&) const = default;
};

struct HashCheck {
  uint64_t tick = 0;
  bool full = false;              // full_hash (every particle) instead of the cheap hash
  std::optional<uint64_t> value;  // absent ("?"): to be filled in by --update-golden
  SourceLine src;
  bool operator==(const HashCheck&) const = default;
};

struct SnapshotCheck {
  uint64_t tick = 0;
  std::string name;  // [A-Za-z0-9_-]+, the golden file is golden/<script>/<name>.png
  SourceLine src;
  bool operator==(const SnapshotCheck&) const = default;
};

struct Script {
  std::string path;
  Header header;
  std::vector<InputEvent> inputs;        // all vectors in non-decreasing tick order
  std::vector<CommandEvent> commands;
  std::vector<Expectation> expectations;
  std::vector<HashCheck> hashes;
  std::vector<SnapshotCheck> snapshots;
  std::optional<uint64_t> end_tick;  // absent (a recording cut short): the last stamped tick
  SourceLine end_src;

  // The tick the run stops at: `end`, else the last tick any line names.
  uint64_t last_tick() const;
  // Equal content, ignoring source positions and text.
  bool same_content(const Script& other) const;
};

// `known` holds every setting a `set` line may name, at its allowed values (the game's:
// game/app/all_settings.h); the replay format itself knows no setting.
Script parse_script(const std::string& text, const std::string& path, const Settings& known);
// InputError "path: cannot read file" when missing.
Script load_script(const std::string& path, const Settings& known);

// The whole script as text in the canonical form (header, then lines in tick order: inputs,
// commands, then checks). Source positions are not used.
std::string write_script(const Script& script);

// Single lines, as the recorder appends them (each ends with '\n').
std::string header_text(const Header& header);
std::string input_event_line(const InputEvent& e);
std::string command_line(const CommandEvent& c);
std::string hash_line(const HashCheck& h);
std::string end_line(uint64_t tick);
// The press/release/axis lines that turn `before` into `after` at `tick` ("" when equal).
std::string input_diff_lines(uint64_t tick, const InputState& before, const InputState& after, uint8_t slot = 0);

// Applies one input event to the held state.
void apply_input(InputState& state, const InputEvent& e);

// Replaces the value of every hash line (by its source line) with `values[i]` for
// script.hashes[i], keeping every other byte of the original text. For --update-golden.
std::string fill_hash_values(const std::string& original_text, const Script& script,
                             const std::vector<uint64_t>& values);

std::string hex64(uint64_t v);  // 16 lowercase hex digits

}  // namespace arc::replay
