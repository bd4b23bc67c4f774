// audio/music_player.h — plays the music pieces through OpenAL and changes them on the beat.
//
// Each piece is rendered once (audio/sequencer.h) into a stereo buffer on its own source. The
// game asks for a piece by name every frame; a change waits for the next beat of what plays now,
// then crossfades over the library's crossfade_beats. Pieces of one set (calm, tension, combat)
// start together and keep playing in sync at zero gain, so a crossfade between them stays on
// the beat and in key. A one-shot (a victory or defeat stinger) cuts in on the beat and, when
// its notes end, hands over to its `then` piece while its tail rings out. Beats are counted
// from the sources' own sample offsets, so under the loopback device the changes fall on the
// same sample every run. Used by AudioEngine with its context current; no GL, no simulation.
#pragma once
#include <string>
#include <vector>

#include "audio/music_def.h"

namespace arc {

class MusicPlayer {
 public:
  MusicPlayer() = default;
  ~MusicPlayer();
  MusicPlayer(const MusicPlayer&) = delete;
  MusicPlayer& operator=(const MusicPlayer&) = delete;

  // Renders every piece at `sample_rate` and uploads it; the music stops.
  void load(const MusicLibraryDef& lib, int sample_rate);
  void clear();
  // The piece that should play ("" for none); unknown names mean none.
  void request(const std::string& piece);
  // Advances the fades by `seconds`; `gain` is the music group's gain (volume, ducking).
  void update(double seconds, double gain);
  // The piece playing or fading in ("" for none).
  std::string playing() const;
  bool loaded() const { return !slots_.empty(); }

 private:
  struct Slot {
    unsigned source = 0, buffer = 0;
    double level = 0, target = 0, rate = 0;  // gain 0..1, where it goes, per second
    bool running = false;
  };
  double seconds_in(int piece) const;  // playback position of the piece's source
  int beat_of(int piece) const;
  void switch_to(int piece);
  void start_set(int piece);

  MusicLibraryDef lib_;
  std::vector<Slot> slots_;  // one per piece
  int requested_ = -1, target_ = -1, current_ = -1;
  int request_beat_ = 0;
};

}  // namespace arc
