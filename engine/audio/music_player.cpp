#include "audio/music_player.h"

#include <AL/al.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <future>

#include "audio/sequencer.h"

namespace arc {

MusicPlayer::~MusicPlayer() { clear(); }

void MusicPlayer::clear() {
  for (Slot& s : slots_) {
    alSourceStop(s.source);
    alSourcei(s.source, AL_BUFFER, 0);
    alDeleteSources(1, &s.source);
    alDeleteBuffers(1, &s.buffer);
  }
  slots_.clear();
  requested_ = target_ = current_ = -1;
}

void MusicPlayer::load(const MusicLibraryDef& lib, int rate) {
  clear();
  lib_ = lib;
  slots_.resize(lib.pieces.size());
  // Pieces are independent: rendered on threads, uploaded in order (the samples do not depend on it).
  std::vector<std::future<std::vector<float>>> rendered;
  for (const MusicPieceDef& p : lib.pieces)
    rendered.push_back(std::async(std::launch::async, [&lib, &p, rate] { return render_piece(lib, p, rate); }));
  for (size_t i = 0; i < lib.pieces.size(); ++i) {
    Slot& s = slots_[i];
    const std::vector<float> f = rendered[i].get();
    std::vector<int16_t> pcm(f.size());
    for (size_t k = 0; k < f.size(); ++k) pcm[k] = int16_t(std::lround(std::clamp(f[k], -1.0f, 1.0f) * 32767.0f));
    alGenBuffers(1, &s.buffer);
    alBufferData(s.buffer, AL_FORMAT_STEREO16, pcm.data(), ALsizei(pcm.size() * 2), rate);
    alGenSources(1, &s.source);
    alSourcei(s.source, AL_BUFFER, ALint(s.buffer));
    alSourcei(s.source, AL_SOURCE_RELATIVE, AL_TRUE);
    alSourcef(s.source, AL_ROLLOFF_FACTOR, 0.0f);
    alSourcei(s.source, AL_LOOPING, lib.pieces[i].loop ? AL_TRUE : AL_FALSE);
    alSourcef(s.source, AL_GAIN, 0.0f);
  }
}

double MusicPlayer::seconds_in(int piece) const {
  ALint offset = 0, freq = 48000, buffer = 0;
  alGetSourcei(slots_[size_t(piece)].source, AL_SAMPLE_OFFSET, &offset);
  alGetSourcei(slots_[size_t(piece)].source, AL_BUFFER, &buffer);
  if (buffer) alGetBufferi(ALuint(buffer), AL_FREQUENCY, &freq);
  return double(offset) / std::max(freq, 1);
}

int MusicPlayer::beat_of(int piece) const {
  return int(std::floor(seconds_in(piece) / lib_.pieces[size_t(piece)].beat_seconds()));
}

void MusicPlayer::request(const std::string& name) {
  int want = -1;
  for (size_t i = 0; i < lib_.pieces.size(); ++i)
    if (lib_.pieces[i].name == name) want = int(i);
  if (want == requested_ || slots_.empty()) return;
  requested_ = target_ = want;
  request_beat_ = current_ >= 0 && slots_[size_t(current_)].running ? beat_of(current_) : 0;
}

// Every piece of `piece`'s set (or the piece alone) starts at once from its first sample.
void MusicPlayer::start_set(int piece) {
  const std::string& set = lib_.pieces[size_t(piece)].set;
  std::vector<ALuint> sources;
  for (size_t i = 0; i < slots_.size(); ++i) {
    if (int(i) != piece && (set.empty() || lib_.pieces[i].set != set)) continue;
    Slot& s = slots_[i];
    if (s.running) continue;
    alSourceStop(s.source);
    alSourceRewind(s.source);
    s.running = true;
    s.level = 0;
    s.target = 0;
    sources.push_back(s.source);
  }
  if (!sources.empty()) alSourcePlayv(ALsizei(sources.size()), sources.data());
}

void MusicPlayer::switch_to(int piece) {
  const double fade_s = current_ >= 0 ? lib_.crossfade_beats * lib_.pieces[size_t(current_)].beat_seconds() : 0.05;
  for (Slot& s : slots_) {
    s.target = 0;
    s.rate = 1.0 / std::max(fade_s, 0.01);
  }
  // A one-shot's tail rings out at full level under what follows.
  if (current_ >= 0 && !lib_.pieces[size_t(current_)].loop) slots_[size_t(current_)].target = 1;
  current_ = piece;
  if (piece < 0) return;
  const MusicPieceDef& p = lib_.pieces[size_t(piece)];
  Slot& s = slots_[size_t(piece)];
  if (!p.loop) {  // a stinger starts afresh at full level
    alSourceStop(s.source);
    s.running = false;
  }
  const bool fresh = !s.running;
  start_set(piece);
  s.target = 1;
  s.rate = 1.0 / std::max(fade_s, 0.01);
  if (fresh && !p.loop) s.level = 1.0;
}

void MusicPlayer::update(double seconds, double gain) {
  if (slots_.empty()) return;
  // A stinger whose notes have ended hands over to the piece it names.
  if (current_ >= 0) {
    const MusicPieceDef& p = lib_.pieces[size_t(current_)];
    if (!p.loop && target_ == current_ && seconds_in(current_) >= p.seconds() - 1e-9) {
      for (size_t i = 0; i < lib_.pieces.size(); ++i)
        if (lib_.pieces[i].name == p.then) target_ = int(i);
      switch_to(target_);
    }
  }
  if (target_ != current_) {
    const bool idle = current_ < 0 || !slots_[size_t(current_)].running;
    if (idle || beat_of(current_) != request_beat_) switch_to(target_);
  }
  for (size_t i = 0; i < slots_.size(); ++i) {
    Slot& s = slots_[i];
    if (!s.running) continue;
    const double step = s.rate * seconds;
    s.level = s.level < s.target ? std::min(s.target, s.level + step) : std::max(s.target, s.level - step);
    ALint state = AL_PLAYING;
    alGetSourcei(s.source, AL_SOURCE_STATE, &state);
    if (state == AL_STOPPED) s.running = false;
    alSourcef(s.source, AL_GAIN, float(std::max(0.0, gain * s.level)));
  }
  // A set no longer heard stops, so its sources cost nothing; it restarts in sync when wanted.
  for (size_t i = 0; i < slots_.size(); ++i) {
    const std::string& set = lib_.pieces[i].set;
    bool heard = false;
    for (size_t j = 0; j < slots_.size(); ++j)
      if ((j == i || (!set.empty() && lib_.pieces[j].set == set)) && (slots_[j].level > 0 || slots_[j].target > 0))
        heard = true;
    if (!heard && slots_[i].running) {
      alSourceStop(slots_[i].source);
      slots_[i].running = false;
    }
  }
}

std::string MusicPlayer::playing() const { return current_ >= 0 ? lib_.pieces[size_t(current_)].name : ""; }

}  // namespace arc
