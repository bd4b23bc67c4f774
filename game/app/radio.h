// game/app/radio.h — radio voice lines: the manifest, the queue that speaks them, the subtitles.
//
// assets/radio/lines.json names each line (an id), its speaker and its text; the WAV beside it
// (assets/radio/ID.wav, IMA ADPCM) was spoken by espeak-ng through a radio filter by
// tools/radio/gen_radio.py. Each line becomes a sound "radio/ID" of the voice group that ducks
// the fight while it speaks. RadioQueue speaks one line at a time, in order, and says what the
// HUD subtitles now. RadioDirector picks the lines the game's events call for (wing replies,
// reinforcements, a missile on the player, the player's kills, the outcome); mission lines
// ("mission_start", "objective_done") are the mission events' to say.
//
// Mission events call AudioSession::say with a line id from the manifest.
// Example, compiled as AppExamples.RadioLine in tests/unit/app/test_app_examples.cpp:
//   audio.say("objective_done");          // unknown ids: false, and nothing is said
//   if (auto s = audio.subtitle()) hud.subtitle = s->speaker + ": " + s->text;
#pragma once
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "audio/sound_def.h"
#include "game/render/sound_events.h"

namespace arc {

class World;

struct RadioLine {
  std::string id, speaker, text;
  double seconds = 0;  // length of its audio
};

struct RadioLibrary {
  std::vector<RadioLine> lines;
  std::vector<SoundDef> sounds;  // "radio/ID", decoded, in the voice group
  const RadioLine* find(const std::string& id) const;
};

// Reads the manifest and decodes every line's WAV; errors are one positioned line (InputError).
RadioLibrary load_radio_library(const std::string& manifest_path);
std::string radio_sound_name(const std::string& id);

struct Subtitle {
  std::string speaker, text;
};

class RadioQueue {
 public:
  // Queues a line (a line already waiting is not queued twice; at most kMaxWaiting wait).
  void say(const RadioLine& line, bool urgent);
  // Advances the clock; returns the line to start now, if one is due.
  std::optional<RadioLine> advance(double seconds);
  std::optional<Subtitle> subtitle() const;
  void clear() { waiting_.clear(); }

 private:
  static constexpr size_t kMaxWaiting = 3;
  static constexpr double kGap = 0.25, kLinger = 1.0;  // seconds between lines; a subtitle stays after
  std::deque<RadioLine> waiting_;
  std::optional<RadioLine> speaking_;
  double clock_ = 0, busy_until_ = 0, shown_until_ = 0;
};

class RadioDirector {
 public:
  // The ids the tick's World and sound events call for, most urgent first.
  std::vector<std::string> lines(const World& w, const std::vector<SoundEvent>& events);

 private:
  int64_t last_tick_ = -1, next_missile_call_ = 0, next_kill_call_ = 0;
  int kill_calls_ = 0;
  int outcome_ = 0;
};

}  // namespace arc
