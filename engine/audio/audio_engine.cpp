#include "audio/audio_engine.h"

#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

#include <glm/geometric.hpp>

#include "audio/mix_bus.h"
#include "audio/music_player.h"
#include "audio/synth.h"
#include "core/file_writer.h"
#include "core/json.h"

namespace arc {
namespace {

constexpr double kStealFade = 0.03;  // seconds over which a taken voice fades out
constexpr double kLoopFade = 0.06;   // seconds over which a loop no longer asked for fades out
constexpr double kLoopFadeIn = 0.02;
constexpr int kSpareSources = 8;     // fading voices play on these, beyond the voice limit
constexpr double kInaudible = 0.002; // a new sound quieter than this at the listener is not started

struct Voice {
  ALuint source = 0;
  int sound = -1;          // index in the library; −1: free
  uint64_t key = 0;
  bool loop = false;
  bool asked = false;      // a loop asked for since the last update
  bool fading = false;
  double fade = 1, fade_rate = 0;  // fade_rate per second: < 0 out, > 0 in
  double cue_gain = 1;
  double level = 1;        // gain at the listener before the mix: fall-off × cue × sound
  uint64_t started = 0;    // order of starting, for "oldest among equals"
};

// While a device opens, ALSA and OpenAL Soft write their own diagnostics to stderr (several
// lines when there is no sound card); the game says what matters in one notice line instead.
class QuietStderr {
 public:
  QuietStderr() {
    std::fflush(stderr);
    saved_ = dup(2);
    const int null = open("/dev/null", O_WRONLY);
    if (saved_ >= 0 && null >= 0) dup2(null, 2);
    if (null >= 0) ::close(null);
  }
  ~QuietStderr() {
    if (saved_ < 0) return;
    dup2(saved_, 2);
    ::close(saved_);
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_ = -1;
};

using LoopbackOpen = ALCdevice*(ALC_APIENTRY*)(const ALCchar*);
using LoopbackSupported = ALCboolean(ALC_APIENTRY*)(ALCdevice*, ALCsizei, ALCenum, ALCenum);
using LoopbackRender = void(ALC_APIENTRY*)(ALCdevice*, ALCvoid*, ALCsizei);

}  // namespace

struct AudioEngine::Impl {
  AudioDesc desc;
  AudioMix mix;
  std::string notice;
  ALCdevice* device = nullptr;
  ALCcontext* context = nullptr;
  LoopbackRender render = nullptr;
  SoundLibraryDef library;
  std::vector<ALuint> buffers;  // one per library sound
  std::vector<Voice> voices;    // mix.voices + kSpareSources sources
  glm::dvec3 listener_pos{0.0}, listener_vel{0.0};
  glm::dquat listener_inv{1, 0, 0, 0};
  uint64_t next_start = 0;
  std::unique_ptr<Limiter> limiter;
  Ducker ducker;
  MusicPlayer music;

  bool open_device();
  bool open_loopback();
  void close();
  void make_sources(int voices);
  void delete_sources();
  void apply(Voice& v, const SoundCue* cue);
  double mix_gain(const SoundDef& def) const;
  double group_gain(MixGroup g, bool duckable = true) const;
  Voice* find_loop(int sound, uint64_t key);
  Voice* free_voice();
  Voice* take_voice(double standing, bool loop);
  bool thin(int sound, double level);
  double level_of(const SoundDef& def, const SoundCue& cue) const;
  double standing(const Voice& v) const;
  void stop(Voice& v);
  void start(Voice& v, int sound, const SoundCue& cue);
};

bool AudioEngine::Impl::open_loopback() {
  if (!alcIsExtensionPresent(nullptr, "ALC_SOFT_loopback")) {
    notice = "no ALC_SOFT_loopback in this OpenAL";
    return false;
  }
  auto open = reinterpret_cast<LoopbackOpen>(alcGetProcAddress(nullptr, "alcLoopbackOpenDeviceSOFT"));
  auto supported = reinterpret_cast<LoopbackSupported>(alcGetProcAddress(nullptr, "alcIsRenderFormatSupportedSOFT"));
  render = reinterpret_cast<LoopbackRender>(alcGetProcAddress(nullptr, "alcRenderSamplesSOFT"));
  device = open && supported && render ? open(nullptr) : nullptr;
  if (!device) {
    notice = "the OpenAL loopback device did not open";
    return false;
  }
  if (!supported(device, desc.sample_rate, ALC_STEREO_SOFT, ALC_FLOAT_SOFT)) {
    notice = "the OpenAL loopback device cannot render " + std::to_string(desc.sample_rate) + " Hz stereo float";
    return false;
  }
  // No HRTF and no output limiter: plain panning, and samples that depend only on the sources.
  const ALCint attrs[] = {ALC_FREQUENCY, desc.sample_rate, ALC_FORMAT_CHANNELS_SOFT, ALC_STEREO_SOFT,
                          ALC_FORMAT_TYPE_SOFT, ALC_FLOAT_SOFT, ALC_HRTF_SOFT, ALC_FALSE,
                          ALC_OUTPUT_LIMITER_SOFT, ALC_FALSE, 0};
  context = alcCreateContext(device, attrs);
  return context != nullptr;
}

bool AudioEngine::Impl::open_device() {
  setenv("ALSOFT_LOGLEVEL", "0", 0);  // OpenAL Soft's own log only when asked for
  QuietStderr quiet;
  if (desc.loopback) {
    if (!open_loopback()) return false;
  } else {
    device = alcOpenDevice(desc.device.empty() ? nullptr : desc.device.c_str());
    if (!device) {
      notice = desc.device.empty() ? "no audio output device" : "no audio output device '" + desc.device + "'";
      return false;
    }
    context = alcCreateContext(device, nullptr);
  }
  if (!context || !alcMakeContextCurrent(context)) {
    if (notice.empty()) notice = "the audio device would not make a context";
    return false;
  }
  alDistanceModel(AL_INVERSE_DISTANCE_CLAMPED);
  return true;
}

void AudioEngine::Impl::close() {
  if (context) music.clear();
  delete_sources();
  if (!buffers.empty()) alDeleteBuffers(ALsizei(buffers.size()), buffers.data());
  buffers.clear();
  if (context) {
    alcMakeContextCurrent(nullptr);
    alcDestroyContext(context);
  }
  if (device) alcCloseDevice(device);
  context = nullptr;
  device = nullptr;
}

void AudioEngine::Impl::make_sources(int count) {
  voices.assign(size_t(count + kSpareSources), Voice{});
  for (Voice& v : voices) {
    alGenSources(1, &v.source);
    alSourcef(v.source, AL_MAX_GAIN, 4.0f);
  }
}

void AudioEngine::Impl::delete_sources() {
  for (Voice& v : voices) {
    alSourceStop(v.source);
    alSourcei(v.source, AL_BUFFER, 0);
    alDeleteSources(1, &v.source);
  }
  voices.clear();
}

double AudioEngine::Impl::group_gain(MixGroup g, bool duckable) const {
  if (mix.mute) return 0.0;
  const double master = mix.volume * std::pow(10.0, library.mix.master_db / 20.0);
  return master * mix.group_volume[int(g)] * (duckable && library.mix.ducked[int(g)] ? ducker.gain() : 1.0);
}

// A sound that ducks the others is not ducked itself.
double AudioEngine::Impl::mix_gain(const SoundDef& def) const {
  return group_gain(def.group, def.duck <= 0) * (def.positional ? mix.effects_volume : 1.0) * def.gain;
}

// Position and velocity in the camera's frame, and the gain with its fade, onto the source.
void AudioEngine::Impl::apply(Voice& v, const SoundCue* cue) {
  const SoundDef& def = library.sounds[size_t(v.sound)];
  if (cue && def.positional) {
    const glm::dvec3 p = listener_inv * (cue->position - listener_pos);
    const glm::dvec3 vel = listener_inv * (cue->velocity - listener_vel);
    alSource3f(v.source, AL_POSITION, float(p.x), float(p.y), float(p.z));
    alSource3f(v.source, AL_VELOCITY, float(vel.x), float(vel.y), float(vel.z));
    alSourcef(v.source, AL_PITCH, float(std::clamp(cue->pitch, 0.25, 4.0)));
  }
  if (cue) {
    v.cue_gain = cue->gain;
    v.level = level_of(def, *cue);
  }
  alSourcef(v.source, AL_GAIN, float(std::max(0.0, mix_gain(def) * v.cue_gain * v.fade)));
}

Voice* AudioEngine::Impl::find_loop(int sound, uint64_t key) {
  for (Voice& v : voices)
    if (v.sound == sound && v.key == key && v.loop && !v.fading) return &v;
  return nullptr;
}

Voice* AudioEngine::Impl::free_voice() {
  for (Voice& v : voices)
    if (v.sound < 0) return &v;
  return nullptr;
}

// OpenAL's inverse-distance-clamped gain at the cue's distance, times the cue's and the sound's.
double AudioEngine::Impl::level_of(const SoundDef& def, const SoundCue& cue) const {
  if (!def.positional) return cue.gain * def.gain;
  const double d = std::clamp(glm::length(cue.position - listener_pos), def.reference_distance, def.max_distance);
  const double falloff = def.reference_distance / (def.reference_distance + def.rolloff * (d - def.reference_distance));
  return falloff * cue.gain * def.gain;
}

// Priority and importance first; among equals the nearer (louder) sound stands higher.
double AudioEngine::Impl::standing(const Voice& v) const {
  return library.sounds[size_t(v.sound)].priority + 10.0 * std::log10(std::max(v.level, 1e-6));
}

// A sound at its max_voices: a new cue louder by 3 dB than the quietest of them takes its
// place (it fades out); else the cue is not heard. Returns whether the cue may start.
bool AudioEngine::Impl::thin(int sound, double level) {
  const SoundDef& def = library.sounds[size_t(sound)];
  if (def.max_voices <= 0) return true;
  int count = 0;
  Voice* quietest = nullptr;
  for (Voice& v : voices) {
    if (v.sound != sound || v.fading) continue;
    ++count;
    if (!quietest || v.level < quietest->level) quietest = &v;
  }
  if (count < def.max_voices) return true;
  if (!quietest || level < quietest->level * 1.41) return false;
  quietest->fading = true;
  quietest->fade_rate = -1.0 / kStealFade;
  return true;
}

// When the pool is full: the lowest-priority playing voice (oldest among equals) starts fading
// out, if it is below `priority` — or equal, when neither is a loop (a newer spark replaces an
// older one; loops of equal priority, asked for every tick, would otherwise take turns).
// Returns the source the new sound takes, or null.
Voice* AudioEngine::Impl::take_voice(double priority, bool loop) {
  int playing = 0;
  Voice* victim = nullptr;
  for (Voice& v : voices) {
    if (v.sound < 0 || v.fading) continue;
    ++playing;
    const double p = standing(v);
    const double vp = victim ? standing(*victim) : 1e9;
    if (p < vp || (p == vp && v.started < victim->started)) victim = &v;
  }
  if (playing >= mix.voices) {
    if (!victim) return nullptr;
    const double vp = standing(*victim);
    // Loops asked for every tick keep their voices against a newcomer unless it clearly stands higher.
    if (vp > priority || ((loop || victim->loop) && vp + 3.0 > priority)) return nullptr;
    victim->fading = true;
    victim->fade_rate = -1.0 / kStealFade;
  }
  if (Voice* v = free_voice()) return v;
  // Every spare source is still fading: cut the quietest fade (it is nearly silent).
  Voice* quietest = nullptr;
  for (Voice& v : voices)
    if (v.fading && (!quietest || v.fade < quietest->fade)) quietest = &v;
  if (!quietest) return nullptr;
  stop(*quietest);
  return quietest;
}

void AudioEngine::Impl::stop(Voice& v) {
  alSourceStop(v.source);
  alSourcei(v.source, AL_BUFFER, 0);
  v = Voice{v.source};
}

void AudioEngine::Impl::start(Voice& v, int sound, const SoundCue& cue) {
  const SoundDef& def = library.sounds[size_t(sound)];
  v.sound = sound;
  v.key = cue.key;
  v.loop = def.loop;
  v.asked = true;
  v.fading = false;
  v.fade = def.loop ? 0.0 : 1.0;
  v.fade_rate = def.loop ? 1.0 / kLoopFadeIn : 0.0;
  v.started = next_start++;
  v.level = level_of(def, cue);
  if (def.duck > 0) ducker.trigger(def.duck * std::min(cue.gain, 1.0), def.duck_hold >= 0 ? def.duck_hold : library.mix.duck_hold, library.mix.duck_release);
  alSourcei(v.source, AL_BUFFER, ALint(buffers[size_t(sound)]));
  alSourcei(v.source, AL_LOOPING, def.loop ? AL_TRUE : AL_FALSE);
  alSourcei(v.source, AL_SOURCE_RELATIVE, def.positional ? AL_FALSE : AL_TRUE);
  alSource3f(v.source, AL_POSITION, 0, 0, 0);
  alSource3f(v.source, AL_VELOCITY, 0, 0, 0);
  alSourcef(v.source, AL_REFERENCE_DISTANCE, float(def.reference_distance));
  alSourcef(v.source, AL_MAX_DISTANCE, float(def.max_distance));
  alSourcef(v.source, AL_ROLLOFF_FACTOR, def.positional ? float(def.rolloff) : 0.0f);
  alSourcef(v.source, AL_PITCH, 1.0f);
  apply(v, &cue);
  alSourcePlay(v.source);
}

AudioEngine::AudioEngine(const AudioDesc& desc) : impl_(std::make_unique<Impl>()) {
  impl_->desc = desc;
  impl_->mix.voices = desc.voices;
  if (!impl_->open_device()) {
    impl_->close();
    std::fprintf(stderr, "arcfire: sound off: %s; the game runs silently\n", impl_->notice.c_str());
    return;
  }
  impl_->make_sources(desc.voices);
}

AudioEngine::~AudioEngine() { impl_->close(); }

bool AudioEngine::active() const { return impl_->context != nullptr; }
const std::string& AudioEngine::notice() const { return impl_->notice; }
int AudioEngine::sample_rate() const {
  ALCint rate = impl_->desc.sample_rate;
  if (impl_->device) alcGetIntegerv(impl_->device, ALC_FREQUENCY, 1, &rate);
  return rate;
}

void AudioEngine::load(const SoundLibraryDef& library) {
  Impl& m = *impl_;
  m.library = library;
  if (!active()) return;
  m.delete_sources();
  if (!m.buffers.empty()) alDeleteBuffers(ALsizei(m.buffers.size()), m.buffers.data());
  m.buffers.assign(library.sounds.size(), 0);
  alGenBuffers(ALsizei(m.buffers.size()), m.buffers.data());
  const int rate = sample_rate();
  m.limiter = std::make_unique<Limiter>(rate, library.mix.ceiling_db, library.mix.limiter_release);
  for (size_t i = 0; i < library.sounds.size(); ++i) {
    const SoundDef& def = library.sounds[i];
    if (!def.pcm.empty()) {
      alBufferData(m.buffers[i], AL_FORMAT_MONO16, def.pcm.data(), ALsizei(def.pcm.size() * 2), def.pcm_rate);
      continue;
    }
    std::vector<float> f = synthesise(def, rate);
    std::vector<int16_t> pcm(f.size());
    for (size_t k = 0; k < f.size(); ++k) pcm[k] = int16_t(std::lround(std::clamp(f[k], -1.0f, 1.0f) * 32767.0f));
    alBufferData(m.buffers[i], AL_FORMAT_MONO16, pcm.data(), ALsizei(pcm.size() * 2), rate);
  }
  alSpeedOfSound(float(library.speed_of_sound));
  alDopplerFactor(float(library.doppler_factor));
  m.make_sources(m.mix.voices);
}

void AudioEngine::set_mix(const AudioMix& mix) {
  Impl& m = *impl_;
  const bool resize = mix.voices != m.mix.voices;
  m.mix = mix;
  if (!active()) return;
  if (resize) {
    m.delete_sources();
    m.make_sources(mix.voices);
  }
  for (Voice& v : m.voices)
    if (v.sound >= 0) m.apply(v, nullptr);
}

void AudioEngine::set_listener(const glm::dvec3& position, const glm::dquat& orientation,
                               const glm::dvec3& velocity) {
  impl_->listener_pos = position;
  impl_->listener_inv = glm::inverse(glm::normalize(orientation));
  impl_->listener_vel = velocity;
}

void AudioEngine::play(const SoundCue& cue) {
  Impl& m = *impl_;
  if (!active()) return;
  int sound = -1;
  for (size_t i = 0; i < m.library.sounds.size(); ++i)
    if (m.library.sounds[i].name == cue.sound) sound = int(i);
  if (sound < 0) return;
  const SoundDef& def = m.library.sounds[size_t(sound)];
  if (def.loop) {
    if (Voice* v = m.find_loop(sound, cue.key)) {
      v->asked = true;
      m.apply(*v, &cue);
      return;
    }
  }
  const double level = m.level_of(def, cue);
  if (level < kInaudible || !m.thin(sound, level)) return;
  if (Voice* v = m.take_voice(def.priority + 10.0 * std::log10(std::max(level, 1e-6)), def.loop)) m.start(*v, sound, cue);
}

void AudioEngine::update(double seconds) {
  Impl& m = *impl_;
  if (!active()) return;
  m.ducker.advance(seconds);
  m.music.update(seconds, m.group_gain(MixGroup::Music));
  for (Voice& v : m.voices) {
    if (v.sound < 0) continue;
    if (v.loop && !v.asked && !v.fading) {
      v.fading = true;
      v.fade_rate = -1.0 / kLoopFade;
    }
    v.asked = false;
    // A fade that reached zero was mixed at zero gain last block: only now is stopping silent.
    const bool faded_out = v.fading && v.fade <= 0.0;
    if (v.fade_rate != 0) v.fade = std::clamp(v.fade + v.fade_rate * seconds, 0.0, 1.0);
    if (!v.fading && v.fade >= 1.0) v.fade_rate = 0;
    ALint state = AL_PLAYING;
    alGetSourcei(v.source, AL_SOURCE_STATE, &state);
    if (state == AL_STOPPED || faded_out) {
      m.stop(v);
      continue;
    }
    m.apply(v, nullptr);
  }
}

void AudioEngine::render(float* stereo, int frames) {
  Impl& m = *impl_;
  if (!active() || !m.render) {
    std::fill(stereo, stereo + 2 * size_t(frames), 0.0f);
    return;
  }
  m.render(m.device, stereo, frames);
  if (m.limiter) m.limiter->process(stereo, frames);
}

void AudioEngine::load_music(const MusicLibraryDef& music) {
  if (active()) impl_->music.load(music, sample_rate());
}

void AudioEngine::set_music(const std::string& piece) {
  if (active()) impl_->music.request(piece);
}

std::string AudioEngine::music() const { return impl_->music.playing(); }
double AudioEngine::duck_db() const { return impl_->ducker.depth_db(); }

int AudioEngine::voice_count() const {
  int n = 0;
  for (const Voice& v : impl_->voices) n += v.sound >= 0 && !v.fading;
  return n;
}

std::vector<VoiceInfo> AudioEngine::voices() const {
  std::vector<VoiceInfo> out;
  for (const Voice& v : impl_->voices)
    if (v.sound >= 0)
      out.push_back({impl_->library.sounds[size_t(v.sound)].name, impl_->library.sounds[size_t(v.sound)].priority,
                     v.fading, v.fade, v.level});
  return out;
}

void write_wav_stereo16(const std::string& path, const std::vector<float>& stereo, int sample_rate) {
  std::string data(44, '\0');
  auto put32 = [&](size_t at, uint32_t x) { std::memcpy(&data[at], &x, 4); };
  auto put16 = [&](size_t at, uint16_t x) { std::memcpy(&data[at], &x, 2); };
  const uint32_t bytes = uint32_t(stereo.size() * 2);
  std::memcpy(&data[0], "RIFF", 4);
  put32(4, 36 + bytes);
  std::memcpy(&data[8], "WAVEfmt ", 8);
  put32(16, 16);
  put16(20, 1);
  put16(22, 2);
  put32(24, uint32_t(sample_rate));
  put32(28, uint32_t(sample_rate) * 4);
  put16(32, 4);
  put16(34, 16);
  std::memcpy(&data[36], "data", 4);
  put32(40, bytes);
  for (float s : stereo) {
    const int16_t v = int16_t(std::lround(std::clamp(s, -1.0f, 1.0f) * 32767.0f));
    data.append(reinterpret_cast<const char*>(&v), 2);
  }
  write_file_atomic(path, data);
}

}  // namespace arc
