#include <cctype>
#include <map>
#include <sstream>

#include "audio/music_def.h"
#include "core/error.h"
#include "core/json.h"

namespace arc {
namespace {

InstrumentDef::Wave wave_of(const std::string& n) {
  if (n == "sine") return InstrumentDef::Wave::Sine;
  if (n == "square") return InstrumentDef::Wave::Square;
  if (n == "triangle") return InstrumentDef::Wave::Triangle;
  if (n == "noise") return InstrumentDef::Wave::Noise;
  return InstrumentDef::Wave::Saw;
}

InstrumentDef parse_instrument(const std::string& name, JsonObject o) {
  InstrumentDef i;
  i.name = name;
  i.wave = wave_of(o.choice("wave", "saw", {"sine", "square", "saw", "triangle", "noise"}));
  i.detune = o.number("detune", 0, 0, 100);
  i.attack = o.number("attack", i.attack, 0.0005, 10);
  i.decay = o.number("decay", i.decay, 0.001, 10);
  i.sustain = o.number("sustain", i.sustain, 0, 1);
  i.release = o.number("release", i.release, 0.001, 10);
  i.lowpass = o.number("lowpass", i.lowpass, 20, 20000);
  i.filter_env = o.number("filter_env", 0, 0, 20);
  i.pitch_drop = o.number("pitch_drop", 0, 0, 6);
  i.pitch_time = o.number("pitch_time", i.pitch_time, 0.001, 2);
  i.highpass = o.number("highpass", 0, 0, 20000);
  i.gain = o.number("gain", 1, 0, 4);
  o.allow({"doc"});
  o.finish();
  return i;
}

// The pattern's steps: each token a chord ("A3+C4+E4"), a rest (".") or a hold ("-") of the
// note before; "|" marks bars for the reader and is skipped.
std::vector<MusicNote> parse_pattern(JsonObject& o, const std::string& text, int transpose, int& steps) {
  std::vector<MusicNote> notes, sounding;
  std::istringstream in(text);
  std::string tok;
  steps = 0;
  while (in >> tok) {
    if (tok == "|") continue;
    if (tok == "-") {
      if (sounding.empty())
        o.fail_key("pattern", "'" + o.key_path("pattern") + "' step " + std::to_string(steps + 1) +
                                  ": '-' holds a note, but no note sounds before it");
      for (MusicNote& n : sounding) n.length += 1;
    } else {
      for (MusicNote& n : sounding) notes.push_back(n);
      sounding.clear();
      if (tok != ".") {
        std::string part;
        std::istringstream chord(tok);
        while (std::getline(chord, part, '+')) {
          const int midi = parse_note_name(part);
          if (midi < 0)
            o.fail_key("pattern", "'" + o.key_path("pattern") + "' step " + std::to_string(steps + 1) + ": '" +
                                      tok + "' is not a step; allowed: a note like A4, C#3 or Eb2, chords joined "
                                      "with '+', '.' (rest), '-' (hold), '|' (bar line)");
          sounding.push_back({double(steps), 1.0, double(midi + transpose)});
        }
      }
    }
    ++steps;
  }
  for (MusicNote& n : sounding) notes.push_back(n);
  if (steps == 0) o.fail_key("pattern", "'" + o.key_path("pattern") + "' has no steps");
  return notes;
}

MusicTrackDef parse_track(JsonObject o, const std::map<std::string, int>& instruments, int total_beats) {
  MusicTrackDef t;
  const std::string inst = o.require_string("instrument");
  auto it = instruments.find(inst);
  if (it == instruments.end()) {
    std::vector<std::string> names;
    for (const auto& [n, i] : instruments) names.push_back(n);
    o.fail_key("instrument", "'" + o.key_path("instrument") + "' is '" + inst + "'; allowed: " + join_allowed(names));
  }
  t.instrument = it->second;
  t.gain = o.number("gain", 1, 0, 4);
  t.pan = o.number("pan", 0, -1, 1);
  t.steps_per_beat = int(o.integer("steps_per_beat", 4, 1, 16));
  const int transpose = int(o.integer("transpose", 0, -48, 48));
  int steps = 0;
  std::vector<MusicNote> pattern = parse_pattern(o, o.require_string("pattern"), transpose, steps);
  const int total = total_beats * t.steps_per_beat;
  if (total % steps != 0)
    o.fail_key("pattern", "'" + o.key_path("pattern") + "' has " + std::to_string(steps) +
                              " steps; it must divide the piece's " + std::to_string(total) + " steps (bars × beats × steps_per_beat)");
  for (int at = 0; at < total; at += steps)
    for (MusicNote n : pattern) {
      n.start += at;
      t.notes.push_back(n);
    }
  o.allow({"doc"});
  o.finish();
  return t;
}

MusicPieceDef parse_piece(const std::string& name, JsonObject o, const std::map<std::string, int>& instruments) {
  MusicPieceDef p;
  p.name = name;
  p.tempo = o.number("tempo", p.tempo, 30, 300);
  p.bars = int(o.integer("bars", p.bars, 1, 64));
  p.beats_per_bar = int(o.integer("beats_per_bar", p.beats_per_bar, 1, 16));
  p.loop = o.boolean("loop", true);
  p.set = o.string("set", "");
  p.then = o.string("then", "");
  p.gain = o.number("gain", 1, 0, 4);
  p.echo_beats = o.number("echo_beats", p.echo_beats, 0.05, 4);
  p.echo_feedback = o.number("echo_feedback", 0, 0, 0.9);
  p.echo_mix = o.number("echo_mix", 0, 0, 1);
  if (p.loop && !p.then.empty()) o.fail_key("then", "'" + o.key_path("then") + "' is only for pieces with \"loop\": false");
  if (p.seconds() > 60) o.fail_key("bars", "'" + o.key_path("bars") + "': a piece may last at most 60 s");
  for (JsonObject t : o.objects("tracks")) p.tracks.push_back(parse_track(t, instruments, p.bars * p.beats_per_bar));
  if (p.tracks.empty()) o.fail("piece '" + name + "' needs 'tracks': a non-empty array of track objects");
  o.allow({"doc"});
  o.finish();
  return p;
}

MusicLibraryDef parse_root(const std::shared_ptr<const JsonDoc>& doc) {
  JsonObject root = JsonValue(doc, "", &doc->root()).object();
  MusicLibraryDef lib;
  lib.crossfade_beats = root.number("crossfade_beats", lib.crossfade_beats, 0.25, 16);
  std::map<std::string, int> index;
  JsonObject inst = root.require_object("instruments");
  for (auto it = inst.raw().begin(); it != inst.raw().end(); ++it) {
    index[it.key()] = int(lib.instruments.size());
    lib.instruments.push_back(parse_instrument(it.key(), inst.get(it.key())->object()));
  }
  inst.finish();
  JsonObject pieces = root.require_object("pieces");
  for (auto it = pieces.raw().begin(); it != pieces.raw().end(); ++it)
    lib.pieces.push_back(parse_piece(it.key(), pieces.get(it.key())->object(), index));
  // A set plays in sync: one tempo and length. A stinger's follower must exist and loop.
  for (auto it = pieces.raw().begin(); it != pieces.raw().end(); ++it) {
    const MusicPieceDef& p = *lib.find(it.key());
    JsonObject o = pieces.get(it.key())->object();
    for (const MusicPieceDef& q : lib.pieces)
      if (!p.set.empty() && q.set == p.set && (q.tempo != p.tempo || q.seconds() != p.seconds()))
        o.fail_key("set", "'" + o.key_path("set") + "': pieces of set '" + p.set + "' must share tempo, bars and beats_per_bar ('" +
                              q.name + "' differs)");
    if (!p.then.empty() && (!lib.find(p.then) || !lib.find(p.then)->loop))
      o.fail_key("then", "'" + o.key_path("then") + "' is '" + p.then + "'; allowed: the name of a looping piece");
  }
  for (const char* needed : {"menu", "calm", "tension", "combat", "victory", "defeat"})
    if (!lib.find(needed)) pieces.fail(std::string("'pieces' needs a piece named '") + needed +
                                       "' (menu, calm, tension, combat, victory and defeat are played by the game)");
  pieces.finish();
  root.allow({"doc"});
  root.finish();
  return lib;
}

}  // namespace

int parse_note_name(const std::string& t) {
  static const int base[7] = {9, 11, 0, 2, 4, 5, 7};  // A B C D E F G
  if (t.size() < 2 || t.size() > 3) return -1;
  const char letter = char(std::toupper(static_cast<unsigned char>(t[0])));
  if (letter < 'A' || letter > 'G') return -1;
  int n = base[letter - 'A'];
  size_t at = 1;
  if (t[at] == '#') n += 1, ++at;
  else if (t[at] == 'b') n -= 1, ++at;
  if (at != t.size() - 1 || !std::isdigit(static_cast<unsigned char>(t[at]))) return -1;
  return n + 12 * (t[at] - '0' + 1);
}

MusicLibraryDef load_music_library(const std::string& path) { return parse_root(JsonDoc::load_file(path)); }

MusicLibraryDef parse_music_library(const std::string& text, const std::string& path) {
  return parse_root(JsonDoc::parse(text, path));
}

}  // namespace arc
