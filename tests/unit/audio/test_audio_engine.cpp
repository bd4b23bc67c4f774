// The audio engine through OpenAL Soft's loopback device: no sound card needed. Sounds placed
// to the left are louder on the left, fall off with distance, shift pitch when they approach,
// the voice limit keeps the important ones, a taken voice fades without a click, and without a
// device everything is silent and safe.
#include <gtest/gtest.h>

#include <cmath>

#include "audio/audio_engine.h"

namespace arc {
namespace {

constexpr int kRate = 48000;
constexpr int kTick = 800;  // frames per 60 Hz tick

SoundLayerDef tone_layer(double freq, double attack, double decay) {
  SoundLayerDef l;
  l.source = SoundLayerDef::Source::Sine;
  l.freq_start = l.freq_end = freq;
  l.attack = attack;
  l.decay = decay;
  return l;
}

// Test sounds: a steady tone (looped), a burst, a high-priority boom with a slow attack.
SoundLibraryDef test_library() {
  SoundLibraryDef lib;
  lib.speed_of_sound = 1500;
  SoundDef tone{.name = "tone", .loop = true, .duration = 0.5, .priority = 10, .reference_distance = 10};
  tone.layers = {tone_layer(400, 0.01, 1)};
  SoundDef spark{.name = "spark", .duration = 2.0, .priority = 20, .reference_distance = 10};
  spark.layers = {tone_layer(600, 0.01, 1.9)};
  SoundDef boom{.name = "boom", .duration = 2.0, .priority = 90, .reference_distance = 10};
  boom.layers = {tone_layer(150, 0.1, 1.8)};
  lib.sounds = {tone, spark, boom};
  return lib;
}

struct Loopback {
  AudioEngine audio;
  explicit Loopback(int voices = 8) : audio(AudioDesc{.loopback = true, .sample_rate = kRate, .voices = voices}) {
    audio.load(test_library());
    audio.set_mix(AudioMix{.voices = voices});
  }
  // Renders `ticks` ticks, calling `each_tick` before each (cues for loops), interleaved stereo.
  template <class F>
  std::vector<float> run(int ticks, F each_tick) {
    std::vector<float> out(size_t(ticks) * kTick * 2);
    for (int t = 0; t < ticks; ++t) {
      each_tick(t);
      audio.update(1.0 / 60.0);
      audio.render(out.data() + size_t(t) * kTick * 2, kTick);
    }
    return out;
  }
  std::vector<float> run(int ticks) {
    return run(ticks, [](int) {});
  }
};

double rms(const std::vector<float>& s, int channel) {
  double sum = 0;
  for (size_t i = size_t(channel); i < s.size(); i += 2) sum += double(s[i]) * s[i];
  return std::sqrt(sum / double(s.size() / 2));
}

// Upward zero crossings per second of one channel.
double crossing_rate(const std::vector<float>& s, int channel) {
  int n = 0;
  for (size_t i = size_t(channel) + 2; i < s.size(); i += 2) n += s[i - 2] < 0 && s[i] >= 0;
  return double(n) / (double(s.size() / 2) / kRate);
}

float max_jump(const std::vector<float>& s, size_t from, size_t to) {
  float m = 0;
  for (size_t i = std::max<size_t>(from, 2); i < std::min(to, s.size()); ++i) m = std::max(m, std::abs(s[i] - s[i - 2]));
  return m;
}

TEST(AudioEngine, LoopbackOpens) {
  Loopback lb;
  ASSERT_TRUE(lb.audio.active()) << lb.audio.notice();
  EXPECT_EQ(lb.audio.sample_rate(), kRate);
}

// An explosion to the camera's left is louder in the left channel, and so it is 1e9 units out.
TEST(AudioEngine, SoundToTheLeftIsLouderOnTheLeft) {
  for (double origin : {0.0, 1e9}) {
    Loopback lb;
    const glm::dvec3 camera(origin, 0, origin);
    lb.audio.set_listener(camera, glm::dquat(1, 0, 0, 0), glm::dvec3(0));
    lb.audio.play({.sound = "boom", .position = camera + glm::dvec3(-30, 0, 0)});
    std::vector<float> s = lb.run(30);
    EXPECT_GT(rms(s, 0), 2.0 * rms(s, 1)) << "camera at " << origin;
    EXPECT_GT(rms(s, 0), 0.01);
  }
}

// The camera's orientation counts: turned 180° about up, the same world point is on the right.
TEST(AudioEngine, ListenerOrientationTurnsTheScene) {
  Loopback lb;
  lb.audio.set_listener(glm::dvec3(0), glm::angleAxis(M_PI, glm::dvec3(0, 1, 0)), glm::dvec3(0));
  lb.audio.play({.sound = "boom", .position = glm::dvec3(-30, 0, 0)});
  std::vector<float> s = lb.run(30);
  EXPECT_GT(rms(s, 1), 2.0 * rms(s, 0));
}

TEST(AudioEngine, FartherIsQuieter) {
  auto level_at = [](double distance) {
    Loopback lb;
    lb.audio.play({.sound = "boom", .position = glm::dvec3(0, 0, -distance)});
    std::vector<float> s = lb.run(30);
    return rms(s, 0) + rms(s, 1);
  };
  const double near = level_at(10), mid = level_at(40), far = level_at(400);
  EXPECT_GT(near, 3.0 * mid);  // inverse distance: 4x farther, about a quarter
  EXPECT_LT(near, 5.0 * mid);
  EXPECT_GT(mid, 5.0 * far);
}

// A missile flying at the camera sounds higher than one at rest, one flying away lower.
TEST(AudioEngine, DopplerShiftsAnApproachingSource) {
  auto rate_for = [](double speed) {
    Loopback lb;
    glm::dvec3 pos(0, 0, -400);
    const glm::dvec3 vel(0, 0, speed);
    return crossing_rate(lb.run(30, [&](int) {
                           lb.audio.play({.sound = "tone", .key = 1, .position = pos, .velocity = vel});
                           pos += vel / 60.0;
                         }),
                         0);
  };
  const double still = rate_for(0), closing = rate_for(300), leaving = rate_for(-300);
  EXPECT_NEAR(still, 400, 15);
  EXPECT_NEAR(closing / still, 1500.0 / (1500.0 - 300.0), 0.05);
  EXPECT_NEAR(leaving / still, 1500.0 / (1500.0 + 300.0), 0.05);
}

TEST(AudioEngine, VoiceLimitKeepsThePriorityOnes) {
  Loopback lb(3);
  for (int i = 0; i < 3; ++i) lb.audio.play({.sound = "spark", .position = glm::dvec3(i, 0, -10)});
  EXPECT_EQ(lb.audio.voice_count(), 3);
  lb.audio.play({.sound = "boom", .position = glm::dvec3(0, 0, -10)});
  EXPECT_EQ(lb.audio.voice_count(), 3);
  int booms = 0, fading = 0;
  for (const VoiceInfo& v : lb.audio.voices()) {
    booms += v.sound == "boom";
    fading += v.fading;
  }
  EXPECT_EQ(booms, 1);
  EXPECT_EQ(fading, 1);  // the taken spark fades out on a spare source
  lb.audio.play({.sound = "boom", .position = glm::dvec3(0, 0, -10)});
  lb.audio.play({.sound = "boom", .position = glm::dvec3(0, 0, -10)});
  lb.audio.play({.sound = "spark", .position = glm::dvec3(0, 0, -10)});  // pool of booms: a spark is dropped
  int sparks = 0;
  for (const VoiceInfo& v : lb.audio.voices()) sparks += v.sound == "spark" && !v.fading;
  EXPECT_EQ(sparks, 0);
  EXPECT_EQ(lb.audio.voice_count(), 3);
  lb.run(10);
  EXPECT_EQ(int(lb.audio.voices().size()), 3) << "fades end and free their sources";
}

// Loops of equal priority asked for every tick (engine hums) keep the voices they have rather
// than taking turns: nothing fades while the pool stays full.
TEST(AudioEngine, EqualLoopsDoNotTakeTurns) {
  Loopback lb(2);
  lb.run(20, [&](int) {
    for (uint64_t key = 1; key <= 4; ++key) lb.audio.play({.sound = "tone", .key = key, .position = glm::dvec3(0, 0, -5)});
    for (const VoiceInfo& v : lb.audio.voices()) EXPECT_FALSE(v.fading);
  });
  EXPECT_EQ(lb.audio.voice_count(), 2);
}

// A sound too far away to hear does not take a voice.
TEST(AudioEngine, InaudibleSoundsAreNotStarted) {
  Loopback lb;
  lb.audio.play({.sound = "boom", .position = glm::dvec3(0, 0, -1e7)});
  EXPECT_EQ(lb.audio.voice_count(), 0);
  lb.audio.play({.sound = "boom", .position = glm::dvec3(0, 0, -100)});
  EXPECT_EQ(lb.audio.voice_count(), 1);
}

// A loud tone's voice is taken by a slow-attack boom: the tone fades, it is not cut. The largest
// sample-to-sample step around the steal stays near the steady tone's own.
TEST(AudioEngine, AStolenVoiceFadesWithoutAClick) {
  Loopback lb(1);
  auto cue = [&](int t) {
    if (t < 20) lb.audio.play({.sound = "tone", .key = 7, .position = glm::dvec3(0, 0, -5)});
    if (t == 20) lb.audio.play({.sound = "boom", .position = glm::dvec3(0, 0, -5)});
  };
  std::vector<float> s = lb.run(40, cue);
  const size_t steal = size_t(20) * kTick * 2;
  const float steady = max_jump(s, steal - 8 * kTick * 2, steal);
  ASSERT_GT(steady, 0.01f);
  EXPECT_LE(max_jump(s, steal, steal + 10 * kTick * 2), steady * 1.2f);
}

// A loop the game stops asking for fades out instead of stopping dead.
TEST(AudioEngine, AnEndedLoopFadesOut) {
  Loopback lb;
  std::vector<float> s = lb.run(40, [&](int t) {
    if (t < 20) lb.audio.play({.sound = "tone", .key = 3, .position = glm::dvec3(0, 0, -5)});
  });
  const size_t end = size_t(20) * kTick * 2;
  const float steady = max_jump(s, end - 8 * kTick * 2, end);
  EXPECT_LE(max_jump(s, end, s.size()), steady * 1.2f);
  EXPECT_LT(rms(std::vector<float>(s.end() - kTick * 2, s.end()), 0), 1e-4);
  EXPECT_EQ(lb.audio.voice_count(), 0);
}

TEST(AudioEngine, MuteAndVolume) {
  Loopback lb;
  lb.audio.set_mix(AudioMix{.mute = true, .voices = 8});
  lb.audio.play({.sound = "boom", .position = glm::dvec3(0, 0, -10)});
  EXPECT_EQ(rms(lb.run(20), 0), 0.0);
}

TEST(AudioEngine, SameCuesGiveTheSameSamples) {
  auto once = [] {
    Loopback lb;
    return lb.run(30, [&](int t) {
      if (t % 7 == 0) lb.audio.play({.sound = "spark", .position = glm::dvec3(t - 15, 0, -20)});
      lb.audio.play({.sound = "tone", .key = 1, .position = glm::dvec3(10, 0, -20 + t)});
    });
  };
  EXPECT_EQ(once(), once());
}

// No device: one notice, every call harmless, silence.
TEST(AudioEngine, NoDeviceRunsSilently) {
  AudioEngine audio(AudioDesc{.device = "arcfire-no-such-device"});
  EXPECT_FALSE(audio.active());
  EXPECT_FALSE(audio.notice().empty());
  audio.load(test_library());
  audio.set_mix(AudioMix{.voices = 4});
  audio.set_listener(glm::dvec3(1e9), glm::dquat(1, 0, 0, 0), glm::dvec3(0));
  audio.play({.sound = "boom"});
  audio.update(0.1);
  std::vector<float> s(200, 1.0f);
  audio.render(s.data(), 100);
  for (float v : s) EXPECT_EQ(v, 0.0f);
  EXPECT_EQ(audio.voice_count(), 0);
}

}  // namespace
}  // namespace arc
