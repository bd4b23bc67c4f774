// audio/audio_engine.h — positional sound through OpenAL Soft; no GL, and no simulation.
//
// The game never calls this from its simulation: the app turns each tick's sound events into
// SoundCues (game/render/sound_events.h) and hands them here, the way a RenderView is handed to
// the renderer. AudioEngine opens the default output device, or OpenAL Soft's loopback device
// (ALC_SOFT_loopback) whose samples the caller pulls with render() — tests and headless runs.
// No device (a server, CI, a broken driver) gives one notice line and a silent engine whose
// calls all do nothing: never a crash, never a hang.
//
// Voices: at most `voices` sounds play at once. A cue that finds the pool full takes the voice
// of the lowest standing (the oldest among equals) if its own is at least as high, else it is
// dropped; standing is the sound's priority plus half its level at the listener in dB, so a
// far sound yields to a near one of the same kind. A sound with max_voices keeps only that many
// voices, the loudest (a dozen beams are thinned to the nearest few, not a wall of crackle).
// A taken voice fades out over 30 ms on a spare source, so nothing clicks.
//
// Mix bus: every sound belongs to a group (MixGroup) with its own volume; a sound with `duck`
// lowers the ducked groups (audio/mix_bus.h) while it sounds; the loopback output passes a
// look-ahead limiter. A device keeps OpenAL Soft's own output limiter instead.
// A looping sound (engine hum, beam, missile flight) plays while the game asks for it with the
// same key each update and fades out in 60 ms once it stops asking.
//
// Positions: the listener is the camera. Positions and velocities are turned into the
// camera's frame in double (camera-relative) before they become OpenAL's floats, so sound
// is placed as well 1e9 units from the origin as at it. Distance attenuation is OpenAL's
// inverse-distance-clamped model with each sound's reference distance; Doppler comes from the
// source's velocity relative to the listener.
//
// Example, compiled as AudioExamples.PlayAndRender in tests/unit/audio/test_audio_examples.cpp:
//   AudioDesc desc;  desc.loopback = true;                      // or the default device
//   AudioEngine audio(desc);                                    // audio.notice() if it is silent
//   audio.load(load_sound_library("assets/sounds/sounds.json"));
//   audio.set_listener(cam_pos, cam_orientation, cam_velocity);
//   audio.play({.sound = "explosion", .position = p, .gain = 1.0});
//   audio.update(1.0 / 60.0);
//   audio.render(stereo_frames.data(), 800);                     // loopback only
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "audio/music_def.h"
#include "audio/sound_def.h"

namespace arc {

struct AudioDesc {
  bool loopback = false;     // render into the caller's buffers instead of a sound card
  std::string device;        // output device name; empty: the system default
  int sample_rate = 48000;   // loopback rate (a device keeps its own)
  int voices = 32;           // simultaneous sounds
};

struct AudioMix {
  double volume = 1;          // master
  double effects_volume = 1;  // positional game sounds (UI sounds use only the master volume)
  double group_volume[kMixGroups] = {1, 1, 1, 1, 1, 1};  // by MixGroup: music, weapons, impacts, engines, UI, voice
  bool mute = false;
  int voices = 32;
};

struct SoundCue {
  std::string sound;          // a name in the loaded library (unknown names are ignored)
  uint64_t key = 0;           // loops: which emitter (one voice per sound and key)
  glm::dvec3 position{0.0};   // world frame
  glm::dvec3 velocity{0.0};
  double gain = 1;            // the event's intensity, times the sound's own gain
  double pitch = 1;
};

struct VoiceInfo {
  std::string sound;
  int priority = 0;
  bool fading = false;
  double fade = 1;
  double level = 1;  // its gain at the listener before the mix (distance fall-off × cue × sound)
};

class AudioEngine {
 public:
  explicit AudioEngine(const AudioDesc& desc);
  ~AudioEngine();
  AudioEngine(const AudioEngine&) = delete;
  AudioEngine& operator=(const AudioEngine&) = delete;

  bool active() const;                // a device and context are open
  const std::string& notice() const;  // why it is silent ("" when active)
  int sample_rate() const;

  // Synthesises every sound and uploads it; playing voices stop (a hot reload).
  void load(const SoundLibraryDef& library);
  void set_mix(const AudioMix& mix);
  void set_listener(const glm::dvec3& position, const glm::dquat& orientation, const glm::dvec3& velocity);
  // Starts a one-shot, or keeps a loop (by sound and key) playing and moves it.
  void play(const SoundCue& cue);
  // Advances fades by `seconds`, ends loops not asked for since the last update, frees voices
  // whose sound ended.
  void update(double seconds);
  // Loopback only: the next `frames` stereo frames, interleaved floats (zeros when inactive),
  // through the master limiter (never above the library's mix ceiling_db).
  void render(float* stereo, int frames);

  // Music (audio/music_player.h): renders the pieces; then the piece to play, by name ("" none).
  void load_music(const MusicLibraryDef& music);
  void set_music(const std::string& piece);
  std::string music() const;
  double duck_db() const;  // how far the ducked groups are lowered now

  int voice_count() const;             // playing voices, fading ones excluded
  std::vector<VoiceInfo> voices() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Writes interleaved stereo float samples as a 16-bit PCM WAV (temporary file, then rename).
void write_wav_stereo16(const std::string& path, const std::vector<float>& stereo, int sample_rate);

}  // namespace arc
