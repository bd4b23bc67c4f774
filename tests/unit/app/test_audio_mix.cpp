// The mix a player hears, measured on rendered sound (sample-exact: the audio is deterministic):
// the arena replay and a recorded duel peak at most −1 dBFS and sit near −16 LUFS; a kill, a hit
// on the player, a missile warning and a radio line rise 6 dB over the second before them; menus and results
// have music with no stretch of silence over 2 s; mood changes land on the beat.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>

#include "audio/loudness.h"
#include "core/data_root.h"
#include "game/app/all_settings.h"
#include "game/app/audio_session.h"
#include "game/app/script_feeder.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "replay/script.h"

namespace arc {
namespace {

struct Render {
  std::vector<float> samples;
  int rate = 48000;
  std::multimap<std::string, double> cues;  // sound name → onset in seconds
  std::vector<std::pair<double, std::string>> music;  // piece changes
  std::vector<std::pair<double, std::string>> lines;  // radio lines, by their subtitles
};

// Plays a replay script's input (no checks) with its sound captured; `extra_ticks` run on after
// its end with no input (the results screen).
Render render_script(const std::string& script_rel, Settings settings, uint64_t extra_ticks = 0,
                     const std::function<void(AudioSession&, uint64_t)>& at_tick = {}) {
  const std::string root = data_root();
  const replay::Script script = replay::load_script(root + "/" + script_rel, all_settings());
  settings = script_settings(script, settings, root);
  GameOptions base;
  base.root_dir = root;
  Game game = Game::load_level(resolve_script_level(script, root), script_game_options(script, settings, base));
  const std::string stem = script_rel.substr(script_rel.find_last_of('/') + 1);
  AudioCapture capture(root + "/assets/sounds/sounds.json", settings, testing::TempDir() + "mix_" + stem + ".wav");
  ScriptFeeder feed(script);
  Render r;
  std::string piece;
  const double lag = 0.002;  // the limiter's look-ahead
  for (uint64_t t = 0; t < script.last_tick() + extra_ticks; ++t) {
    if (t < script.last_tick()) feed.step(game, t);
    else game.step(InputFrame{});
    const double now = double(capture.samples().size() / 2) / r.rate + lag;
    if (at_tick) at_tick(capture.session(), t);
    capture.after_tick(game.world());
    for (const SoundEvent& e : capture.session().last_events()) r.cues.emplace(sound_kind_name(e.kind), now);
    const std::optional<Subtitle> sub = capture.session().subtitle();
    if (sub && (r.lines.empty() || r.lines.back().second != sub->text)) r.lines.emplace_back(now, sub->text);
    if (capture.session().engine().music() != piece) {
      piece = capture.session().engine().music();
      r.music.emplace_back(now, piece);
    }
  }
  r.samples = capture.samples();
  capture.finish();  // the WAV stays in the test's temporary folder to listen to
  return r;
}

double first_cue(const Render& r, const std::string& name, double after = 1.5) {
  for (auto [it, end] = r.cues.equal_range(name); it != end; ++it)
    if (it->second >= after) return it->second;
  return -1;
}

void print_figures(const char* what, const Render& r) {
  std::printf("%s: peak %.2f dBFS, loudness %.2f LUFS\n", what, peak_dbfs(r.samples), integrated_lufs(r.samples, r.rate));
  for (const char* cue : {"kill_confirm", "player_hit", "missile_warning"})
    if (double t = first_cue(r, cue); t > 0)
      std::printf("  %s at %.2f s: rise %+.1f dB\n", cue, t, cue_rise_db(r.samples, r.rate, t));
  for (const auto& [t, piece] : r.music) std::printf("  music %s from %.2f s\n", piece.c_str(), t);
  for (const auto& [t, text] : r.lines) std::printf("  radio \"%s\" at %.2f s\n", text.c_str(), t);
}

TEST(AudioMix, ArenaPeakAndLoudness) {
  const Render r = render_script("tests/replays/arena.replay", all_settings());
  print_figures("arena", r);
  EXPECT_LE(peak_dbfs(r.samples), -1.0);
  EXPECT_NEAR(integrated_lufs(r.samples, r.rate), -16.0, 2.0);
}

// A mission's radio line in the thick of the arena (8 s in, every beam firing).
TEST(AudioMix, ARadioLineStandsOutInTheArena) {
  const uint64_t at = 8 * 60;
  const Render r = render_script("tests/replays/arena.replay", all_settings(), 0, [&](AudioSession& a, uint64_t t) {
    if (t == at) a.say("objective_done");
  });
  const double t = double(at) / 60.0 + 0.002;  // the tick's samples start there, behind the look-ahead
  const double rise = cue_rise_db(r.samples, r.rate, t, 0.5);
  print_figures("arena with a radio line", r);
  std::printf("arena radio line at %.2f s: rise %+.1f dB over 0.5 s\n", t, rise);
  // Levelled speech (RMS within about 10 dB of its peak) over a fight ducked 15 dB (docs/audio.md).
  EXPECT_GE(rise, 6.0);
  EXPECT_LE(peak_dbfs(r.samples), -1.0);
}

TEST(AudioMix, DuelCuesStandOut) {
  const Render r = render_script("tests/audio/duel.replay", all_settings());
  print_figures("duel", r);
  EXPECT_LE(peak_dbfs(r.samples), -1.0);
  EXPECT_NEAR(integrated_lufs(r.samples, r.rate), -16.0, 2.0);
  for (const char* cue : {"player_hit", "missile_warning"}) {
    const double t = first_cue(r, cue);
    ASSERT_GT(t, 0) << cue << " never sounded in the duel";
    EXPECT_GE(cue_rise_db(r.samples, r.rate, t), 6.0) << cue << " at " << t << " s";
  }
}

TEST(AudioMix, AKillStandsOut) {
  const Render r = render_script("tests/replays/range_kill_explosion.replay", all_settings());
  print_figures("range kill", r);
  const double t = first_cue(r, "kill_confirm");
  ASSERT_GT(t, 0) << "the player's kill was not heard";
  EXPECT_GE(cue_rise_db(r.samples, r.rate, t), 6.0);
  EXPECT_LE(peak_dbfs(r.samples), -1.0);
}

// The attract demo behind the title menu plays the menu theme: no silence over 2 s.
TEST(AudioMix, TheMenuHasMusic) {
  Game game = Game::load_level(data_root() + "/levels/attract.json", GameOptions{});
  AudioCapture capture(data_root() + "/assets/sounds/sounds.json", all_settings(), testing::TempDir() + "menu.wav");
  capture.session().set_menu(true);
  for (int t = 0; t < 60 * 30; ++t) {
    game.step(InputFrame{});
    capture.after_tick(game.world());
  }
  EXPECT_EQ(capture.session().engine().music(), "menu");
  const SilenceFigures s = silence(capture.samples(), 48000);
  std::printf("menu: silence %.1f %%, longest %.1f s, loudness %.2f LUFS, peak %.2f dBFS\n", 100 * s.share, s.longest,
              integrated_lufs(capture.samples(), 48000), peak_dbfs(capture.samples()));
  EXPECT_LT(s.longest, 2.0);
  EXPECT_LE(peak_dbfs(capture.samples()), -1.0);
}

// After the kill wins the range: the victory stinger, then the menu theme under the results.
TEST(AudioMix, TheResultsHaveMusic) {
  const Render r = render_script("tests/replays/range_kill_explosion.replay", all_settings(), 60 * 30);
  double won = -1;
  for (const auto& [t, piece] : r.music)
    if (piece == "victory") won = t;
  ASSERT_GT(won, 0);
  EXPECT_EQ(r.music.back().second, "menu") << "the stinger hands over to the menu theme";
  const std::vector<float> after(r.samples.begin() + std::ptrdiff_t(won * r.rate) * 2, r.samples.end());
  const SilenceFigures s = silence(after, r.rate);
  std::printf("results: silence %.1f %%, longest %.1f s over %.1f s\n", 100 * s.share, s.longest, double(after.size() / 2) / r.rate);
  EXPECT_LT(s.longest, 2.0);
}

// Changes of mood between the mission's layers fall within a tick after a beat of the set.
TEST(AudioMix, MoodsChangeOnTheBeat) {
  const Render r = render_script("tests/audio/duel.replay", all_settings());
  const double beat = 60.0 / 112.0, tick = 1.0 / 60.0;
  ASSERT_GE(r.music.size(), 3u) << "the duel moves between calm, tension and combat";
  const double start = r.music.front().first;
  for (size_t i = 1; i < r.music.size(); ++i) {
    const double since = r.music[i].first - start;
    const double past = since - std::floor(since / beat + 1e-9) * beat;
    EXPECT_LE(past, tick + 1e-6) << r.music[i].second << " at " << r.music[i].first << " s";
  }
}

TEST(AudioMix, ARadioLineSpeaksWithASubtitle) {
  Game game = Game::load_level(data_root() + "/levels/attract.json", GameOptions{});
  AudioCapture capture(data_root() + "/assets/sounds/sounds.json", all_settings(), testing::TempDir() + "radio.wav");
  EXPECT_FALSE(capture.session().say("no_such_line"));
  ASSERT_TRUE(capture.session().say("objective_done"));
  bool heard = false, shown = false;
  for (int t = 0; t < 30; ++t) {
    game.step(InputFrame{});
    capture.after_tick(game.world());
    for (const VoiceInfo& v : capture.session().engine().voices()) heard = heard || v.sound == "radio/objective_done";
    if (auto sub = capture.session().subtitle()) shown = shown || sub->text == "Objective complete.";
  }
  EXPECT_TRUE(heard);
  EXPECT_TRUE(shown);
  EXPECT_GT(capture.session().engine().duck_db(), 0) << "the fight ducks under the voice";
}

}  // namespace
}  // namespace arc
