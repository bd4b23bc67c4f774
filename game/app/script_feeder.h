// game/app/script_feeder.h — a replay script's side of a Game: what the player, the
// serialization test and the recorder share.
//
// A script (engine/replay) speaks its own plain types; these convert its held input to the
// game's InputFrame and back, resolve the level it names, gather the settings it runs under
// and the options its game is loaded with, and step a Game with the script's input and
// commands tick by tick (ScriptFeeder).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/settings.h"
#include "game/sim/game.h"
#include "replay/script.h"

namespace arc {

// Converts between the script's held input and the simulation's InputFrame.
InputFrame to_input_frame(const replay::InputState& s);
replay::InputState to_input_state(const InputFrame& f);

// The folder data files are found under: options.root_dir, or the data root (core/data_root.h) for ".".
std::string data_root_of(const GameOptions& options);

// The level a script names: as written (relative to the working folder), else relative to
// root_dir, so scripts run from any folder. InputError at the level line when neither exists.
std::string resolve_script_level(const replay::Script& script, const std::string& root_dir);
// InputError unless the mods in use (core/data_layers.h) are the script's `mod` lines: the same
// folders by name, in the same order, with the same content hash. resolve_script_level() checks.
void check_script_mods(const replay::Script& script);

// The settings a script runs under: `base` (the command line's), then the script's `quality`
// preset (from root_dir/assets/settings/quality.json), then its `set` lines.
Settings script_settings(const replay::Script& script, Settings base, const std::string& root_dir);

// The options a script's game is loaded with: `base`, the simulation keys of `settings` when
// the script sets any settings, then the header's seed, difficulty and simulation keys.
GameOptions script_game_options(const replay::Script& script, const Settings& settings, GameOptions base);

// Feeds a script's held input and commands to a Game, one step at a time.
class ScriptFeeder {
 public:
  explicit ScriptFeeder(const replay::Script& script) : script_(&script) {}
  // Applies the lines stamped `tick`, then steps the game once (a match: every slot's input).
  void step(Game& game, uint64_t tick);

 private:
  void step_match(Game& game, uint64_t tick);
  const replay::Script* script_;
  size_t next_input_ = 0, next_command_ = 0;
  replay::InputState held_;
  std::vector<replay::InputState> held_slots_;  // a match's, by slot
  std::vector<bool> flying_;                    // the slots pilots fly at the last step

};

}  // namespace arc
