// The master bus and the music data: the limiter never lets a sample past its ceiling and
// leaves quiet sound alone; the loudness meter reads BS.1770's reference tone right; ducking
// holds then releases; music files are checked with positioned errors, notes are named right,
// and a looping piece renders to exactly its bars at its tempo.
#include <gtest/gtest.h>

#include <cmath>

#include "audio/adpcm.h"
#include "audio/loudness.h"
#include "audio/mix_bus.h"
#include "audio/music_def.h"
#include "audio/sequencer.h"
#include "core/data_root.h"
#include "core/error.h"

namespace arc {
namespace {

std::vector<float> sine(double amplitude, double hz, double seconds, int rate = 48000) {
  std::vector<float> s(size_t(seconds * rate) * 2);
  for (size_t i = 0; i < s.size() / 2; ++i)
    s[2 * i] = s[2 * i + 1] = float(amplitude * std::sin(2 * 3.14159265358979 * hz * double(i) / rate));
  return s;
}

TEST(MixBus, TheLimiterHoldsItsCeiling) {
  Limiter lim(48000, -1.0, 0.25);
  std::vector<float> s = sine(2.0, 220, 1.0);
  for (size_t i = 0; i < s.size(); i += 2 * 800) lim.process(s.data() + i, 800);
  EXPECT_LE(peak_dbfs(s), -1.0);
  EXPECT_GT(peak_dbfs(s), -1.5) << "limited to the ceiling, not far under it";
}

TEST(MixBus, TheLimiterLeavesQuietSoundAlone) {
  Limiter lim(48000, -1.0, 0.25);
  const std::vector<float> in = sine(0.5, 440, 0.5);
  std::vector<float> out = in;
  lim.process(out.data(), int(out.size() / 2));
  const size_t lag = size_t(lim.lookahead()) * 2;
  for (size_t i = lag; i < out.size(); ++i) ASSERT_FLOAT_EQ(out[i], in[i - lag]) << i;
}

TEST(MixBus, LoudnessOfTheReferenceTone) {
  // BS.1770: a 1 kHz sine at −20 dBFS in both channels reads −20 LUFS (K-weighting is ~0 dB there).
  const std::vector<float> s = sine(0.1, 1000, 5.0);
  EXPECT_NEAR(integrated_lufs(s, 48000), -20.0 + 20 * std::log10(std::sqrt(2.0)) - 3.01 + 0.0, 0.3);
  EXPECT_NEAR(peak_dbfs(s), -20.0, 0.01);
  EXPECT_LT(integrated_lufs(std::vector<float>(96000, 0.0f), 48000), -100) << "silence";
}

TEST(MixBus, DuckingHoldsThenReleases) {
  Ducker d;
  d.trigger(12, 0.5, 0.5);
  d.advance(0.4);
  EXPECT_DOUBLE_EQ(d.depth_db(), 12);
  d.advance(0.35);  // 0.1 s of hold left, then 0.25 s of release: half way
  EXPECT_NEAR(d.depth_db(), 6, 1e-9);
  d.advance(1.0);
  EXPECT_DOUBLE_EQ(d.gain(), 1.0);
}

TEST(MusicLibrary, NotesAreNamedLikeScores) {
  EXPECT_EQ(parse_note_name("A4"), 69);
  EXPECT_EQ(parse_note_name("C4"), 60);
  EXPECT_EQ(parse_note_name("C#3"), 49);
  EXPECT_EQ(parse_note_name("Eb2"), 39);
  EXPECT_EQ(parse_note_name("H2"), -1);
  EXPECT_EQ(parse_note_name("A"), -1);
}

TEST(MusicLibrary, TheGameFileLoadsAndLoopsRenderToTheirBars) {
  const MusicLibraryDef lib = load_music_library(data_root() + "/assets/music/music.json");
  for (const char* name : {"menu", "calm", "tension", "combat", "victory", "defeat"}) ASSERT_TRUE(lib.find(name)) << name;
  const MusicPieceDef& calm = *lib.find("calm");
  const std::vector<float> s = render_piece(lib, calm, 48000);
  EXPECT_EQ(s.size() / 2, size_t(std::llround(calm.seconds() * 48000)));
  EXPECT_LT(peak_dbfs(s), 0.0);
  EXPECT_NEAR(rms_dbfs(s, 48000, 0, calm.seconds()), 20 * std::log10(kMusicRms * calm.gain), 0.5);
  EXPECT_EQ(render_piece(lib, calm, 48000), s) << "deterministic";
}

std::string bad_music(const std::string& piece_body) {
  const std::string text = R"({ "instruments": { "pad": { "wave": "saw" } }, "pieces": {
  "menu": )" + piece_body + R"(,
  "calm": { "tracks": [ { "instrument": "pad", "pattern": "A3" } ] },
  "tension": { "tracks": [ { "instrument": "pad", "pattern": "A3" } ] },
  "combat": { "tracks": [ { "instrument": "pad", "pattern": "A3" } ] },
  "victory": { "loop": false, "then": "calm", "tracks": [ { "instrument": "pad", "pattern": "A3" } ] },
  "defeat": { "loop": false, "then": "calm", "tracks": [ { "instrument": "pad", "pattern": "A3" } ] } } })";
  try {
    parse_music_library(text, "m.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MusicLibrary, BadFilesArePositionedErrors) {
  EXPECT_EQ(bad_music(R"({ "tracks": [ { "instrument": "pad", "pattern": "A3" } ] })"), "");
  EXPECT_NE(bad_music(R"({ "tracks": [ { "instrument": "pad", "pattern": "A3 X9" } ] })").find("m.json:2:"), std::string::npos);
  EXPECT_NE(bad_music(R"({ "tracks": [ { "instrument": "pad", "pattern": "A3 X9" } ] })").find("'X9' is not a step"),
            std::string::npos);
  EXPECT_NE(bad_music(R"({ "tracks": [ { "instrument": "lute", "pattern": "A3" } ] })").find("allowed: pad"), std::string::npos);
  EXPECT_NE(bad_music(R"({ "tracks": [ { "instrument": "pad", "pattern": "A3 B3 C4" } ] })").find("must divide"),
            std::string::npos);
  EXPECT_NE(bad_music(R"({ "tracks": [ { "instrument": "pad", "pattern": "- A3" } ] })").find("no note sounds"),
            std::string::npos);
}

TEST(Adpcm, TheRadioLinesDecode) {
  const DecodedAudio a = load_ima_adpcm_wav(data_root() + "/assets/radio/kill_1.wav");
  EXPECT_EQ(a.sample_rate, 8000);
  EXPECT_GT(a.samples.size(), size_t(4000));
  int peak = 0;
  for (int16_t s : a.samples) peak = std::max(peak, std::abs(int(s)));
  EXPECT_GT(peak, 16000) << "speech near full scale";
  EXPECT_THROW(decode_ima_adpcm_wav("RIFF....WAVEjunk", "x.wav"), InputError);
}

}  // namespace
}  // namespace arc
