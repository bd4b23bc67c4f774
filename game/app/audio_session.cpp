#include "game/app/audio_session.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "audio/music_def.h"
#include "audio/sound_library.h"
#include "core/error.h"
#include "core/json.h"
#include "game/sim/world.h"

namespace arc {
namespace {

constexpr double kReferenceBlast = 48;  // a fighter's blast radius (collision radius 8 × 6)

// assets/NAME beside assets/sounds/, or "" when there is no such file.
std::string beside_sounds(const std::string& sounds_path, const char* name) {
  namespace fs = std::filesystem;
  const fs::path p = fs::path(sounds_path).parent_path().parent_path() / name;
  std::error_code ec;
  return fs::is_regular_file(p, ec) ? p.string() : "";
}

}  // namespace

SoundCue sound_cue(const SoundEvent& e) {
  SoundCue c;
  c.sound = sound_kind_name(e.kind);
  c.key = is_loop(e.kind) ? e.owner : 0;
  c.position = e.position;
  c.velocity = e.velocity;
  c.gain = e.intensity;
  if (e.kind == SoundKind::Explosion) {
    const double scale = std::max(e.size, 1.0) / kReferenceBlast;
    c.gain = std::clamp(std::sqrt(scale), 0.6, 1.6);
    c.pitch = std::clamp(std::pow(scale, -0.3), 0.55, 1.4);
  }
  if (e.kind == SoundKind::EngineHum) c.pitch = 0.75 + 0.5 * e.intensity;
  return c;
}

AudioMix audio_mix(const Settings& s) {
  AudioMix m;
  m.volume = s.number("audio.volume");
  m.effects_volume = s.number("audio.effects_volume");
  m.mute = s.flag("audio.mute");
  const char* groups[kMixGroups] = {"audio.music_volume", "audio.weapons_volume", "audio.impacts_volume",
                                    "audio.engines_volume", "audio.ui_volume",    "audio.voice_volume"};
  for (int g = 0; g < kMixGroups; ++g) m.group_volume[g] = s.number(groups[g]);
  m.voices = int(s.integer("audio.voices"));
  return m;
}

AudioSession::AudioSession(const std::string& sounds_path, const Settings& settings, bool loopback)
    : path_(sounds_path), mix_(audio_mix(settings)) {
  // Every file is read and checked before any device opens: a bad one throws first.
  SoundLibraryDef library = load_sound_library(sounds_path);
  const std::string radio_path = beside_sounds(sounds_path, "radio/lines.json");
  if (!radio_path.empty()) radio_ = load_radio_library(radio_path);
  const std::string music_path = beside_sounds(sounds_path, "music/music.json");
  MusicLibraryDef music;
  if (!music_path.empty()) music = load_music_library(music_path);
  for (const SoundDef& s : library.sounds) sound_names_.push_back(s.name);
  for (const SoundDef& s : radio_.sounds) library.sounds.push_back(s);
  subtitles_ = settings.flag("audio.subtitles");
  AudioDesc desc;
  desc.loopback = loopback;
  desc.voices = mix_.voices;
  engine_ = std::make_unique<AudioEngine>(desc);
  engine_->set_mix(mix_);
  engine_->load(library);
  if (!music.pieces.empty()) engine_->load_music(music);
}

void AudioSession::apply_settings(const Settings& settings) {
  const bool mute = mix_.mute;
  mix_ = audio_mix(settings);
  mix_.mute = mix_.mute || mute;  // M's toggle stands until the setting is changed to on
  subtitles_ = settings.flag("audio.subtitles");
  engine_->set_mix(mix_);
}

bool AudioSession::toggle_mute() {
  mix_.mute = !mix_.mute;
  engine_->set_mix(mix_);
  return mix_.mute;
}

double AudioSession::step_volume(int steps) {
  mix_.volume = std::clamp(std::round(mix_.volume * 10.0 + steps) / 10.0, 0.0, 1.0);
  engine_->set_mix(mix_);
  return mix_.volume;
}

void AudioSession::after_tick(const World& w) {
  ticked_ = true;
  events_ = tracker_.collect(w);
  for (const SoundEvent& e : events_) engine_->play(sound_cue(e));
  for (const std::string& id : radio_director_.lines(w, events_))
    say(id, id == "missile_six" || id == "mission_won" || id == "mission_lost");
  mission_audio(w);
  mood_ = director_.mood(w);
}

// The voices and cues of the mission events that fired this tick, from the level's actions
// (the replay's ticks fire the same events, so a render speaks the same lines).
void AudioSession::mission_audio(const World& w) {
  if (!w.mission) return;
  if (w.level.path != checked_level_) {
    check_level(w.level);
    checked_level_ = w.level.path;
  }
  const std::vector<EventDef>& defs = w.level.events.events;
  for (size_t i = 0; i < defs.size() && i < w.mission->events.size(); ++i) {
    if (w.mission->events[i].fired_tick != w.tick) continue;
    for (const ActionDef& a : defs[i].actions) {
      if (a.kind == ActionKind::Radio && !a.voice.empty()) say(a.voice);
      if (a.kind == ActionKind::Cue) engine_->play({.sound = a.cue});
    }
  }
}

void AudioSession::check_level(const LevelDef& level) const {
  for (const EventDef& e : level.events.events)
    for (const ActionDef& a : e.actions) {
      if (a.kind == ActionKind::Radio && !a.voice.empty() && !radio_.lines.empty() && !radio_.find(a.voice))
        throw InputError(a.where + " is \"" + a.voice + "\", no line of assets/radio/lines.json; add it there " +
                         "(tools/radio/gen_radio.py speaks it) or name one of its ids");
      if (a.kind == ActionKind::Cue && std::find(sound_names_.begin(), sound_names_.end(), a.cue) == sound_names_.end())
        throw InputError(a.where + " is \"" + a.cue + "\", no sound of " + path_ + "; allowed: " + join_allowed(sound_names_));
    }
}

void AudioSession::frame(const World& w, double seconds) {
  const glm::dvec3 velocity = (w.camera.position - w.prev_camera.position) / std::max(w.dt, 1e-9);
  engine_->set_listener(w.camera.position, w.camera.orientation, velocity);
  // A frame without a tick (a display faster than the tick rate) keeps the loops of the last.
  if (!ticked_)
    for (const SoundEvent& e : events_)
      if (is_loop(e.kind)) engine_->play(sound_cue(e));
  ticked_ = false;
  engine_->set_music(menu_ ? "menu" : mood_);
  if (std::optional<RadioLine> line = radio_queue_.advance(seconds)) engine_->play({.sound = radio_sound_name(line->id)});
  engine_->update(seconds);
}

bool AudioSession::say(const std::string& id, bool urgent) {
  const RadioLine* line = radio_.find(id);
  if (!line) return false;
  radio_queue_.say(*line, urgent);
  return true;
}

std::optional<Subtitle> AudioSession::subtitle() const {
  return subtitles_ ? radio_queue_.subtitle() : std::nullopt;
}

void AudioSession::ui(const std::string& sound) { engine_->play({.sound = sound}); }

std::string AudioSession::reload() {
  try {
    SoundLibraryDef library = load_sound_library(path_);
    sound_names_.clear();
    for (const SoundDef& s : library.sounds) sound_names_.push_back(s.name);
    for (const SoundDef& s : radio_.sounds) library.sounds.push_back(s);
    engine_->load(library);
    return "";
  } catch (const InputError& e) {
    return e.what();
  }
}

AudioCapture::AudioCapture(const std::string& sounds_path, const Settings& settings, std::string wav_path)
    : session_(sounds_path, settings, true), wav_path_(std::move(wav_path)) {}

void AudioCapture::after_tick(const World& w) {
  session_.after_tick(w);
  session_.frame(w, w.dt);
  owed_ += w.dt * session_.engine().sample_rate();
  const int frames = int(std::floor(owed_));
  owed_ -= frames;
  const size_t at = samples_.size();
  samples_.resize(at + size_t(frames) * 2);
  session_.engine().render(samples_.data() + at, frames);
}

size_t AudioCapture::finish() {
  write_wav_stereo16(wav_path_, samples_, session_.engine().sample_rate());
  std::printf("arcfire: sound: %s (%.2f s)\n", wav_path_.c_str(),
              double(samples_.size() / 2) / session_.engine().sample_rate());
  return samples_.size() / 2;
}

}  // namespace arc
