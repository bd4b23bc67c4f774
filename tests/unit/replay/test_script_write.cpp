// Writer → parser round trips, axis quantisation round trips and the recorder's diff lines.
#include <gtest/gtest.h>

#include <cmath>

#include "game/app/all_settings.h"
#include "replay/script.h"

using namespace arc::replay;

namespace {

// Every setting the game knows: what a `set` line may name.
const arc::Settings& known() {
  static const arc::Settings settings = arc::all_settings();
  return settings;
}

}  // namespace

TEST(ReplayWrite, AxisTextRoundTripsEveryQuantisedValue) {
  for (int q = -127; q <= 127; ++q) {
    std::string t = axis_text(static_cast<int8_t>(q));
    EXPECT_EQ(quantise_axis(std::stod(t)), q) << t;
    EXPECT_LE(t.size(), 7u) << t;
  }
  EXPECT_EQ(axis_text(0), "0");
  EXPECT_EQ(axis_text(127), "1");
  EXPECT_EQ(axis_text(-127), "-1");
}

TEST(ReplayWrite, QuantisationMatchesLiveInputRules) {
  EXPECT_EQ(quantise_axis(0.5), 64);
  EXPECT_EQ(quantise_axis(-0.5), -64);
  EXPECT_EQ(quantise_axis(2.0), 127);
  EXPECT_EQ(quantise_axis(-7.0), -127);
  EXPECT_EQ(quantise_axis(std::nan("")), 0);
  EXPECT_EQ(quantise_axis(0.003), 0);
  EXPECT_EQ(quantise_axis(0.004), 1);
}

TEST(ReplayWrite, ParsedScriptWritesAndParsesBackToTheSameContent) {
  const std::string text = R"(arcfire-replay 1
level "levels/my duel.json"
seed 7
tick_rate 120
difficulty easy
build abc123
snapshot_size 320 200
particle_budget 4000
substeps 3
quality medium
set render.soft_edges=linear
set render.scale=0.75
mod red_rally 00000000000000ff
tolerance 2/255 99.95%
snapshots_like other_scene
0 press fire_primary
0 axis yaw 0.25
+10 axis strafe_y -1
10 release fire_primary
12 command switch_weapon
12 command camera
20 expect alive "Red Leader"
20 expect hull Player 12.5..100
20 expect position Player -1..1 -2..2 -3e5..3e5
20 expect distance Player "Red Leader" 0..1e9
20 expect particles 10..20
20 expect winner blue
20 snapshot shot
20 hash 0123456789abcdef
21 full_hash ?
30 end
)";
  Script a = parse_script(text, "a.replay", known());
  std::string written = write_script(a);
  Script b = parse_script(written, "b.replay", known());
  EXPECT_TRUE(a.same_content(b)) << written;
  EXPECT_EQ(write_script(b), written);
  EXPECT_NE(written.find("\nquality medium\nset render.soft_edges=linear\nset render.scale=0.75\n"
                         "mod red_rally 00000000000000ff\ntolerance 2/255 99.95%\nsnapshots_like other_scene\n"),
            std::string::npos)
      << written;
}

TEST(ReplayWrite, ChangedContentIsNotTheSame) {
  Script a = parse_script("arcfire-replay 1\nlevel x\n0 axis yaw 0.25\n1 end\n", "a", known());
  Script b = parse_script("arcfire-replay 1\nlevel x\n0 axis yaw 0.26\n1 end\n", "b", known());
  EXPECT_FALSE(a.same_content(b));
  const std::string head = "arcfire-replay 1\nlevel x\n";
  EXPECT_FALSE(parse_script(head + "set render.scale=1\n1 end\n", "c", known())
                   .same_content(parse_script(head + "set render.scale=0.5\n1 end\n", "d", known())));
  EXPECT_FALSE(parse_script(head + "tolerance 5/255 99.9%\n1 end\n", "e", known())
                   .same_content(parse_script(head + "tolerance 5/255 99%\n1 end\n", "f", known())));
  EXPECT_FALSE(parse_script(head + "quality low\n1 end\n", "g", known()).same_content(parse_script(head + "1 end\n", "h", known())));
  EXPECT_TRUE(parse_script(head + "quality low\n1 end\n", "i", known())
                  .same_content(parse_script("# moved\n" + head + "\nquality low\n1 end\n", "j", known())));
  // Found by tests/fuzz (replay): a sound expectation's column is a source position too.
  EXPECT_TRUE(parse_script(head + "1 expect sound explosion\n2 end\n", "k", known())
                  .same_content(parse_script(head + "1 expect sound   explosion\n2 end\n", "l", known())));
}

TEST(ReplayWrite, RecordedDiffsReplayToTheSameHeldState) {
  // The recorder writes only changes; applying the parsed lines must rebuild each tick's state.
  std::vector<InputState> live(50);
  for (size_t t = 0; t < live.size(); ++t) {
    InputState s;
    s.axes[0] = static_cast<int8_t>((int(t) * 37) % 255 - 127);
    s.axes[3] = t > 20 ? 127 : 0;
    s.buttons = static_cast<uint16_t>((t / 7) % 16);
    live[t] = s;
  }
  Header h;
  h.level = "levels/duel.json";
  std::string text = header_text(h);
  InputState prev;
  for (size_t t = 0; t < live.size(); ++t) {
    text += input_diff_lines(t, prev, live[t]);
    prev = live[t];
  }
  text += end_line(live.size());
  Script s = parse_script(text, "rec.replay", known());
  InputState held;
  size_t next = 0;
  for (size_t t = 0; t < live.size(); ++t) {
    while (next < s.inputs.size() && s.inputs[next].tick == t) apply_input(held, s.inputs[next++]);
    ASSERT_EQ(held, live[t]) << "tick " << t;
  }
  EXPECT_EQ(input_diff_lines(3, live[4], live[4]), "");
}

// Only the value's bytes change: CR LF line ends and a missing final newline stay as they were.
TEST(ReplayWrite, FillHashValuesKeepsLineEndsAndTheLastByte) {
  const std::string text = "arcfire-replay 1\r\nlevel x\r\n60 hash 12\r\n60 end";
  Script s = parse_script(text, "f.replay", known());
  EXPECT_EQ(fill_hash_values(text, s, {0xabcULL}), "arcfire-replay 1\r\nlevel x\r\n60 hash 0000000000000abc\r\n60 end");
}

TEST(ReplayWrite, FillHashValuesKeepsEverythingElse) {
  const std::string text =
      "arcfire-replay 1\nlevel x\n# keep me\n+60 hash ?   # after one second\n120 full_hash 12\n120 end\n";
  Script s = parse_script(text, "f.replay", known());
  std::string filled = fill_hash_values(text, s, {0xabcULL, 0xffffffffffffffffULL});
  EXPECT_EQ(filled,
            "arcfire-replay 1\nlevel x\n# keep me\n+60 hash 0000000000000abc   # after one second\n"
            "120 full_hash ffffffffffffffff\n120 end\n");
  Script t = parse_script(filled, "f.replay", known());
  EXPECT_EQ(t.hashes[0].value, 0xabcULL);
  EXPECT_EQ(t.hashes[0].tick, 60u);
}
