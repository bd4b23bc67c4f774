// The sound file loads, every sound synthesises deterministically, and a bad file is one
// positioned line.
#include <gtest/gtest.h>

#include <cmath>

#include "audio/sound_library.h"
#include "audio/synth.h"
#include "core/error.h"
#include "core/data_root.h"

namespace arc {
namespace {

const std::string kSounds = arc::data_root() + "/assets/sounds/sounds.json";

std::string error_of(const std::string& text) {
  try {
    parse_sound_library(text, "sounds.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SoundLibrary, TheGameFileHasEverySound) {
  SoundLibraryDef lib = load_sound_library(kSounds);
  for (const char* name : {"beam", "beam_hit_shield", "beam_hit_hull", "shield_recharge", "missile_launch",
                           "missile_flight", "plasma_shot", "explosion", "afterburner", "engine_hum", "lock_tick", "lock_tone", "flare", "ui_click",
                           "victory", "defeat"})
    EXPECT_NE(lib.find(name), nullptr) << name;
}

TEST(SoundLibrary, SynthesisIsDeterministicAndBounded) {
  SoundLibraryDef lib = load_sound_library(kSounds);
  for (const SoundDef& s : lib.sounds) {
    std::vector<float> a = synthesise(s, 48000), b = synthesise(s, 48000);
    ASSERT_EQ(a, b) << s.name;
    float peak = 0;
    for (float v : a) peak = std::max(peak, std::abs(v));
    EXPECT_GT(peak, 0.5f) << s.name;
    EXPECT_LE(peak, 0.91f) << s.name;
    if (!s.loop) {
      EXPECT_EQ(a.back(), 0.0f) << s.name << ": a one-shot ends at zero";
    }
  }
}

// A loop's last sample flows into its first: the seam jump is no bigger than the sound's own.
TEST(SoundLibrary, LoopsHaveNoSeam) {
  SoundLibraryDef lib = load_sound_library(kSounds);
  for (const SoundDef& s : lib.sounds) {
    if (!s.loop) continue;
    std::vector<float> a = synthesise(s, 48000);
    float largest = 0;
    for (size_t i = 1; i < a.size(); ++i) largest = std::max(largest, std::abs(a[i] - a[i - 1]));
    EXPECT_LE(std::abs(a.front() - a.back()), largest * 1.01f) << s.name;
  }
}

TEST(SoundLibrary, BadFilesArePositionedErrors) {
  EXPECT_EQ(error_of("{\"sounds\": {\"x\": {\"layers\": [{\"freq\": -5}]}}}"),
            "sounds.json:1:39: 'sounds.x.layers[0].freq' must be in [10, 20000], got -5");
  EXPECT_NE(error_of("{\"sounds\": {\"x\": {\"layers\": [{\"sorce\": \"sine\"}]}}}").find("sounds.json:1:"), std::string::npos);
  EXPECT_NE(error_of("{\"sounds\": {\"x\": {\"layers\": [{\"sorce\": \"sine\"}]}}}").find("unknown key 'sorce'"),
            std::string::npos);
  EXPECT_NE(error_of("{\"sounds\": {\"x\": {\"layers\": [{\"source\": \"flute\"}]}}}").find("sine"), std::string::npos);
  EXPECT_NE(error_of("{\"sounds\": {\"x\": {\"loop\": true}}}").find("needs 'layers'"), std::string::npos);
  EXPECT_NE(error_of("{\"sounds\": {\"x\": {\"layers\": [{\"burst_period\": 0.1, \"burst_length\": 0.5}]}}}")
                .find("'sounds.x.layers[0].burst_length' must not be longer"),
            std::string::npos);
}

}  // namespace
}  // namespace arc
