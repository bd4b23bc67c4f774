// Parser: every line kind, and a positioned error for every kind of malformed line.
#include <gtest/gtest.h>

#include "core/error.h"
#include "game/app/all_settings.h"
#include "replay/script.h"

using namespace arc::replay;

namespace {

// Every setting the game knows: what a `set` line may name.
const arc::Settings& known() {
  static const arc::Settings settings = arc::all_settings();
  return settings;
}

const char* kGood = R"(# A hand-written script using every line kind.
arcfire-replay 1
level levels/duel.json
seed 1101
tick_rate 60
difficulty hard
build "0.1.0 release"
snapshot_size 320 180
particle_budget 50000
lightning_interval 4
substeps 2

0 axis throttle 1          # full ahead
0 press fire_primary
+30 release fire_primary
30 axis pitch -0.5
45 command target_nearest
45 command pause
50 command resume
60 expect alive Player
60 expect destroyed "Red Leader"
60 expect hull Player 50..100
60 expect shield "Red Leader" 0..0
60 expect position Player -10..10 -5.5..5.5 -1e3..0
60 expect distance Player "Red Leader" 100..2000
60 expect particles 0..100000
60 expect winner none
60 snapshot first-contact_1
60 hash 00000000deadbeef
60 full_hash ?
120 end
)";

std::string error_of(const std::string& text) {
  try {
    parse_script(text, "s.replay", known());
  } catch (const arc::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

const std::string kHead = "arcfire-replay 1\nlevel levels/duel.json\n";
const std::string kMatch = "arcfire-replay 2\nlevel levels/duel.json\n";

}  // namespace

TEST(ReplayParse, EveryLineKind) {
  Script s = parse_script(kGood, "good.replay", known());
  EXPECT_EQ(s.header.level, "levels/duel.json");
  EXPECT_EQ(s.header.seed, 1101u);
  EXPECT_EQ(s.header.tick_rate, 60);
  EXPECT_EQ(s.header.difficulty, "hard");
  EXPECT_EQ(s.header.build, "0.1.0 release");
  EXPECT_EQ(s.header.snapshot_width, 320);
  EXPECT_EQ(s.header.snapshot_height, 180);
  EXPECT_EQ(s.header.particle_budget, 50000u);
  EXPECT_EQ(s.header.lightning_interval, 4);
  EXPECT_EQ(s.header.substeps, 2);
  ASSERT_EQ(s.inputs.size(), 4u);
  EXPECT_EQ(s.inputs[0].kind, InputEvent::Kind::Axis);
  EXPECT_EQ(s.inputs[0].axis, Axis::Throttle);
  EXPECT_EQ(s.inputs[0].value, 127);
  EXPECT_EQ(s.inputs[1].kind, InputEvent::Kind::Press);
  EXPECT_EQ(s.inputs[1].button, kFirePrimary);
  EXPECT_EQ(s.inputs[2].tick, 30u);  // +30 after tick 0
  EXPECT_EQ(s.inputs[2].kind, InputEvent::Kind::Release);
  EXPECT_EQ(s.inputs[3].value, -64);  // -0.5 * 127 = -63.5 rounds away from zero
  EXPECT_EQ(s.inputs[3].src.line, 16);
  ASSERT_EQ(s.commands.size(), 3u);
  EXPECT_EQ(s.commands[0].command, ScriptCommand::TargetNearest);
  EXPECT_EQ(s.commands[1].command, ScriptCommand::Pause);
  EXPECT_EQ(s.commands[2].command, ScriptCommand::Resume);
  ASSERT_EQ(s.expectations.size(), 8u);
  EXPECT_EQ(s.expectations[1].kind, Expectation::Kind::Destroyed);
  EXPECT_EQ(s.expectations[1].ship, "Red Leader");
  EXPECT_EQ(s.expectations[2].range, (Range{50, 100}));
  EXPECT_EQ(s.expectations[4].box[1], (Range{-5.5, 5.5}));
  EXPECT_EQ(s.expectations[4].box[2], (Range{-1000, 0}));
  EXPECT_EQ(s.expectations[5].other, "Red Leader");
  EXPECT_EQ(s.expectations[7].team, "none");
  ASSERT_EQ(s.snapshots.size(), 1u);
  EXPECT_EQ(s.snapshots[0].name, "first-contact_1");
  ASSERT_EQ(s.hashes.size(), 2u);
  EXPECT_EQ(s.hashes[0].value, 0xdeadbeefu);
  EXPECT_FALSE(s.hashes[0].full);
  EXPECT_TRUE(s.hashes[1].full);
  EXPECT_FALSE(s.hashes[1].value.has_value());
  EXPECT_EQ(s.end_tick, 120u);
  EXPECT_EQ(s.last_tick(), 120u);
}

TEST(ReplayParse, SettingsToleranceAndSnapshotsLike) {
  Script s = parse_script(kHead +
                              "quality high\n"
                              "set render.soft_edges=contrast   # any --set key\n"
                              "  set render.scale=0.5\n"
                              "tolerance 3/255 99.5%\n"
                              "snapshots_like gallery-near_1\n"
                              "5 end\n",
                          "s.replay", known());
  ASSERT_TRUE(s.header.quality.has_value());
  EXPECT_EQ(s.header.quality->preset, "high");
  EXPECT_EQ(s.header.quality->line, 3);
  EXPECT_EQ(s.header.quality->col, 9);
  ASSERT_EQ(s.header.settings.size(), 2u);
  EXPECT_EQ(s.header.settings[0].key, "render.soft_edges");
  EXPECT_EQ(s.header.settings[0].value, "contrast");
  EXPECT_EQ(s.header.settings[1].key, "render.scale");
  EXPECT_EQ(s.header.settings[1].value, "0.5");
  EXPECT_EQ(s.header.settings[1].line, 5);
  EXPECT_EQ(s.header.settings[1].col, 20);  // the value, where a bad one would be reported
  ASSERT_TRUE(s.header.tolerance.has_value());
  EXPECT_EQ(s.header.tolerance->max_channel_diff, 3);
  EXPECT_EQ(s.header.tolerance->min_percent, 99.5);
  EXPECT_EQ(s.header.snapshots_like, "gallery-near_1");
}

// Mods in the order they were laid, each with its content hash.
TEST(ReplayParse, ModLines) {
  Script s = parse_script(kHead + "mod red_rally 00000000000000ff\nmod big-ships fedcba9876543210\n5 end\n", "s.replay", known());
  ASSERT_EQ(s.header.mods.size(), 2u);
  EXPECT_EQ(s.header.mods[0].name, "red_rally");
  EXPECT_EQ(s.header.mods[0].hash, 0xffu);
  EXPECT_EQ(s.header.mods[1].name, "big-ships");
  EXPECT_EQ(s.header.mods[1].hash, 0xfedcba9876543210ull);
  EXPECT_EQ(s.header.mods[1].line, 4);
}

// The combat counters' expectations: kills as one number or a range, damage, accuracy per weapon.
TEST(ReplayParse, CounterExpectations) {
  Script s = parse_script(kHead +
                              "60 expect kills Player 1\n60 expect kills Player 0..2\n"
                              "60 expect damage_dealt Player 100..400\n60 expect damage_taken \"Red Leader\" 0..50\n"
                              "60 expect accuracy Player beam 0.2..0.9\n"
                              "60 expect accuracy Player missile 0..1\n60 end\n",
                          "c.replay", known());
  ASSERT_EQ(s.expectations.size(), 6u);
  EXPECT_EQ(s.expectations[0].kind, Expectation::Kind::Kills);
  EXPECT_EQ(s.expectations[0].range, (Range{1, 1}));
  EXPECT_EQ(s.expectations[1].range, (Range{0, 2}));
  EXPECT_EQ(s.expectations[2].kind, Expectation::Kind::DamageDealt);
  EXPECT_EQ(s.expectations[3].kind, Expectation::Kind::DamageTaken);
  EXPECT_EQ(s.expectations[3].ship, "Red Leader");
  EXPECT_EQ(s.expectations[4].kind, Expectation::Kind::Accuracy);
  EXPECT_EQ(s.expectations[4].weapon, "beam");
  EXPECT_EQ(s.expectations[4].range, (Range{0.2, 0.9}));
  EXPECT_EQ(s.expectations[5].weapon, "missile");
}

TEST(ReplayParse, MissingEndRunsToTheLastStampedTick) {
  Script s = parse_script(kHead + "10 press afterburner\n250 hash 1\n", "cut.replay", known());
  EXPECT_FALSE(s.end_tick.has_value());
  EXPECT_EQ(s.last_tick(), 250u);
}

TEST(ReplayParse, DefaultsWhenHeaderIsMinimal) {
  Script s = parse_script(kHead + "5 end\n", "m.replay", known());
  EXPECT_FALSE(s.header.seed.has_value());
  EXPECT_FALSE(s.header.tick_rate.has_value());
  EXPECT_FALSE(s.header.difficulty.has_value());
  EXPECT_EQ(s.header.snapshot_width, 640);
  EXPECT_FALSE(s.header.quality.has_value());
  EXPECT_TRUE(s.header.settings.empty());
  EXPECT_FALSE(s.header.tolerance.has_value());
  EXPECT_TRUE(s.header.snapshots_like.empty());
}

struct BadCase {
  const char* name;
  std::string text;
  const char* error;  // the full "path:line:col: message" prefix expected
};

class ReplayParseBad : public ::testing::TestWithParam<BadCase> {};

TEST_P(ReplayParseBad, PositionedError) {
  const BadCase& c = GetParam();
  std::string e = error_of(c.text);
  EXPECT_EQ(e.rfind(c.error, 0), 0u) << "got: " << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << "one line: " << e;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ReplayParseBad,
    ::testing::Values(
        BadCase{"empty", "# nothing\n", "s.replay:1:1: empty script"},
        BadCase{"no_magic", "level x\n", "s.replay:1:1: a replay script starts with 'arcfire-replay 1'"},
        BadCase{"bad_version", "arcfire-replay 3\n", "s.replay:1:16: format version must be an integer in [1, 2]"},
        BadCase{"slots_in_v1", kHead + "slots 2\n", "s.replay:3:1: 'slots' needs version 2 of the format"},
        BadCase{"slots_range", kMatch + "slots 9\n", "s.replay:3:7: slots must be an integer in [1, 8]"},
        BadCase{"pilot_first", kMatch + "pilot 0 Host\n", "s.replay:3:1: 'pilot' lines come after a 'slots N' line"},
        BadCase{"pilot_slot", kMatch + "slots 2\npilot 2 Host\n", "s.replay:4:7: slot must be an integer in [0, 1]"},
        BadCase{"pilot_twice", kMatch + "slots 2\npilot 1 A\npilot 1 B\n", "s.replay:5:1: slot 1 has two 'pilot' lines"},
        BadCase{"drop_no_pilot", kMatch + "slots 2\ndrop 1 30\n", "s.replay:4:1: slot 1 has no 'pilot' line"},
        BadCase{"slot_line_alone", kHead + "0 slot 1 press fire_primary\n",
                "s.replay:3:3: 'slot' lines need a 'slots N' header line"},
        BadCase{"slot_range", kMatch + "slots 2\n0 slot 2 press fire_primary\n", "s.replay:4:8: slot must be an integer in [0, 1]"},
        BadCase{"slot_expect", kMatch + "slots 2\n0 slot 1 expect alive P\n",
                "s.replay:4:10: a slot line is press, release, axis or command, got 'expect'"},
        BadCase{"no_level", "arcfire-replay 1\n0 end\n", "s.replay:2:1: the header has no 'level' line"},
        BadCase{"unknown_header", kHead + "  colour red\n", "s.replay:3:3: unknown header key 'colour'"},
        BadCase{"dup_header", kHead + "level b\n", "s.replay:3:1: header key 'level' appears twice"},
        BadCase{"bad_seed", kHead + "seed -4\n", "s.replay:3:6: seed must be an integer in [0, 4294967295]"},
        BadCase{"bad_rate", kHead + "tick_rate 5\n", "s.replay:3:11: tick_rate must be an integer in [10, 480]"},
        BadCase{"bad_budget", kHead + "particle_budget 10\n", "s.replay:3:17: particle_budget must be an integer in [1000, 4000000]"},
        BadCase{"bad_substeps", kHead + "substeps 0\n", "s.replay:3:10: substeps must be an integer in [1, 16]"},
        BadCase{"bad_difficulty", kHead + "difficulty insane\n", "s.replay:3:12: difficulty must be easy, normal or hard"},
        BadCase{"header_after_body", kHead + "0 end\nseed 3\n", "s.replay:4:1: expected a tick number"},
        BadCase{"bad_tick", kHead + "1x press fire_primary\n", "s.replay:3:1: tick must be an integer"},
        BadCase{"order", kHead + "50 end_not\n", "s.replay:3:4: unknown line 'end_not'"},
        BadCase{"backwards", kHead + "50 press afterburner\n40 release afterburner\n",
                "s.replay:4:1: tick 40 is before the previous line's tick 50"},
        BadCase{"no_verb", kHead + "50   \n", "s.replay:3:3: missing what happens at this tick"},
        BadCase{"bad_button", kHead + "0 press fire\n", "s.replay:3:9: unknown button 'fire'; allowed: fire_primary"},
        BadCase{"bad_axis", kHead + "0 axis pich 1\n", "s.replay:3:8: unknown axis 'pich'"},
        BadCase{"axis_range", kHead + "0 axis pitch 1.5\n", "s.replay:3:14: axis value must be in [-1, 1], got 1.5"},
        BadCase{"axis_nan", kHead + "0 axis pitch nan\n", "s.replay:3:14: axis value must be a finite number"},
        BadCase{"axis_missing", kHead + "0 axis pitch\n", "s.replay:3:13: missing axis value"},
        BadCase{"bad_command", kHead + "0 command fly\n", "s.replay:3:11: unknown command 'fly'"},
        BadCase{"extra", kHead + "0 press afterburner now\n", "s.replay:3:21: unexpected 'now' after press afterburner"},
        BadCase{"bad_expect", kHead + "0 expect happy Player\n", "s.replay:3:10: unknown expectation 'happy'"},
        BadCase{"bad_range", kHead + "0 expect hull Player 50\n", "s.replay:3:22: hull must be a range MIN..MAX"},
        BadCase{"bad_kills", kHead + "0 expect kills Player many\n",
                "s.replay:3:23: kill count must be a number N or a range MIN..MAX, got 'many'"},
        BadCase{"bad_weapon", kHead + "0 expect accuracy Player laser 0..1\n",
                "s.replay:3:26: unknown weapon 'laser'; allowed: beam or missile"},
        BadCase{"no_accuracy_range", kHead + "0 expect accuracy Player beam\n",
                "s.replay:3:30: missing accuracy range MIN..MAX"},
        BadCase{"empty_range", kHead + "0 expect hull Player 50..10\n", "s.replay:3:22: hull range is empty"},
        BadCase{"range_words", kHead + "0 expect hull Player a..b\n", "s.replay:3:22: hull range bounds must be finite"},
        BadCase{"box_short", kHead + "0 expect position P 0..1 0..1\n", "s.replay:3:30: missing z range MIN..MAX"},
        BadCase{"quote", kHead + "0 expect alive \"Red\n", "s.replay:3:16: unterminated quoted name"},
        BadCase{"snapshot_name", kHead + "0 snapshot a/b\n", "s.replay:3:12: snapshot name must be 1 to 64"},
        BadCase{"snapshot_twice", kHead + "0 snapshot a\n1 snapshot a\n", "s.replay:4:12: snapshot name 'a' is used twice"},
        BadCase{"hash_hex", kHead + "0 hash xyz\n", "s.replay:3:8: hash value must be 1 to 16 hex digits"},
        BadCase{"hash_long", kHead + "0 hash 0123456789abcdef0\n", "s.replay:3:8: hash value must be 1 to 16 hex digits"},
        BadCase{"after_end", kHead + "10 end\n20 press afterburner\n", "s.replay:4:1: line after 'end' (line 3)"},
        BadCase{"set_no_value", kHead + "set render.sorting\n", "s.replay:3:5: expected key=value as with --set"},
        BadCase{"set_missing", kHead + "set\n", "s.replay:3:4: missing setting key=value"},
        BadCase{"set_unknown_key", kHead + "set render.fuzz=1\n", "s.replay:3:5: unknown setting 'render.fuzz'; known: "},
        BadCase{"set_bad_value", kHead + "set render.sorting=some\n",
                "s.replay:3:20: setting 'render.sorting' must be one of off, cluster or full, got 'some'"},
        BadCase{"set_twice", kHead + "set render.sorting=full\nset render.sorting=off\n",
                "s.replay:4:5: setting 'render.sorting' is set twice"},
        BadCase{"set_pinned", kHead + "substeps 2\nset sim.substeps=3\n",
                "s.replay:4:5: setting 'sim.substeps' is already given by the header's 'substeps' line"},
        BadCase{"pinned_after_set", kHead + "set particles.budget=5000\nparticle_budget 6000\n",
                "s.replay:4:1: header key 'particle_budget' repeats the setting of an earlier 'set particles.budget' line"},
        BadCase{"set_extra", kHead + "set render.scale=1 render.sorting=off\n",
                "s.replay:3:20: unexpected 'render.sorting=off' after the setting"},
        BadCase{"quality_missing", kHead + "quality\n", "s.replay:3:8: missing quality preset name"},
        BadCase{"quality_twice", kHead + "quality low\nquality high\n", "s.replay:4:1: header key 'quality' appears twice"},
        BadCase{"tolerance_form", kHead + "tolerance 5 99.9%\n", "s.replay:3:11: tolerance must be written N/255"},
        BadCase{"tolerance_range", kHead + "tolerance 300/255 99.9%\n",
                "s.replay:3:11: tolerance must be an integer in [0, 255], got '300'"},
        BadCase{"tolerance_no_percent", kHead + "tolerance 5/255 99.9\n",
                "s.replay:3:17: share of pixels must be a percentage in (0, 100] written P%"},
        BadCase{"tolerance_zero", kHead + "tolerance 5/255 0%\n", "s.replay:3:17: share of pixels must be a percentage"},
        BadCase{"tolerance_missing", kHead + "tolerance 5/255\n", "s.replay:3:16: missing share of pixels"},
        BadCase{"snapshots_like_name", kHead + "snapshots_like ../x\n", "s.replay:3:16: script name must be 1 to 64"},
        BadCase{"mod_name", kHead + "mod ../up 0123456789abcdef\n", "s.replay:3:5: mod name must be 1 to 64"},
        BadCase{"mod_hash", kHead + "mod red_rally 12345\n", "s.replay:3:15: mod hash must be 16 lowercase hexadecimal"},
        BadCase{"mod_no_hash", kHead + "mod red_rally\n", "s.replay:3:14: missing the mod's content hash"},
        BadCase{"mod_twice", kHead + "mod a 0123456789abcdef\nmod a 0123456789abcdef\n", "s.replay:4:5: mod 'a' is named twice"}),
    [](const ::testing::TestParamInfo<BadCase>& i) { return std::string(i.param.name); });

// Version 2: a network match's slots, pilots and per-slot input; it writes back the same.
TEST(ReplayParse, MatchLines) {
  const Script s = parse_script(kMatch +
                                    "slots 3\npilot 0 Host\npilot 2 \"Red Two\"\ndrop 2 90\n"
                                    "0 axis throttle 0.5\n0 slot 2 press fire_primary\n+5 slot 2 command countermeasure\n"
                                    "5 command target_next\n120 end\n",
                                "s.replay", known());
  EXPECT_EQ(s.header.version, 2);
  EXPECT_EQ(s.header.slots, 3);
  ASSERT_EQ(s.header.pilots.size(), 2u);
  EXPECT_EQ(s.header.pilots[1].name, "Red Two");
  EXPECT_EQ(s.header.pilots[1].drop, 90u);
  EXPECT_FALSE(s.header.pilots[0].drop);
  ASSERT_EQ(s.inputs.size(), 2u);
  EXPECT_EQ(s.inputs[0].slot, 0);
  EXPECT_EQ(s.inputs[1].slot, 2);
  ASSERT_EQ(s.commands.size(), 2u);
  EXPECT_EQ(s.commands[0].slot, 2);
  EXPECT_EQ(s.commands[1].slot, 0);
  const std::string text = write_script(s);
  EXPECT_NE(text.find("0 slot 2 press fire_primary\n"), std::string::npos);
  EXPECT_TRUE(parse_script(text, "w.replay", known()).same_content(s));
}

TEST(ReplayParse, MissingFileIsAnInputError) {
  EXPECT_THROW(load_script("tests/replays/no_such_script.replay", known()), arc::InputError);
}
