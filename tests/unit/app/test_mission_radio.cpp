// The campaign's radio actions are spoken: every "voice" names a line of the radio manifest, a
// mission's opening line plays with its subtitle, two renders of the same ticks are the same
// samples, a bad voice or cue name stops the run with one positioned line, and cues play.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "audio/loudness.h"
#include "core/data_root.h"
#include "core/error.h"
#include "game/app/all_settings.h"
#include "game/app/audio_session.h"
#include "game/sim/game.h"
#include "game/sim/world.h"

namespace arc {
namespace {

const char* kMissions[] = {"02_patrol", "03_escort", "04_defend", "05_intercept", "06_ace", "07_strike", "08_fleet"};

Game load(const std::string& path) {
  GameOptions o;
  o.root_dir = data_root();
  return Game::load_level(path, o);
}

Game campaign_level(const std::string& stem) { return load(data_root() + "/levels/campaign/" + stem + ".json"); }

TEST(MissionRadio, EveryCampaignRadioLineHasAVoice) {
  AudioCapture capture(data_root() + "/assets/sounds/sounds.json", all_settings(), testing::TempDir() + "voices.wav");
  int radios = 0;
  for (const char* stem : kMissions) {
    Game game = campaign_level(stem);
    EXPECT_NO_THROW(capture.session().check_level(game.world().level)) << stem;
    for (const EventDef& e : game.world().level.events.events)
      for (const ActionDef& a : e.actions)
        if (a.kind == ActionKind::Radio) {
          ++radios;
          const RadioLine* line = capture.session().radio().find(a.voice);
          ASSERT_NE(line, nullptr) << stem << " event " << e.id << " has no voice";
          EXPECT_EQ(line->speaker + ": " + line->text, a.speaker + ": " + a.text) << "the subtitle says what the HUD says";
        }
  }
  EXPECT_GE(radios, 31);
}

// The patrol's first event (0 s) says its line: the voice plays, the subtitle shows, the render
// is the same each time.
std::vector<float> render_patrol_start(bool& heard, bool& shown, bool& stinger) {
  Game game = campaign_level("02_patrol");
  AudioCapture capture(data_root() + "/assets/sounds/sounds.json", all_settings(), testing::TempDir() + "patrol.wav");
  for (int t = 0; t < 60 * 4; ++t) {
    game.step(InputFrame{});
    capture.after_tick(game.world());
    for (const VoiceInfo& v : capture.session().engine().voices()) {
      heard = heard || v.sound == "radio/patrol_start";
      stinger = stinger || v.sound == "contact";
    }
    if (auto sub = capture.session().subtitle()) shown = shown || sub->speaker == "Control";
  }
  return capture.samples();
}

TEST(MissionRadio, AMissionSpeaksItsLineTheSameEachTime) {
  bool heard = false, shown = false, stinger = false;
  const std::vector<float> a = render_patrol_start(heard, shown, stinger);
  EXPECT_TRUE(heard);
  EXPECT_TRUE(shown);
  bool h2 = false, s2 = false, c2 = false;
  const std::vector<float> b = render_patrol_start(h2, s2, c2);
  EXPECT_TRUE(a == b) << "the same ticks give the same samples";
  std::printf("patrol start: peak %.2f dBFS, first 3 s %.1f dBFS RMS\n", peak_dbfs(a), rms_dbfs(a, 48000, 0.0, 3.0));
  EXPECT_GT(rms_dbfs(a, 48000, 0.1, 3.0), -30.0) << "the line is heard";
}

TEST(MissionRadio, ACueActionPlaysItsSound) {
  AudioCapture capture(data_root() + "/assets/sounds/sounds.json", all_settings(), testing::TempDir() + "cue.wav");
  Game game = campaign_level("02_patrol");
  LevelDef level = game.world().level;
  ActionDef cue;
  cue.kind = ActionKind::Cue;
  cue.cue = "ambush";
  cue.where = "test.json:1:1: 'events[0].do[0].name'";
  level.events.events.at(0).actions = {cue};
  EXPECT_NO_THROW(capture.session().check_level(level));
  level.events.events.at(0).actions[0].cue = "no_such_sound";
  try {
    capture.session().check_level(level);
    ADD_FAILURE() << "an unknown cue passed";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("test.json:1:1: 'events[0].do[0].name' is \"no_such_sound\""), std::string::npos) << m;
    EXPECT_NE(m.find("ambush"), std::string::npos) << "names the sounds allowed: " << m;
  }
}

// A level whose radio action names a line the manifest lacks: one line, the file and key path.
TEST(MissionRadio, AnUnknownVoiceIsOnePositionedLine) {
  std::ifstream in(data_root() + "/levels/campaign/02_patrol.json");
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const std::string good = "\"voice\": \"patrol_nav_alpha\"";
  ASSERT_NE(s.find(good), std::string::npos);
  s.replace(s.find(good), good.size(), "\"voice\": \"patrol_nav_alfa\"");
  const std::string path = testing::TempDir() + "zz_bad_voice_test.json";
  std::ofstream(path) << s;
  AudioCapture capture(data_root() + "/assets/sounds/sounds.json", all_settings(), testing::TempDir() + "bad.wav");
  Game game = load(path);
  try {
    capture.after_tick(game.world());
    game.step(InputFrame{});
    capture.after_tick(game.world());
    ADD_FAILURE() << "an unknown voice passed";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("zz_bad_voice_test.json:"), std::string::npos) << m;
    EXPECT_NE(m.find("'events[1].do[0].voice' is \"patrol_nav_alfa\""), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace arc
