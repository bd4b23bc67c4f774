// The usage examples of engine/audio's header banners as tests (HeaderExamples.MatchTheirTests
// keeps each banner and its test the same text).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "audio/audio_engine.h"
#include "audio/sound_library.h"
#include "audio/synth.h"

namespace arc {
namespace {

TEST(AudioExamples, PlayAndRender) {
  const glm::dvec3 cam_pos{0.0}, cam_velocity{0.0}, p{0, 0, -50};
  const glm::dquat cam_orientation{1, 0, 0, 0};
  std::vector<float> stereo_frames(2 * 800);
  AudioDesc desc;  desc.loopback = true;                      // or the default device
  AudioEngine audio(desc);                                    // audio.notice() if it is silent
  audio.load(load_sound_library("assets/sounds/sounds.json"));
  audio.set_listener(cam_pos, cam_orientation, cam_velocity);
  audio.play({.sound = "explosion", .position = p, .gain = 1.0});
  audio.update(1.0 / 60.0);
  audio.render(stereo_frames.data(), 800);                     // loopback only
  if (!audio.notice().empty()) GTEST_SKIP() << "no loopback device: " << audio.notice();
  float loudest = 0;
  for (float s : stereo_frames) loudest = std::max(loudest, std::abs(s));
  EXPECT_GT(loudest, 0.0f);
}

TEST(AudioExamples, SynthesiseOne) {
  SoundLibraryDef lib = load_sound_library("assets/sounds/sounds.json");
  std::vector<float> boom = synthesise(*lib.find("explosion"), 48000);   // audio/synth.h
  EXPECT_FALSE(boom.empty());
}

}  // namespace
}  // namespace arc
