// Parsing of replay scripts: one pass over lines, each split into positioned tokens, so every
// error names the exact line and column of the word that is wrong.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <utility>

#include "core/error.h"
#include "core/input_limits.h"
#include "core/json.h"
#include "core/settings.h"
#include "replay/script.h"

namespace arc::replay {
namespace {

struct Token {
  std::string text;
  int col = 1;
};

struct LineParser {
  const std::string& path;
  int line;
  std::vector<Token> tokens;
  size_t next = 0;
  int end_col = 1;  // column just past the last character, for "missing ..." errors

  [[noreturn]] void fail_at(int col, const std::string& message) const {
    throw InputError(path + ":" + std::to_string(line) + ":" + std::to_string(col) + ": " + message);
  }
  [[noreturn]] void fail(const Token& t, const std::string& message) const { fail_at(t.col, message); }

  const Token& take(const std::string& what) {
    if (next >= tokens.size()) fail_at(end_col, "missing " + what);
    return tokens[next++];
  }
  void done(const std::string& after) {
    if (next < tokens.size())
      fail(tokens[next], "unexpected '" + tokens[next].text + "' after " + after);
  }
};

std::vector<Token> tokenize(const std::string& text, const std::string& path, int line, int& end_col) {
  std::vector<Token> out;
  size_t i = 0;
  end_col = 1;
  while (i < text.size()) {
    char c = text[i];
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
      continue;
    }
    if (c == '#') break;
    Token t;
    t.col = static_cast<int>(i) + 1;
    if (c == '"') {
      size_t close = text.find('"', i + 1);
      if (close == std::string::npos)
        throw InputError(path + ":" + std::to_string(line) + ":" + std::to_string(t.col) +
                         ": unterminated quoted name (missing closing \")");
      t.text = text.substr(i + 1, close - i - 1);
      if (t.text.empty())
        throw InputError(path + ":" + std::to_string(line) + ":" + std::to_string(t.col) + ": empty quoted name");
      i = close + 1;
    } else {
      size_t j = i;
      while (j < text.size() && text[j] != ' ' && text[j] != '\t' && text[j] != '\r' && text[j] != '#') ++j;
      t.text = text.substr(i, j - i);
      i = j;
    }
    end_col = static_cast<int>(i) + 1;
    out.push_back(std::move(t));
  }
  return out;
}

bool parse_u64(const std::string& s, uint64_t& v) {
  if (s.empty() || s[0] == '+' || s[0] == '-') return false;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && p == s.data() + s.size();
}

bool parse_double(const std::string& s, double& v) {
  const char* b = s.data();
  if (!s.empty() && s[0] == '+') ++b;
  auto [p, ec] = std::from_chars(b, s.data() + s.size(), v, std::chars_format::fixed);
  if (ec != std::errc() || p != s.data() + s.size()) {
    auto [p2, ec2] = std::from_chars(b, s.data() + s.size(), v, std::chars_format::general);
    if (ec2 != std::errc() || p2 != s.data() + s.size()) return false;
  }
  return std::isfinite(v);
}

uint64_t integer_in(LineParser& lp, const Token& t, const std::string& what, uint64_t lo, uint64_t hi) {
  uint64_t v = 0;
  if (!parse_u64(t.text, v) || v < lo || v > hi)
    lp.fail(t, what + " must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got '" +
                   t.text + "'");
  return v;
}

double number(LineParser& lp, const Token& t, const std::string& what) {
  double v = 0;
  if (!parse_double(t.text, v)) lp.fail(t, what + " must be a finite number, got '" + t.text + "'");
  return v;
}

Range range(LineParser& lp, const std::string& what) {
  const Token& t = lp.take(what + " range MIN..MAX");
  size_t dots = t.text.find("..");
  if (dots == std::string::npos || dots == 0 || dots + 2 >= t.text.size())
    lp.fail(t, what + " must be a range MIN..MAX (e.g. 0..50), got '" + t.text + "'");
  Range r;
  if (!parse_double(t.text.substr(0, dots), r.min) || !parse_double(t.text.substr(dots + 2), r.max))
    lp.fail(t, what + " range bounds must be finite numbers, got '" + t.text + "'");
  if (r.min > r.max) lp.fail(t, what + " range is empty: " + t.text + " (MIN must be <= MAX)");
  return r;
}

template <typename E, size_t N>
E choose(LineParser& lp, const Token& t, const std::string& what, const std::array<E, N>& values,
         const char* (*name)(E)) {
  std::vector<std::string> names;
  for (E v : values) {
    if (t.text == name(v)) return v;
    names.push_back(name(v));
  }
  lp.fail(t, "unknown " + what + " '" + t.text + "'; allowed: " + join_allowed(names));
}

constexpr std::array<Button, 4> kButtons{kFirePrimary, kFireSecondary, kAfterburner, kFlightAssist};
constexpr std::array<Axis, kAxisCount> kAxes{Axis::Pitch, Axis::Yaw, Axis::Roll, Axis::Throttle, Axis::StrafeX, Axis::StrafeY};
constexpr std::array<ScriptCommand, 14> kCommands{
    ScriptCommand::TargetNext,     ScriptCommand::TargetNearest, ScriptCommand::TargetNextHostile,
    ScriptCommand::SwitchWeapon,   ScriptCommand::CameraToggle,  ScriptCommand::Pause,
    ScriptCommand::Resume,         ScriptCommand::CameraPadlock, ScriptCommand::Countermeasure,
    ScriptCommand::OrderAttack,    ScriptCommand::OrderCover,    ScriptCommand::OrderFormUp,
    ScriptCommand::OrderEngage,    ScriptCommand::TargetSubsystem};

bool valid_name(const std::string& s) {
  return !s.empty() && s.size() <= 64 && std::all_of(s.begin(), s.end(), [](char c) {
           return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
         });
}

// The header keys that pin a simulation setting, and the setting each pins.
constexpr std::array<std::pair<const char*, const char*>, 3> kPinnedSettings{
    {{"particle_budget", "particles.budget"}, {"lightning_interval", "particles.lightning_interval"}, {"substeps", "sim.substeps"}}};

// The other spelling of the same setting ("particle_budget" <-> "particles.budget"), or "".
std::string pinned_twin(const std::string& name) {
  for (const auto& [header_key, setting] : kPinnedSettings) {
    if (name == header_key) return setting;
    if (name == setting) return header_key;
  }
  return "";
}

bool seen_before(const std::vector<std::string>& seen, const std::string& name) {
  return std::find(seen.begin(), seen.end(), name) != seen.end();
}

// `set key=value`: the key must be one of `known` and the value one it allows.
void parse_setting(LineParser& lp, Header& h, std::vector<std::string>& seen, const Settings& known) {
  const Token& t = lp.take("setting key=value (e.g. render.soft_edges=linear)");
  const size_t eq = t.text.find('=');
  if (eq == std::string::npos || eq == 0)
    lp.fail(t, "expected key=value as with --set (e.g. set render.soft_edges=linear), got '" + t.text + "'");
  SettingLine s{t.text.substr(0, eq), t.text.substr(eq + 1), lp.line, t.col};
  Settings settings = known;
  const std::vector<SettingDef>& defs = settings.all();
  const bool is_known = std::any_of(defs.begin(), defs.end(), [&](const SettingDef& d) { return d.key == s.key; });
  if (is_known) s.col = t.col + static_cast<int>(eq) + 1;  // a bad value is reported where it is written
  settings.set(s.key, s.value, lp.path + ":" + std::to_string(lp.line) + ":" + std::to_string(s.col));
  if (seen_before(seen, s.key)) lp.fail(t, "setting '" + s.key + "' is set twice");
  const std::string twin = pinned_twin(s.key);
  if (seen_before(seen, twin)) lp.fail(t, "setting '" + s.key + "' is already given by the header's '" + twin + "' line");
  seen.push_back(s.key);
  h.settings.push_back(s);
}

// `tolerance N/255 P%`: the largest channel difference and the share of pixels within it.
SnapshotTolerance parse_tolerance(LineParser& lp) {
  SnapshotTolerance tol;
  const Token& diff = lp.take("largest channel difference N/255 (e.g. 5/255)");
  const size_t slash = diff.text.find('/');
  if (slash == std::string::npos || diff.text.substr(slash) != "/255")
    lp.fail(diff, "tolerance must be written N/255 with N in [0, 255] (e.g. 5/255), got '" + diff.text + "'");
  tol.max_channel_diff = static_cast<int>(integer_in(lp, Token{diff.text.substr(0, slash), diff.col}, "tolerance", 0, 255));
  const Token& share = lp.take("share of pixels within the tolerance, P% (e.g. 99.9%)");
  double percent = 0;
  if (share.text.size() < 2 || share.text.back() != '%' ||
      !parse_double(share.text.substr(0, share.text.size() - 1), percent) || percent <= 0 || percent > 100)
    lp.fail(share, "share of pixels must be a percentage in (0, 100] written P% (e.g. 99.9%), got '" + share.text + "'");
  tol.min_percent = percent;
  return tol;
}

// `mod NAME HASH`: the mod's folder name and its 16-digit hexadecimal content hash.
void parse_mod(LineParser& lp, Header& h) {
  const Token& name = lp.take("mod name (its folder's name)");
  if (!valid_name(name.text)) lp.fail(name, "mod name must be 1 to 64 of A-Z a-z 0-9 _ -, got '" + name.text + "'");
  for (const ModLine& m : h.mods)
    if (m.name == name.text) lp.fail(name, "mod '" + name.text + "' is named twice");
  const Token& hash = lp.take("the mod's content hash (16 hexadecimal digits)");
  if (hash.text.size() != 16 || hash.text.find_first_not_of("0123456789abcdef") != std::string::npos)
    lp.fail(hash, "mod hash must be 16 lowercase hexadecimal digits, got '" + hash.text + "'");
  h.mods.push_back({name.text, std::stoull(hash.text, nullptr, 16), lp.line, name.col});
}

// `pilot SLOT NAME` and `drop SLOT TICK`, after `slots`: a slot named once by each.
void parse_pilot(LineParser& lp, Header& h, const Token& key) {
  if (h.slots == 0) lp.fail(key, "'" + key.text + "' lines come after a 'slots N' line");
  const int slot = static_cast<int>(integer_in(lp, lp.take("slot number"), "slot", 0, uint64_t(h.slots - 1)));
  auto it = std::find_if(h.pilots.begin(), h.pilots.end(), [&](const PilotLine& p) { return p.slot == slot; });
  if (key.text == "pilot") {
    if (it != h.pilots.end()) lp.fail(key, "slot " + std::to_string(slot) + " has two 'pilot' lines");
    const Token& name = lp.take("the pilot's name");
    if (name.text.empty() || name.text.size() > 64) lp.fail(name, "a pilot's name is 1 to 64 characters");
    h.pilots.push_back(PilotLine{slot, name.text, std::nullopt});
    std::sort(h.pilots.begin(), h.pilots.end(), [](const PilotLine& a, const PilotLine& b) { return a.slot < b.slot; });
    lp.done("the pilot's name");
    return;
  }
  if (it == h.pilots.end()) lp.fail(key, "slot " + std::to_string(slot) + " has no 'pilot' line before its 'drop'");
  if (it->drop) lp.fail(key, "slot " + std::to_string(slot) + " is dropped twice");
  it->drop = integer_in(lp, lp.take("the tick its pilot left"), "drop tick", 0, kMaxScriptTick);
  lp.done("the drop tick");
}

void parse_header_line(LineParser& lp, Header& h, std::vector<std::string>& seen, const Settings& known) {
  const Token& key = lp.tokens[lp.next++];
  if (key.text == "set") {
    parse_setting(lp, h, seen, known);
    lp.done("the setting");
    return;
  }
  if (key.text == "mod") {
    parse_mod(lp, h);
    lp.done("the mod");
    return;
  }
  if (key.text == "pilot" || key.text == "drop") {
    parse_pilot(lp, h, key);
    return;
  }
  if (seen_before(seen, key.text)) lp.fail(key, "header key '" + key.text + "' appears twice");
  if (seen_before(seen, pinned_twin(key.text)))
    lp.fail(key, "header key '" + key.text + "' repeats the setting of an earlier 'set " + pinned_twin(key.text) + "' line");
  seen.push_back(key.text);
  if (key.text == "level") {
    h.level = lp.take("level path").text;
    h.level_line = lp.line;
  } else if (key.text == "seed") {
    h.seed = integer_in(lp, lp.take("seed value"), "seed", 0, 4294967295ull);
  } else if (key.text == "tick_rate") {
    h.tick_rate = static_cast<int>(integer_in(lp, lp.take("tick rate"), "tick_rate", 10, 480));
  } else if (key.text == "difficulty") {
    const Token& t = lp.take("difficulty (easy, normal or hard)");
    if (t.text != "easy" && t.text != "normal" && t.text != "hard")
      lp.fail(t, "difficulty must be easy, normal or hard, got '" + t.text + "'");
    h.difficulty = t.text;
  } else if (key.text == "ship") {
    const Token& t = lp.take("ship class name");
    if (!valid_name(t.text)) lp.fail(t, "ship class must be 1 to 64 of A-Z a-z 0-9 _ -, got '" + t.text + "'");
    h.ship = t.text;
  } else if (key.text == "loadout") {
    const Token& t = lp.take("loadout (PRIMARY+SECONDARY, e.g. beam+torpedo)");
    const size_t plus = t.text.find('+');
    if (plus == std::string::npos || !valid_name(t.text.substr(0, plus)) || !valid_name(t.text.substr(plus + 1)))
      lp.fail(t, "loadout must be PRIMARY+SECONDARY (e.g. beam+torpedo), got '" + t.text + "'");
    h.loadout = t.text;
  } else if (key.text == "build") {
    h.build = lp.take("build id").text;
  } else if (key.text == "snapshot_size") {
    h.snapshot_width = static_cast<int>(integer_in(lp, lp.take("snapshot width"), "snapshot width", 16, 4096));
    h.snapshot_height = static_cast<int>(integer_in(lp, lp.take("snapshot height"), "snapshot height", 16, 4096));
  } else if (key.text == "particle_budget") {
    h.particle_budget = static_cast<uint32_t>(integer_in(lp, lp.take("particle budget"), "particle_budget", 1000, 4000000));
  } else if (key.text == "lightning_interval") {
    h.lightning_interval = static_cast<int>(integer_in(lp, lp.take("lightning interval"), "lightning_interval", 0, 60));
  } else if (key.text == "substeps") {
    h.substeps = static_cast<int>(integer_in(lp, lp.take("sub-step count"), "substeps", 1, 16));
  } else if (key.text == "quality") {
    const Token& t = lp.take("quality preset name (e.g. low, medium, high or reference)");
    h.quality = QualityLine{t.text, lp.line, t.col};
  } else if (key.text == "tolerance") {
    h.tolerance = parse_tolerance(lp);
  } else if (key.text == "slots") {
    if (h.version < 2) lp.fail(key, "'slots' needs version 2 of the format: the first line 'arcfire-replay 2'");
    h.slots = static_cast<int>(integer_in(lp, lp.take("slot count"), "slots", 1, kMaxSlots));
  } else if (key.text == "snapshots_like") {
    const Token& t = lp.take("the name of the script whose golden images to compare with");
    if (!valid_name(t.text)) lp.fail(t, "script name must be 1 to 64 of A-Z a-z 0-9 _ -, got '" + t.text + "'");
    h.snapshots_like = t.text;
  } else {
    lp.fail(key, "unknown header key '" + key.text +
                     "'; allowed: level, seed, tick_rate, difficulty, ship, loadout, build, snapshot_size, particle_budget, "
                     "lightning_interval, substeps, quality, set, mod, tolerance, snapshots_like, slots, pilot, drop, or a tick-stamped "
                     "line");
  }
  lp.done(key.text);
}

void take_ship(LineParser& lp, std::string& name, int& col, const std::string& what) {
  const Token& t = lp.take(what);
  name = t.text;
  col = t.col;
}

// A range, or one number N meaning N..N (`expect kills Player 1`).
Range range_or_number(LineParser& lp, const std::string& what) {
  if (lp.next < lp.tokens.size() && lp.tokens[lp.next].text.find("..") != std::string::npos) return range(lp, what);
  const Token& t = lp.take(what + " (N or MIN..MAX)");
  double v = 0;
  if (!parse_double(t.text, v)) lp.fail(t, what + " must be a number N or a range MIN..MAX, got '" + t.text + "'");
  return Range{v, v};
}

// The combat counters: kills, damage_dealt, damage_taken, accuracy (of one weapon).
bool parse_counter_expect(LineParser& lp, const std::string& w, Expectation& e) {
  if (w == "kills") {
    e.kind = Expectation::Kind::Kills;
    take_ship(lp, e.ship, e.ship_col, "ship name");
    e.range = range_or_number(lp, "kill count");
  } else if (w == "damage_dealt" || w == "damage_taken") {
    e.kind = w == "damage_dealt" ? Expectation::Kind::DamageDealt : Expectation::Kind::DamageTaken;
    take_ship(lp, e.ship, e.ship_col, "ship name");
    e.range = range(lp, w);
  } else if (w == "accuracy") {
    e.kind = Expectation::Kind::Accuracy;
    take_ship(lp, e.ship, e.ship_col, "ship name");
    const Token& weapon = lp.take("weapon (beam or missile)");
    if (weapon.text != "beam" && weapon.text != "missile")
      lp.fail(weapon, "unknown weapon '" + weapon.text + "'; allowed: beam or missile");
    e.weapon = weapon.text;
    e.range = range(lp, "accuracy");
  } else {
    return false;
  }
  return true;
}

Expectation parse_expect(LineParser& lp, uint64_t tick) {
  Expectation e;
  e.tick = tick;
  const Token& what = lp.take(
      "what to expect (alive, destroyed, hull, shield, position, distance, particles, winner, kills, damage_dealt, "
      "damage_taken, accuracy, sound)");
  const std::string& w = what.text;
  if (w == "alive" || w == "destroyed") {
    e.kind = w == "alive" ? Expectation::Kind::Alive : Expectation::Kind::Destroyed;
    take_ship(lp, e.ship, e.ship_col, "ship name");
  } else if (w == "hull" || w == "shield") {
    e.kind = w == "hull" ? Expectation::Kind::Hull : Expectation::Kind::Shield;
    take_ship(lp, e.ship, e.ship_col, "ship name");
    e.range = range(lp, w);
  } else if (w == "position") {
    e.kind = Expectation::Kind::Position;
    take_ship(lp, e.ship, e.ship_col, "ship name");
    e.box[0] = range(lp, "x");
    e.box[1] = range(lp, "y");
    e.box[2] = range(lp, "z");
  } else if (w == "distance") {
    e.kind = Expectation::Kind::Distance;
    take_ship(lp, e.ship, e.ship_col, "first ship name");
    take_ship(lp, e.other, e.other_col, "second ship name");
    e.range = range(lp, "distance");
  } else if (w == "particles") {
    e.kind = Expectation::Kind::Particles;
    e.range = range(lp, "particle count");
  } else if (w == "winner") {
    e.kind = Expectation::Kind::Winner;
    e.team = lp.take("team name (or none)").text;
  } else if (w == "sound") {
    e.kind = Expectation::Kind::Sound;
    const Token& t = lp.take("sound event name (explosion, beam, missile_launch, ...)");
    e.sound = t.text;
    e.sound_col = t.col;
  } else if (!parse_counter_expect(lp, w, e)) {
    lp.fail(what, "unknown expectation '" + w +
                      "'; allowed: alive, destroyed, hull, shield, position, distance, particles, winner, kills, "
                      "damage_dealt, damage_taken, accuracy or sound");
  }
  lp.done("expect " + w);
  return e;
}

HashCheck parse_hash(LineParser& lp, uint64_t tick, bool full) {
  HashCheck h;
  h.tick = tick;
  h.full = full;
  const Token& t = lp.take("hash value (16 hex digits, or ? to fill in with --update-golden)");
  if (t.text != "?") {
    uint64_t v = 0;
    auto [p, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v, 16);
    if (t.text.size() > 16 || ec != std::errc() || p != t.text.data() + t.text.size())
      lp.fail(t, "hash value must be 1 to 16 hex digits or ?, got '" + t.text + "'");
    h.value = v;
  }
  lp.done(full ? "full_hash value" : "hash value");
  return h;
}

// One tick-stamped line after its tick: input, command, check or `end`.
void parse_stamped_line(LineParser& lp, uint64_t tick, const SourceLine& src, Script& s) {
  const Token* word = &lp.take("what happens at this tick (press, release, axis, command, expect, snapshot, hash, full_hash, end)");
  uint8_t slot = 0;
  if (word->text == "slot") {
    // `T slot K press ...`: an input or command of slot K's pilot.
    if (s.header.slots == 0) lp.fail(*word, "'slot' lines need a 'slots N' header line (a network match)");
    slot = static_cast<uint8_t>(integer_in(lp, lp.take("slot number"), "slot", 0, uint64_t(s.header.slots - 1)));
    word = &lp.take("the slot's input or command (press, release, axis, command)");
    if (word->text != "press" && word->text != "release" && word->text != "axis" && word->text != "command")
      lp.fail(*word, "a slot line is press, release, axis or command, got '" + word->text + "'");
  }
  const Token& verb = *word;
  const std::string& v = verb.text;
  if (v == "press" || v == "release") {
    InputEvent e;
    e.tick = tick;
    e.kind = v == "press" ? InputEvent::Kind::Press : InputEvent::Kind::Release;
    e.button = choose(lp, lp.take("button name"), "button", kButtons, &button_name);
    e.slot = slot;
    e.src = src;
    lp.done(v + " " + button_name(e.button));
    s.inputs.push_back(e);
  } else if (v == "axis") {
    InputEvent e;
    e.tick = tick;
    e.kind = InputEvent::Kind::Axis;
    e.axis = choose(lp, lp.take("axis name"), "axis", kAxes, &axis_name);
    const Token& t = lp.take("axis value in [-1, 1]");
    double x = number(lp, t, "axis value");
    if (x < -1.0 || x > 1.0) lp.fail(t, "axis value must be in [-1, 1], got " + t.text);
    e.value = quantise_axis(x);
    e.slot = slot;
    e.src = src;
    lp.done("the axis value");
    s.inputs.push_back(e);
  } else if (v == "command") {
    CommandEvent c;
    c.tick = tick;
    c.command = choose(lp, lp.take("command name"), "command", kCommands, &command_name);
    c.slot = slot;
    c.src = src;
    lp.done(std::string("command ") + command_name(c.command));
    s.commands.push_back(c);
  } else if (v == "expect") {
    Expectation e = parse_expect(lp, tick);
    e.src = src;
    s.expectations.push_back(std::move(e));
  } else if (v == "snapshot") {
    const Token& t = lp.take("snapshot name");
    if (!valid_name(t.text))
      lp.fail(t, "snapshot name must be 1 to 64 of A-Z a-z 0-9 _ -, got '" + t.text + "'");
    for (const SnapshotCheck& o : s.snapshots)
      if (o.name == t.text) lp.fail(t, "snapshot name '" + t.text + "' is used twice (also line " + std::to_string(o.src.line) + ")");
    lp.done("the snapshot name");
    s.snapshots.push_back(SnapshotCheck{tick, t.text, src});
  } else if (v == "hash" || v == "full_hash") {
    HashCheck h = parse_hash(lp, tick, v == "full_hash");
    h.src = src;
    s.hashes.push_back(h);
  } else if (v == "end") {
    lp.done("end");
    s.end_tick = tick;
    s.end_src = src;
  } else {
    lp.fail(verb, "unknown line '" + v +
                      "'; allowed: press, release, axis, command, expect, snapshot, hash, full_hash or end");
  }
}

// The tick a line is stamped with: absolute, or +N after the previous line's tick.
uint64_t stamped_tick(LineParser& lp, const Token& first, uint64_t last_tick) {
  uint64_t tick = 0;
  if (first.text[0] == '+') {
    Token delta{first.text.substr(1), first.col + 1};
    tick = last_tick + integer_in(lp, delta, "relative tick", 0, kMaxScriptTick);
    // Summed over many lines, relative ticks could reach any count: the sum obeys the same limit.
    if (tick > kMaxScriptTick)
      lp.fail(first, "relative tick +" + delta.text + " after tick " + std::to_string(last_tick) + " reaches tick " +
                         std::to_string(tick) + "; allowed: ticks up to " + std::to_string(kMaxScriptTick));
  } else {
    tick = integer_in(lp, first, "tick", 0, kMaxScriptTick);
  }
  if (tick < last_tick)
    lp.fail(first, "tick " + std::to_string(tick) + " is before the previous line's tick " +
                       std::to_string(last_tick) + "; lines must be in tick order");
  return tick;
}

}  // namespace

// Bounded lines keep the tokenizer and the messages that quote a line cheap.
static void check_line_limits(const std::string& raw, const std::string& path, int line) {
  const std::string at = path + ":" + std::to_string(line) + ":1: ";
  if (size_t(line) > kMaxScriptLines)
    throw InputError(at + "more than " + std::to_string(kMaxScriptLines) + " lines; a replay script may have at most " +
                     std::to_string(kMaxScriptLines));
  if (raw.size() > kMaxScriptLineBytes)
    throw InputError(at + "line of " + std::to_string(raw.size()) + " bytes; lines may be at most " +
                     std::to_string(kMaxScriptLineBytes) + " bytes long");
}

Script parse_script(const std::string& text, const std::string& path, const Settings& known) {
  check_text_size(text.size(), path, kMaxScriptFileBytes, "a replay script");
  Script s;
  s.path = path;
  std::istringstream in(text);
  std::string raw;
  int line = 0;
  bool have_version = false;
  bool in_body = false;
  uint64_t last_tick = 0;
  std::vector<std::string> seen_keys;
  while (std::getline(in, raw)) {
    ++line;
    check_line_limits(raw, path, line);
    LineParser lp{path, line, {}, 0, 1};
    lp.tokens = tokenize(raw, path, line, lp.end_col);
    if (lp.tokens.empty()) continue;
    SourceLine src{line, raw};
    const Token& first = lp.tokens[0];
    if (!have_version) {
      if (first.text != "arcfire-replay")
        lp.fail(first, "a replay script starts with 'arcfire-replay " + std::to_string(kFirstFormatVersion) + "', got '" +
                           first.text + "'");
      lp.next = 1;
      s.header.version = static_cast<int>(
          integer_in(lp, lp.take("format version"), "format version", kFirstFormatVersion, kFormatVersion));
      lp.done("the format version");
      have_version = true;
      continue;
    }
    const bool stamped = (first.text[0] >= '0' && first.text[0] <= '9') || first.text[0] == '+';
    if (!stamped) {
      if (in_body)
        lp.fail(first, "expected a tick number (or +N) at the start of the line, got '" + first.text +
                           "'; header lines come before the first tick-stamped line");
      parse_header_line(lp, s.header, seen_keys, known);
      continue;
    }
    if (!in_body) {
      if (s.header.level.empty())
        lp.fail_at(1, "the header has no 'level' line (e.g. 'level levels/duel.json') before the first tick");
      in_body = true;
    }
    if (s.end_tick) lp.fail(first, "line after 'end' (line " + std::to_string(s.end_src.line) + ")");
    lp.next = 1;
    last_tick = stamped_tick(lp, first, last_tick);
    parse_stamped_line(lp, last_tick, src, s);
  }
  if (!have_version)
    throw InputError(path + ":1:1: empty script; it starts with 'arcfire-replay " + std::to_string(kFirstFormatVersion) + "'");
  if (s.header.level.empty()) throw InputError(path + ":1:1: the header has no 'level' line");
  return s;
}

Script load_script(const std::string& path, const Settings& known) {
  return parse_script(read_text_file(path, kMaxScriptFileBytes, "a replay script"), path, known);
}

}  // namespace arc::replay
