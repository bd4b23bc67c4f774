// audio/music_def.h — the game's music as data: instruments, and pieces made of pattern tracks.
//
// assets/music/music.json (documented in assets/music/README.md) describes a few synthesised
// instruments (an oscillator pair or noise, an ADSR envelope, a two-pole low-pass, a pitch drop
// for drums) and pieces: a tempo, a length in bars, and tracks that each repeat a pattern of
// steps (a note or chord, a rest, or a hold) on one instrument. render_piece() (audio/
// sequencer.h) turns a piece into stereo samples at start-up; nothing is recorded. Pieces that
// share a `set` play together in sync, so the music can crossfade between them on the beat.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace arc {

struct InstrumentDef {
  enum class Wave : uint8_t { Sine, Square, Saw, Triangle, Noise };
  std::string name;
  Wave wave = Wave::Saw;
  double detune = 0;          // cents of a second oscillator above the first; 0: one oscillator
  double attack = 0.01, decay = 0.2, sustain = 0.7, release = 0.2;  // seconds, level 0..1
  double lowpass = 8000;      // Hz, two-pole; the note's start opens it by `filter_env` times
  double filter_env = 0;      // extra cut-off share at the note's start, decaying with `decay`
  double pitch_drop = 0;      // octaves the pitch falls from the note's start (drums)
  double pitch_time = 0.05;   // seconds over which it falls 63 %
  double highpass = 0;        // Hz, one-pole; 0 off
  double gain = 1;
};

struct MusicNote {
  double start = 0, length = 0;  // steps from the piece's start
  double midi = 60;              // MIDI note number (69 = A4 = 440 Hz)
};

struct MusicTrackDef {
  int instrument = 0;            // index into MusicLibraryDef::instruments
  double gain = 1, pan = 0;      // pan −1 left .. 1 right
  int steps_per_beat = 4;
  std::vector<MusicNote> notes;  // over the whole piece, the pattern already repeated
};

struct MusicPieceDef {
  std::string name;
  double tempo = 100;            // beats per minute
  int bars = 8, beats_per_bar = 4;
  bool loop = true;
  std::string set;               // pieces of one set play in sync and crossfade on the beat
  std::string then;              // a one-shot (stinger): the piece that follows it
  double gain = 1;
  double echo_beats = 0.75, echo_feedback = 0, echo_mix = 0;  // a ping-pong echo; 0 mix: off
  std::vector<MusicTrackDef> tracks;
  double seconds() const { return bars * beats_per_bar * 60.0 / tempo; }
  double beat_seconds() const { return 60.0 / tempo; }
};

struct MusicLibraryDef {
  double crossfade_beats = 2;    // how long a change of mood takes, starting on a beat
  std::vector<InstrumentDef> instruments;
  std::vector<MusicPieceDef> pieces;
  const MusicPieceDef* find(const std::string& name) const {
    for (const MusicPieceDef& p : pieces)
      if (p.name == name) return &p;
    return nullptr;
  }
};

// Loads and checks assets/music/music.json; errors are `path:line:col: what, what is allowed`
// (InputError), like every other data file.
MusicLibraryDef load_music_library(const std::string& path);
MusicLibraryDef parse_music_library(const std::string& text, const std::string& path);

// A pattern token's MIDI note: "A4" is 69, "C#3" 49, "Eb2" 39; −1 when it is not a note.
int parse_note_name(const std::string& token);

}  // namespace arc
