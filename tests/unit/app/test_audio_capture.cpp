// The game's sound end to end, headless through OpenAL's loopback device: a beam on a shield
// is heard while it fires, the same session gives the same samples, the settings are listed.
#include <gtest/gtest.h>

#include <cmath>

#include "core/settings.h"
#include "game/app/all_settings.h"
#include "game/app/audio_session.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "test_helpers.h"
#include "core/data_root.h"

namespace arc {
namespace {

const std::string kSounds = arc::data_root() + "/assets/sounds/sounds.json";

Game shooter_and_drone() {
  const std::string ships = R"({ "name": "Shooter", "class": "viper", "team": "blue", "player": true },
    { "name": "Drone", "class": "viper", "team": "red", "ai": "none", "position": [0, 0, -200] })";
  Game g = Game::load_level(test::write_level("audio_beam.json", test::level_text(ships)), test::options());
  // No target, so no missile lock: its tick and tone would sound through the quiet second.
  g.world_mut().ships[0].target = {};
  return g;
}

// RMS of both channels in each 100 ms window.
std::vector<double> rms_windows(const std::vector<float>& stereo, int rate) {
  const size_t window = size_t(rate / 10) * 2;
  std::vector<double> out;
  for (size_t at = 0; at + window <= stereo.size(); at += window) {
    double sum = 0;
    for (size_t i = at; i < at + window; ++i) sum += double(stereo[i]) * stereo[i];
    out.push_back(std::sqrt(sum / double(window)));
  }
  return out;
}

// Effects only: no music, no radio.
Settings effects_only() {
  Settings s = all_settings();
  s.set_from_text("audio.music_volume=0", "--set");
  s.set_from_text("audio.voice_volume=0", "--set");
  return s;
}

// One second of quiet flight, two seconds of beam on the drone's shield, one second after.
std::vector<float> beam_session(const std::string& wav) {
  Game g = shooter_and_drone();
  AudioCapture capture(kSounds, effects_only(), wav);
  for (int t = 0; t < 240; ++t) {
    InputFrame f;
    if (t >= 60 && t < 180) f.buttons = kFirePrimary;
    g.step(f);
    capture.after_tick(g.world());
  }
  return capture.samples();
}

TEST(AudioCapture, ABeamOnAShieldIsHeardWhileItFires) {
  std::vector<float> s = beam_session(testing::TempDir() + "beam.wav");
  ASSERT_EQ(s.size(), size_t(240 * 800 * 2)) << "800 frames per 60 Hz tick at 48 kHz";
  std::vector<double> rms = rms_windows(s, 48000);
  double before = 0;
  for (int i = 2; i < 10; ++i) before = std::max(before, rms[size_t(i)]);
  for (int i = 11; i < 30; ++i) EXPECT_GT(rms[size_t(i)], 2.0 * before) << "window " << i << " while the beam fires";
  // Quiet again after the beam, before the shield's recharge rises from 3.5 s.
  EXPECT_LT(rms[33], 1.5 * before) << "quiet again after the beam";
}

TEST(AudioCapture, TheSameSessionGivesTheSameSamples) {
  EXPECT_EQ(beam_session(testing::TempDir() + "a.wav"), beam_session(testing::TempDir() + "b.wav"));
}

TEST(AudioCapture, SettingsAreListedAndMix) {
  Settings s = all_settings();
  for (const char* key : {"audio.volume", "audio.effects_volume", "audio.mute", "audio.voices"})
    EXPECT_NE(s.describe().find(key), std::string::npos) << key;
  s.set_from_text("audio.voices=8", "--set");
  s.set_from_text("audio.mute=on", "--set");
  const AudioMix m = audio_mix(s);
  EXPECT_EQ(m.voices, 8);
  EXPECT_TRUE(m.mute);
  EXPECT_THROW(s.set_from_text("audio.volume=2", "--set"), InputError);
}

TEST(AudioCapture, BigExplosionsAreLouderAndDeeper) {
  SoundEvent small, big;
  small.kind = big.kind = SoundKind::Explosion;
  small.size = 48;
  big.size = 300;
  EXPECT_GT(sound_cue(big).gain, sound_cue(small).gain);
  EXPECT_LT(sound_cue(big).pitch, sound_cue(small).pitch);
  EXPECT_EQ(sound_cue(big).sound, "explosion");
}

}  // namespace
}  // namespace arc
