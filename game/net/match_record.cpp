// game/net/match_record.cpp — a match's record as a replay script (match_record.h).
#include "game/net/match_record.h"

#include <charconv>
#include <cmath>

#include "core/data_layers.h"
#include "game/sim/world.h"
#include "replay/script.h"

namespace arc {
namespace {

replay::InputState state_of(const InputFrame& f) {
  replay::InputState s;
  s.axes = {f.pitch, f.yaw, f.roll, f.throttle, f.strafe_x, f.strafe_y};
  s.buttons = f.buttons;
  return s;
}

// A pilot's name as one word of a script: printable, no quotes, within 64 characters.
std::string script_name(std::string n) {
  for (char& c : n)
    if (c < 0x20 || c > 0x7e || c == '"') c = '_';
  if (n.size() > 64) n.resize(64);
  return n.empty() ? "Pilot" : n;
}

replay::Header match_header(const RollbackSession& s, const std::string& level, const std::vector<std::string>& names) {
  const World& w = s.game().world();
  replay::Header h;
  h.version = replay::kFormatVersion;
  h.level = level;
  h.seed = w.seed;
  h.tick_rate = static_cast<int>(std::lround(1.0 / w.dt));
  h.difficulty = difficulty_name(static_cast<Difficulty>(w.difficulty));
  h.ship = w.options.ship;
  h.loadout = w.options.loadout;
  for (const ModLayer& m : data_layers().mods()) h.mods.push_back({m.name, m.hash});
  // What the simulation ran under, so the record replays under any --quality.
  h.particle_budget = w.options.particle_budget;
  h.lightning_interval = w.options.lightning_interval;
  h.substeps = w.options.substeps;
  if (w.options.cull_distance != GameOptions{}.cull_distance) {
    char text[32];
    char* end = std::to_chars(text, text + sizeof text, w.options.cull_distance).ptr;
    h.settings.push_back({"particles.cull_distance", std::string(text, size_t(end - text))});
  }
  h.slots = s.config().slots;
  for (int k = 0; k < h.slots; ++k) {
    if (!s.config().piloted[size_t(k)]) continue;
    replay::PilotLine p{k, script_name(size_t(k) < names.size() ? names[size_t(k)] : ""), std::nullopt};
    // The first step the AI flies is drop + 1 in the script's ticks.
    if (s.drop_tick(k) != RollbackSession::kNever) p.drop = uint64_t(std::max<int64_t>(s.drop_tick(k) - 1, 0));
    h.pilots.push_back(p);
  }
  return h;
}

}  // namespace

std::string match_record_text(const RollbackSession& s, const std::string& level, const std::vector<std::string>& names,
                              int64_t last_tick, int hash_every) {
  const replay::Header h = match_header(s, level, names);
  std::string out = replay::header_text(h) + "# network match\n";
  const int64_t end = std::max<int64_t>(std::min(s.final_tick(), last_tick), 0);
  std::vector<replay::InputState> held(size_t(h.slots));
  // Lines stamped T: the inputs and commands of step T + 1, then the hash of the state after T steps.
  for (int64_t t = 0; t <= end; ++t) {
    const int64_t step = t + 1;
    for (const replay::PilotLine& p : h.pilots) {
      const auto& known = s.inputs(p.slot);
      if (step > end || step >= s.drop_tick(p.slot) || step > int64_t(known.size())) continue;
      const SlotInput& in = known[size_t(step - 1)];
      const replay::InputState now = state_of(in.input);
      out += replay::input_diff_lines(uint64_t(t), held[size_t(p.slot)], now, uint8_t(p.slot));
      held[size_t(p.slot)] = now;
    }
    for (const replay::PilotLine& p : h.pilots) {
      const auto& known = s.inputs(p.slot);
      if (step > end || step >= s.drop_tick(p.slot) || step > int64_t(known.size())) continue;
      for (Command c : known[size_t(step - 1)].commands)
        if (c != Command::None) out += replay::command_line({uint64_t(t), replay::ScriptCommand(c), uint8_t(p.slot), {}});
    }
    if (t > 0 && (t % hash_every == 0 || t == end)) out += replay::hash_line({uint64_t(t), false, s.hash_at(t), {}});
  }
  out += replay::end_line(uint64_t(end));
  return out;
}

}  // namespace arc
