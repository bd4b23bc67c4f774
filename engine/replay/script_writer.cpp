// Writing replay scripts (whole files and the recorder's single lines), names of inputs and
// commands, and the axis quantisation shared with live input.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "replay/script.h"

namespace arc::replay {

const char* axis_name(Axis a) {
  switch (a) {
    case Axis::Pitch: return "pitch";
    case Axis::Yaw: return "yaw";
    case Axis::Roll: return "roll";
    case Axis::Throttle: return "throttle";
    case Axis::StrafeX: return "strafe_x";
    case Axis::StrafeY: return "strafe_y";
  }
  return "?";
}

const char* button_name(Button b) {
  switch (b) {
    case kFirePrimary: return "fire_primary";
    case kFireSecondary: return "fire_secondary";
    case kAfterburner: return "afterburner";
    case kFlightAssist: return "flight_assist_off";
  }
  return "?";
}

const char* command_name(ScriptCommand c) {
  switch (c) {
    case ScriptCommand::TargetNext: return "target_next";
    case ScriptCommand::TargetNearest: return "target_nearest";
    case ScriptCommand::TargetNextHostile: return "target_next_hostile";
    case ScriptCommand::SwitchWeapon: return "switch_weapon";
    case ScriptCommand::CameraToggle: return "camera";
    case ScriptCommand::Pause: return "pause";
    case ScriptCommand::Resume: return "resume";
    case ScriptCommand::CameraPadlock: return "camera_padlock";
    case ScriptCommand::Countermeasure: return "countermeasure";
    case ScriptCommand::OrderAttack: return "order_attack";
    case ScriptCommand::OrderCover: return "order_cover";
    case ScriptCommand::OrderFormUp: return "order_form_up";
    case ScriptCommand::OrderEngage: return "order_engage";
    case ScriptCommand::TargetSubsystem: return "target_subsystem";
  }
  return "?";
}

int8_t quantise_axis(double v) {
  if (!std::isfinite(v)) return 0;
  v = std::clamp(v, -1.0, 1.0);
  return static_cast<int8_t>(std::lround(v * 127.0));
}

std::string axis_text(int8_t q) {
  // Four decimals are always enough: the rounding error (5e-5 · 127) is far below half a step.
  for (int digits = 0; digits <= 4; ++digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, double(q) / 127.0);
    double back = std::strtod(buf, nullptr);
    if (quantise_axis(back) == q) {
      std::string s = buf;
      if (s == "-0") s = "0";
      return s;
    }
  }
  return std::to_string(double(q) / 127.0);
}

std::string hex64(uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

namespace {

std::string quoted(const std::string& name) {
  return name.find_first_of(" \t#") == std::string::npos ? name : "\"" + name + "\"";
}

std::string number_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// The shortest text that parses back to the same double (99.9 → "99.9").
std::string shortest_number_text(double v) {
  char buf[40];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : number_text(v);
}

std::string range_text(const Range& r) { return number_text(r.min) + ".." + number_text(r.max); }

std::string expectation_line(const Expectation& e) {
  std::string s = std::to_string(e.tick) + " expect ";
  switch (e.kind) {
    case Expectation::Kind::Alive: return s + "alive " + quoted(e.ship) + "\n";
    case Expectation::Kind::Destroyed: return s + "destroyed " + quoted(e.ship) + "\n";
    case Expectation::Kind::Hull: return s + "hull " + quoted(e.ship) + " " + range_text(e.range) + "\n";
    case Expectation::Kind::Shield: return s + "shield " + quoted(e.ship) + " " + range_text(e.range) + "\n";
    case Expectation::Kind::Position:
      return s + "position " + quoted(e.ship) + " " + range_text(e.box[0]) + " " + range_text(e.box[1]) + " " +
             range_text(e.box[2]) + "\n";
    case Expectation::Kind::Distance:
      return s + "distance " + quoted(e.ship) + " " + quoted(e.other) + " " + range_text(e.range) + "\n";
    case Expectation::Kind::Particles: return s + "particles " + range_text(e.range) + "\n";
    case Expectation::Kind::Winner: return s + "winner " + quoted(e.team) + "\n";
    case Expectation::Kind::Kills: return s + "kills " + quoted(e.ship) + " " + range_text(e.range) + "\n";
    case Expectation::Kind::DamageDealt:
      return s + "damage_dealt " + quoted(e.ship) + " " + range_text(e.range) + "\n";
    case Expectation::Kind::DamageTaken:
      return s + "damage_taken " + quoted(e.ship) + " " + range_text(e.range) + "\n";
    case Expectation::Kind::Accuracy:
      return s + "accuracy " + quoted(e.ship) + " " + e.weapon + " " + range_text(e.range) + "\n";
    case Expectation::Kind::Sound: return s + "sound " + e.sound + "\n";
  }
  return s + "\n";
}

}  // namespace

uint64_t Script::last_tick() const {
  if (end_tick) return *end_tick;
  uint64_t t = 0;
  for (const auto& e : inputs) t = std::max(t, e.tick);
  for (const auto& e : commands) t = std::max(t, e.tick);
  for (const auto& e : expectations) t = std::max(t, e.tick);
  for (const auto& e : hashes) t = std::max(t, e.tick);
  for (const auto& e : snapshots) t = std::max(t, e.tick);
  return t;
}

bool Header::same_content(const Header& o) const {
  auto same_settings = [](const std::vector<SettingLine>& a, const std::vector<SettingLine>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const SettingLine& x, const SettingLine& y) {
      return x.key == y.key && x.value == y.value;
    });
  };
  const std::optional<std::string> preset = quality ? std::optional(quality->preset) : std::nullopt;
  const std::optional<std::string> other_preset = o.quality ? std::optional(o.quality->preset) : std::nullopt;
  return version == o.version && level == o.level && seed == o.seed && tick_rate == o.tick_rate &&
         difficulty == o.difficulty && ship == o.ship && loadout == o.loadout && build == o.build && snapshot_width == o.snapshot_width &&
         snapshot_height == o.snapshot_height && particle_budget == o.particle_budget &&
         lightning_interval == o.lightning_interval && substeps == o.substeps && preset == other_preset &&
         same_settings(settings, o.settings) && mods == o.mods && tolerance == o.tolerance &&
         snapshots_like == o.snapshots_like && slots == o.slots && pilots == o.pilots;
}

bool Script::same_content(const Script& o) const {
  auto strip = [](Script s) {
    s.path.clear();
    s.end_src = {};
    for (auto& e : s.inputs) e.src = {};
    for (auto& e : s.commands) e.src = {};
    for (auto& e : s.expectations) {
      e.src = {};
      e.ship_col = e.other_col = e.sound_col = 0;
    }
    for (auto& e : s.hashes) e.src = {};
    for (auto& e : s.snapshots) e.src = {};
    return s;
  };
  Script a = strip(*this), b = strip(o);
  return a.header.same_content(b.header) && a.inputs == b.inputs && a.commands == b.commands &&
         a.expectations == b.expectations && a.hashes == b.hashes && a.snapshots == b.snapshots &&
         a.end_tick == b.end_tick;
}

std::string header_text(const Header& h) {
  std::string s = "arcfire-replay " + std::to_string(h.version) + "\n";
  s += "level " + quoted(h.level) + "\n";
  if (h.seed) s += "seed " + std::to_string(*h.seed) + "\n";
  if (h.tick_rate) s += "tick_rate " + std::to_string(*h.tick_rate) + "\n";
  if (h.difficulty) s += "difficulty " + *h.difficulty + "\n";
  if (!h.ship.empty()) s += "ship " + h.ship + "\n";
  if (!h.loadout.empty()) s += "loadout " + h.loadout + "\n";
  if (!h.build.empty()) s += "build " + quoted(h.build) + "\n";
  if (h.snapshot_width != Header{}.snapshot_width || h.snapshot_height != Header{}.snapshot_height)
    s += "snapshot_size " + std::to_string(h.snapshot_width) + " " + std::to_string(h.snapshot_height) + "\n";
  if (h.particle_budget) s += "particle_budget " + std::to_string(*h.particle_budget) + "\n";
  if (h.lightning_interval) s += "lightning_interval " + std::to_string(*h.lightning_interval) + "\n";
  if (h.substeps) s += "substeps " + std::to_string(*h.substeps) + "\n";
  if (h.quality) s += "quality " + h.quality->preset + "\n";
  for (const SettingLine& line : h.settings) s += "set " + line.key + "=" + line.value + "\n";
  for (const ModLine& m : h.mods) s += "mod " + m.name + " " + hex64(m.hash) + "\n";
  if (h.tolerance)
    s += "tolerance " + std::to_string(h.tolerance->max_channel_diff) + "/255 " +
         shortest_number_text(h.tolerance->min_percent) + "%\n";
  if (!h.snapshots_like.empty()) s += "snapshots_like " + h.snapshots_like + "\n";
  if (h.slots > 0) s += "slots " + std::to_string(h.slots) + "\n";
  for (const PilotLine& p : h.pilots) {
    s += "pilot " + std::to_string(p.slot) + " " + quoted(p.name) + "\n";
    if (p.drop) s += "drop " + std::to_string(p.slot) + " " + std::to_string(*p.drop) + "\n";
  }
  return s;
}

// "T" or, for another slot than the player's, "T slot K".
static std::string stamp(uint64_t tick, uint8_t slot) {
  return std::to_string(tick) + (slot ? " slot " + std::to_string(slot) : "");
}

std::string input_event_line(const InputEvent& e) {
  std::string s = stamp(e.tick, e.slot);
  switch (e.kind) {
    case InputEvent::Kind::Press: return s + " press " + button_name(e.button) + "\n";
    case InputEvent::Kind::Release: return s + " release " + button_name(e.button) + "\n";
    case InputEvent::Kind::Axis: return s + " axis " + axis_name(e.axis) + " " + axis_text(e.value) + "\n";
  }
  return s + "\n";
}

std::string command_line(const CommandEvent& c) {
  return stamp(c.tick, c.slot) + " command " + command_name(c.command) + "\n";
}

std::string hash_line(const HashCheck& h) {
  return std::to_string(h.tick) + (h.full ? " full_hash " : " hash ") + (h.value ? hex64(*h.value) : "?") + "\n";
}

std::string end_line(uint64_t tick) { return std::to_string(tick) + " end\n"; }

void apply_input(InputState& state, const InputEvent& e) {
  switch (e.kind) {
    case InputEvent::Kind::Press: state.buttons |= e.button; break;
    case InputEvent::Kind::Release: state.buttons &= static_cast<uint16_t>(~e.button); break;
    case InputEvent::Kind::Axis: state.axes[static_cast<size_t>(e.axis)] = e.value; break;
  }
}

std::string input_diff_lines(uint64_t tick, const InputState& before, const InputState& after, uint8_t slot) {
  std::string s;
  for (Button b : {kFirePrimary, kFireSecondary, kAfterburner, kFlightAssist}) {
    bool was = before.buttons & b, is = after.buttons & b;
    if (was == is) continue;
    InputEvent e;
    e.tick = tick;
    e.kind = is ? InputEvent::Kind::Press : InputEvent::Kind::Release;
    e.button = b;
    e.slot = slot;
    s += input_event_line(e);
  }
  for (int a = 0; a < kAxisCount; ++a)
    if (before.axes[a] != after.axes[a]) {
      InputEvent e;
      e.tick = tick;
      e.kind = InputEvent::Kind::Axis;
      e.axis = static_cast<Axis>(a);
      e.value = after.axes[a];
      e.slot = slot;
      s += input_event_line(e);
    }
  return s;
}

std::string write_script(const Script& script) {
  // Lines of one tick in a fixed order: inputs, commands, then checks, which see the state
  // before that tick's inputs apply (the order in the file does not change meaning).
  struct Timed {
    uint64_t tick;
    int group;
    size_t index;
    std::string text;
  };
  std::vector<Timed> lines;
  for (size_t i = 0; i < script.inputs.size(); ++i) lines.push_back({script.inputs[i].tick, 0, i, input_event_line(script.inputs[i])});
  for (size_t i = 0; i < script.commands.size(); ++i) lines.push_back({script.commands[i].tick, 1, i, command_line(script.commands[i])});
  for (size_t i = 0; i < script.expectations.size(); ++i)
    lines.push_back({script.expectations[i].tick, 2, i, expectation_line(script.expectations[i])});
  for (size_t i = 0; i < script.hashes.size(); ++i) lines.push_back({script.hashes[i].tick, 3, i, hash_line(script.hashes[i])});
  for (size_t i = 0; i < script.snapshots.size(); ++i)
    lines.push_back({script.snapshots[i].tick, 4, i,
                     std::to_string(script.snapshots[i].tick) + " snapshot " + script.snapshots[i].name + "\n"});
  std::stable_sort(lines.begin(), lines.end(), [](const Timed& a, const Timed& b) {
    if (a.tick != b.tick) return a.tick < b.tick;
    if (a.group != b.group) return a.group < b.group;
    return a.index < b.index;
  });
  std::string out = header_text(script.header);
  for (const Timed& t : lines) out += t.text;
  if (script.end_tick) out += end_line(*script.end_tick);
  return out;
}

std::string fill_hash_values(const std::string& original_text, const Script& script,
                             const std::vector<uint64_t>& values) {
  // Each value is spliced into its line; every other byte (line ends, a missing final newline,
  // comments) stays as it was.
  std::vector<size_t> line_starts{0};
  for (size_t i = 0; i < original_text.size(); ++i)
    if (original_text[i] == '\n') line_starts.push_back(i + 1);
  std::vector<std::pair<size_t, size_t>> spans;  // [begin, end) of each value in the text
  std::vector<std::string> texts;
  for (size_t i = 0; i < script.hashes.size() && i < values.size(); ++i) {
    const HashCheck& h = script.hashes[i];
    const size_t begin = line_starts.at(static_cast<size_t>(h.src.line - 1));
    const size_t end = std::min(original_text.find('\n', begin), original_text.size());
    const std::string l = original_text.substr(begin, end - begin);
    // The value is the third word: keep the tick as written (+N or absolute) and any comment.
    const size_t verb = l.find(h.full ? "full_hash" : "hash");
    size_t start = l.find_first_not_of(" \t", verb + (h.full ? 9 : 4));
    if (start == std::string::npos) start = l.size();
    size_t stop = l.find_first_of(" \t#\r", start);
    if (stop == std::string::npos) stop = l.size();
    spans.emplace_back(begin + start, begin + stop);
    texts.push_back(hex64(values[i]));
  }
  std::vector<size_t> order(spans.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return spans[a].first < spans[b].first; });
  std::string out;
  size_t at = 0;
  for (size_t i : order) {
    out.append(original_text, at, spans[i].first - at);
    out += texts[i];
    at = spans[i].second;
  }
  out.append(original_text, at, std::string::npos);
  return out;
}

}  // namespace arc::replay
