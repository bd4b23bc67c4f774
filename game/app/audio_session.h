// game/app/audio_session.h — the game's sound: settings, the sound file, events to cues.
//
// One AudioSession per run. It loads assets/sounds/sounds.json (a bad file throws InputError
// at start-up; a bad hot reload keeps the last good sounds and returns the error), opens the
// default device (window) or the loopback device (headless, tests), applies the audio.*
// settings, and after every tick turns the SoundEventTracker's events (game/render/
// sound_events.h) into cues; before mixing it places the listener at the camera. UI clicks
// come from the app. Beside the sound file it loads the music (assets/music/music.json, played
// by the MusicDirector's mood, or the menu theme while a menu is over the game) and the radio
// lines (assets/radio/lines.json, spoken one at a time with subtitles); where either file is
// absent (a test's own sound file) there is none. Without a device it is silent and costs
// almost nothing.
//
// Example, compiled as AppExamples.AudioSession in tests/unit/app/test_app_examples.cpp:
//   AudioSession audio(root + "/assets/sounds/sounds.json", settings, false);
//   game.step(frame, commands);  audio.after_tick(game.world());
//   audio.frame(game.world(), frame_seconds);
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "audio/audio_engine.h"
#include "audio/sound_def.h"
#include "core/settings.h"
#include "game/app/music_director.h"
#include "game/app/radio.h"
#include "game/render/sound_events.h"

namespace arc {

class World;
struct LevelDef;

// The engine's cue for a game sound event: explosions louder and deeper for bigger blasts,
// the engine hum's gain and pitch by throttle.
SoundCue sound_cue(const SoundEvent& e);
// The audio.* settings as the engine's mix.
AudioMix audio_mix(const Settings& s);

class AudioSession {
 public:
  AudioSession(const std::string& sounds_path, const Settings& settings, bool loopback);

  void apply_settings(const Settings& settings);
  bool toggle_mute();  // returns whether it is muted now
  bool muted() const { return mix_.mute; }
  // The master volume in steps of 0.1 within [0, 1] (the pause menu's Volume item).
  double step_volume(int steps);
  double volume() const { return mix_.volume; }
  // The events of the tick just stepped, played; the last list stays for expectations.
  void after_tick(const World& w);
  // Listener at the camera, fades advanced by the frame's time.
  void frame(const World& w, double seconds);
  // A non-positional sound by name: "ui_click", "victory", "defeat".
  void ui(const std::string& sound);
  // Reads the sound file again: "" when it loaded, else its error (the old sounds stay).
  std::string reload();
  // While a menu is over the game (the title, the results) the menu theme plays.
  void set_menu(bool open) { menu_ = open; }
  // Speaks a radio line by its id in assets/radio/lines.json (after any line speaking now);
  // false for an unknown id. Missions' own lines come through here.
  bool say(const std::string& line_id, bool urgent = false);
  // The line being spoken, for the HUD (none when audio.subtitles is off).
  std::optional<Subtitle> subtitle() const;
  const RadioLibrary& radio() const { return radio_; }
  // Throws InputError, positioned in the level file, where a radio action's "voice" names no
  // line of the radio manifest or a "cue" action names no sound of the sound file. after_tick
  // checks each level once, when it first meets it.
  void check_level(const LevelDef& level) const;

  AudioEngine& engine() { return *engine_; }
  const std::vector<SoundEvent>& last_events() const { return events_; }
  const std::string& sounds_path() const { return path_; }

 private:
  std::string path_;
  AudioMix mix_;
  std::unique_ptr<AudioEngine> engine_;
  SoundEventTracker tracker_;
  std::vector<SoundEvent> events_;
  MusicDirector director_;
  RadioLibrary radio_;
  RadioDirector radio_director_;
  RadioQueue radio_queue_;
  std::vector<std::string> sound_names_;  // of the sound file, for the levels' cues
  std::string checked_level_;             // the path of the level check_level passed last
  void mission_audio(const World& w);
  const char* mood_ = "menu";
  bool menu_ = false, subtitles_ = true;
  bool ticked_ = false;  // a tick was stepped since the last frame()
};

// A headless or replayed session's sound: after each tick, that tick's share of samples from
// the loopback device (48 kHz; a 60 Hz tick is 800 frames), written as a 16-bit stereo WAV at
// the end. The same ticks give the same file, byte for byte.
class AudioCapture {
 public:
  AudioCapture(const std::string& sounds_path, const Settings& settings, std::string wav_path);
  void after_tick(const World& w);
  // Writes the WAV (atomically) and says where; returns the number of frames written.
  size_t finish();
  AudioSession& session() { return session_; }
  const std::vector<float>& samples() const { return samples_; }

 private:
  AudioSession session_;
  std::string wav_path_;
  std::vector<float> samples_;  // interleaved stereo
  double owed_ = 0;             // frames owed to the ticks so far, fraction carried
};

}  // namespace arc
