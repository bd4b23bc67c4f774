// audio/sound_def.h — what a sound is: parameters the synthesiser turns into samples.
//
// Every sound of the game is described in assets/sounds/sounds.json (documented in
// assets/sounds/README.md) by a few layers, each an oscillator or a noise source with a pitch
// sweep, an envelope, one-pole filters and an optional burst gate, summed and scaled. Nothing
// is recorded or downloaded: synthesise() makes the samples at start-up, from a seed, so the same
// file gives the same samples on every run. These are plain defs; load_sound_library() fills
// them and checks every value.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace arc {

// The mix bus's groups: each has its volume setting, and ducking lowers some of them.
enum class MixGroup : uint8_t { Music = 0, Weapons = 1, Impacts = 2, Engines = 3, Ui = 4, Voice = 5 };
constexpr int kMixGroups = 6;
const char* mix_group_name(MixGroup g);

struct SoundLayerDef {
  enum class Source : uint8_t { Sine, Square, Saw, Triangle, Noise };
  Source source = Source::Sine;
  double freq_start = 220, freq_end = 220;  // Hz, swept exponentially over the layer (oscillators)
  double gain = 1;
  double delay = 0;                          // seconds after the sound starts
  double attack = 0.005, hold = 0, decay = 0.2;  // envelope, seconds (loops: ignored, steady)
  double decay_curve = 2;                    // envelope power during decay: 1 linear, higher is sharper
  double lowpass = 0, highpass = 0;          // one-pole cut-offs in Hz; 0 is off
  double burst_period = 0, burst_length = 0; // gate: on for burst_length every period (jittered); 0 is off
  double jitter = 0;                         // fraction of the period a burst start may move
};

struct SoundDef {
  std::string name;
  bool loop = false;            // looped while the game keeps asking for it; seamless at the seam
  double duration = 1;          // seconds of samples (a loop's length)
  int priority = 50;            // 0..100: a full voice pool drops the lowest for a higher one
  double gain = 1;
  bool positional = true;       // false: UI sounds, heard at the listener whatever the camera
  double reference_distance = 50;  // units at which the gain is 1 (inverse-distance, clamped)
  double max_distance = 20000;     // beyond it the sound no longer falls off
  double rolloff = 1;
  uint64_t seed = 1;
  MixGroup group = MixGroup::Weapons;
  int max_voices = 0;           // at most this many voices of the sound (the loudest kept); 0: no cap
  double duck = 0;              // dB by which the ducked groups drop while it sounds (a cue that must cut through)
  double duck_hold = -1;        // seconds the duck holds; < 0: the mix's duck_hold
  std::vector<int16_t> pcm;     // samples given instead of layers (radio lines decoded from assets)
  int pcm_rate = 0;
  std::vector<SoundLayerDef> layers;
};

// The master bus: gain, the limiter's ceiling, and how ducking moves.
struct MixDef {
  double master_db = 0;         // gain on the whole mix before the limiter
  double ceiling_db = -1;       // the limiter's ceiling: no sample of the output exceeds it
  double limiter_release = 0.25;  // seconds for the limiter's gain to recover 63 % of the way
  double duck_hold = 0.6;       // seconds a duck holds at full depth after its cue starts
  double duck_release = 0.5;    // seconds over which it returns to 0 dB
  bool ducked[kMixGroups] = {true, true, true, true, false, false};  // music, weapons, impacts, engines
};

struct SoundLibraryDef {
  double speed_of_sound = 1500;  // world units per second, for Doppler (space is silent: a game value)
  double doppler_factor = 1;
  MixDef mix;
  std::vector<SoundDef> sounds;  // in file order
  const SoundDef* find(const std::string& name) const {
    for (const SoundDef& s : sounds)
      if (s.name == name) return &s;
    return nullptr;
  }
};

}  // namespace arc
