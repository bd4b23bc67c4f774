// Replay script ↔ Game: input conversion, level and settings of a script, and its feeder.
#include "game/app/script_feeder.h"

#include <algorithm>
#include <filesystem>
#include <vector>

#include "core/data_layers.h"
#include "core/data_root.h"
#include "core/error.h"
#include "core/input_file.h"
#include "core/json.h"
#include "game/app/app_options.h"

namespace arc {

// The script's names for inputs and commands are the game's, value for value.
static_assert(uint16_t(replay::kFirePrimary) == kFirePrimary && uint16_t(replay::kFireSecondary) == kFireSecondary &&
              uint16_t(replay::kAfterburner) == kAfterburner && uint16_t(replay::kFlightAssist) == kFlightAssist);
static_assert(uint8_t(replay::ScriptCommand::TargetNext) == uint8_t(Command::TargetNext) &&
              uint8_t(replay::ScriptCommand::TargetNearest) == uint8_t(Command::TargetNearest) &&
              uint8_t(replay::ScriptCommand::TargetNextHostile) == uint8_t(Command::TargetNextHostile) &&
              uint8_t(replay::ScriptCommand::SwitchWeapon) == uint8_t(Command::SwitchWeapon) &&
              uint8_t(replay::ScriptCommand::CameraToggle) == uint8_t(Command::CameraToggle) &&
              uint8_t(replay::ScriptCommand::Pause) == uint8_t(Command::Pause) &&
              uint8_t(replay::ScriptCommand::Resume) == uint8_t(Command::Resume) &&
              uint8_t(replay::ScriptCommand::CameraPadlock) == uint8_t(Command::CameraPadlock) &&
              uint8_t(replay::ScriptCommand::Countermeasure) == uint8_t(Command::Countermeasure) &&
              uint8_t(replay::ScriptCommand::OrderAttack) == uint8_t(Command::OrderAttack) &&
              uint8_t(replay::ScriptCommand::OrderCover) == uint8_t(Command::OrderCover) &&
              uint8_t(replay::ScriptCommand::OrderFormUp) == uint8_t(Command::OrderFormUp) &&
              uint8_t(replay::ScriptCommand::OrderEngage) == uint8_t(Command::OrderEngage) &&
              uint8_t(replay::ScriptCommand::TargetSubsystem) == uint8_t(Command::TargetSubsystem));

InputFrame to_input_frame(const replay::InputState& s) {
  InputFrame f;
  f.pitch = s.axes[0];
  f.yaw = s.axes[1];
  f.roll = s.axes[2];
  f.throttle = s.axes[3];
  f.strafe_x = s.axes[4];
  f.strafe_y = s.axes[5];
  f.buttons = s.buttons;
  return f;
}

replay::InputState to_input_state(const InputFrame& f) {
  replay::InputState s;
  s.axes = {f.pitch, f.yaw, f.roll, f.throttle, f.strafe_x, f.strafe_y};
  s.buttons = f.buttons;
  return s;
}

std::string data_root_of(const GameOptions& options) { return options.root_dir == "." ? data_root() : options.root_dir; }

void check_script_mods(const replay::Script& s) {
  const std::vector<ModLayer>& laid = data_layers().mods();
  for (size_t i = 0; i < s.header.mods.size(); ++i) {
    const replay::ModLine& m = s.header.mods[i];
    const std::string at = s.path + ":" + std::to_string(m.line) + ":" + std::to_string(m.col) + ": ";
    if (i >= laid.size() || laid[i].name != m.name)
      throw InputError(at + "recorded with mod '" + m.name + "' (mod " + std::to_string(i + 1) + " of " +
                       std::to_string(s.header.mods.size()) + "); this run lays " +
                       (i < laid.size() ? "'" + laid[i].name + "' there" : "no such mod") +
                       ": replay it with the script's --mod folders, in the script's order");
    if (laid[i].hash != m.hash)
      throw InputError(at + "mod '" + m.name + "' (" + laid[i].dir + ") holds other data than when recorded (content hash " +
                       replay::hex64(laid[i].hash) + ", recorded " + replay::hex64(m.hash) + ")");
  }
  if (laid.size() > s.header.mods.size())
    throw InputError(s.path + ": recorded without mod '" + laid[s.header.mods.size()].name +
                     "', which this run lays over the data: replay it without that --mod (or settings.json's mods)");
}

std::string resolve_script_level(const replay::Script& s, const std::string& root) {
  namespace fs = std::filesystem;
  check_script_mods(s);
  const std::string& level = s.header.level;
  // A name that finds something is used; its reader says what is wrong with it, if anything.
  if (input_path_exists(level)) return level;
  const fs::path under_root = data_file(root, level);  // a mod's level first
  if (!fs::path(level).is_absolute() && input_path_exists(under_root.string())) return under_root.string();
  throw InputError(s.path + ":" + std::to_string(s.header.level_line) + ":1: level file '" + level +
                   "' not found (looked in the working folder and in " + root + ")");
}

Settings script_settings(const replay::Script& s, Settings settings, const std::string& root) {
  if (s.header.quality) {
    const replay::QualityLine& q = *s.header.quality;
    const std::string file = data_file(root, "assets/settings/quality.json");
    const std::vector<std::string> names = Settings::preset_names(file);
    if (std::find(names.begin(), names.end(), q.preset) == names.end())
      throw InputError(s.path + ":" + std::to_string(q.line) + ":" + std::to_string(q.col) + ": unknown quality preset '" +
                       q.preset + "' in " + file + "; allowed: " + join_allowed(names));
    settings.apply_preset_file(file, q.preset);
  }
  for (const replay::SettingLine& line : s.header.settings)
    settings.set(line.key, line.value, s.path + ":" + std::to_string(line.line) + ":" + std::to_string(line.col));
  return settings;
}

GameOptions script_game_options(const replay::Script& s, const Settings& settings, GameOptions o) {
  if (s.header.quality || !s.header.settings.empty()) apply_simulation_settings(settings, o);
  if (s.header.particle_budget) o.particle_budget = *s.header.particle_budget;
  if (s.header.lightning_interval) o.lightning_interval = *s.header.lightning_interval;
  if (s.header.substeps) o.substeps = *s.header.substeps;
  if (s.header.seed) {
    o.seed_override = true;
    o.seed = *s.header.seed;
  }
  o.ship = s.header.ship;
  o.loadout = s.header.loadout;
  if (s.header.difficulty) {
    o.difficulty_override = true;
    const std::string& d = *s.header.difficulty;
    o.difficulty = d == "easy" ? Difficulty::Easy : d == "hard" ? Difficulty::Hard : Difficulty::Normal;
  }
  return o;
}

// A network match's tick: each slot's held input and commands, the AI in the slots no pilot
// flies (or flies no longer).
void ScriptFeeder::step_match(Game& game, uint64_t t) {
  const replay::Script& s = *script_;
  const size_t slots = size_t(s.header.slots);
  if (held_slots_.empty()) {
    if (game.slot_count() != slots)
      throw InputError(s.path + ": the script is a match over " + std::to_string(slots) + " slots; its level has " +
                       std::to_string(game.slot_count()));
    held_slots_.resize(slots);
  }
  for (; next_input_ < s.inputs.size() && s.inputs[next_input_].tick == t; ++next_input_)
    replay::apply_input(held_slots_[s.inputs[next_input_].slot], s.inputs[next_input_]);
  std::vector<SlotInput> in(slots);
  for (size_t k = 0; k < slots; ++k) in[k].input = to_input_frame(held_slots_[k]);
  for (; next_command_ < s.commands.size() && s.commands[next_command_].tick == t; ++next_command_)
    in[s.commands[next_command_].slot].commands.push_back(static_cast<Command>(s.commands[next_command_].command));
  std::vector<bool> flying(slots, false);
  for (const replay::PilotLine& p : s.header.pilots) flying[size_t(p.slot)] = !p.drop || t < *p.drop;
  if (flying != flying_) game.set_pilots(flying_ = flying);
  game.step_slots(in);
}

void ScriptFeeder::step(Game& game, uint64_t t) {
  const replay::Script& s = *script_;
  if (s.header.slots > 0) return step_match(game, t);
  for (; next_input_ < s.inputs.size() && s.inputs[next_input_].tick == t; ++next_input_)
    replay::apply_input(held_, s.inputs[next_input_]);
  std::vector<Command> commands;
  for (; next_command_ < s.commands.size() && s.commands[next_command_].tick == t; ++next_command_)
    commands.push_back(static_cast<Command>(s.commands[next_command_].command));
  game.step(to_input_frame(held_), commands);
}

}  // namespace arc
