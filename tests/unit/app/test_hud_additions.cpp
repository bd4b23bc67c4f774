// The HUD pieces the live game adds: the set throttle and speed, the outcome above the pause
// menu, the joystick reticle, and messages wrapped within the screen (game/render/hud_layout).
#include <gtest/gtest.h>

#include "game/render/hud_layout.h"
#include "game/render/render_view_builder.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "core/data_root.h"

namespace {

arc::Game duel() {
  arc::GameOptions o;
  o.root_dir = arc::data_root();
  return arc::Game::load_level(arc::data_root() + "/levels/duel.json", o);
}

arc::HudLayer hud_of(const arc::Game& game, const arc::HudState& state, int width, int height) {
  arc::RenderView view;
  arc::build_render_view(game.world(), {}, 1.0, arc::CameraSettings{}, state, width, height, view);
  return view.hud;
}

const arc::HudText* find_text(const arc::HudLayer& h, const std::string& part) {
  for (const arc::HudText& t : h.texts)
    if (t.text.find(part) != std::string::npos) return &t;
  return nullptr;
}

constexpr double kGlyphAdvance = 7.0;  // gfx/hud_font: ProggyClean at scale 1

}  // namespace

TEST(WrapText, LinesFitAndLongWordsAreCut) {
  const auto lines = arc::wrap_text("reload failed: levels/a_very_long_file_name.json:3:4: unknown key", 16, 10);
  ASSERT_GE(lines.size(), 4u);
  for (const std::string& l : lines) EXPECT_LE(l.size(), 16u) << l;
  EXPECT_EQ(lines[0], "reload failed:");
  EXPECT_EQ(arc::wrap_text("one two three four", 9, 1), (std::vector<std::string>{"one tw..."}));
  EXPECT_EQ(arc::wrap_text("  a\nb  ", 9, 3), (std::vector<std::string>{"a b"}));
  EXPECT_TRUE(arc::wrap_text("", 9, 3).empty());
}

TEST(HudAdditions, ErrorBannerWrapsInsideTheScreenAboveTheBars) {
  arc::Game game = duel();
  arc::HudState state;
  state.error_banner = "reload failed: " + std::string(300, 'x') + " and then some more words to wrap";
  for (auto [width, height] : {std::pair{1280, 720}, std::pair{640, 360}, std::pair{2560, 1440}}) {
    const arc::HudLayer h = hud_of(game, state, width, height);
    const arc::HudText* first = find_text(h, "reload failed");
    ASSERT_NE(first, nullptr);
    for (const arc::HudText& t : h.texts) {
      if (t.y < first->y || t.color != first->color) continue;
      EXPECT_GE(t.x, 0.0f);
      EXPECT_LE(t.x + t.text.size() * kGlyphAdvance * t.scale, width) << width << ": " << t.text;
      EXPECT_LT(t.y, height - 140.0 * height / 720.0) << "over the bars at " << height;
    }
  }
}

TEST(HudAdditions, ThrottleAndSpeedAreShown) {
  arc::Game game = duel();
  arc::InputFrame f;
  f.throttle = arc::quantise_axis(0.5);
  for (int i = 0; i < 120; ++i) game.step(f);
  const arc::HudLayer h = hud_of(game, arc::HudState{}, 1280, 720);
  EXPECT_NE(find_text(h, "THR"), nullptr);
  EXPECT_NE(find_text(h, "50%"), nullptr);
  const arc::HudText* speed = find_text(h, " m/s");
  ASSERT_NE(speed, nullptr);
  EXPECT_EQ(speed->text, "81 m/s");  // 64/127 of the Viper's 160 m/s
  const arc::HudLayer big = hud_of(game, arc::HudState{}, 2560, 1440);
  EXPECT_FLOAT_EQ(find_text(big, " m/s")->scale, 2.0f * speed->scale);  // scaled with the height
}

TEST(HudAdditions, ReticleIsDrawnOnlyWhenShown) {
  arc::Game game = duel();
  arc::HudState state;
  const size_t lines = hud_of(game, state, 1280, 720).lines.size();
  state.reticle = {true, 0.1, -0.05, 0.25, 0.015};
  const arc::HudLayer h = hud_of(game, state, 1280, 720);
  EXPECT_GT(h.lines.size(), lines + 48);  // the ring, the dead zone, the cursor
  bool cursor = false;  // a stroke of the cross centred 0.1 and -0.05 screen heights off the centre
  for (const arc::HudLine& l : h.lines)
    cursor |= std::abs((l.x0 + l.x1) * 0.5f - 712.0f) < 0.5f && std::abs((l.y0 + l.y1) * 0.5f - 324.0f) < 0.5f;
  EXPECT_TRUE(cursor);
}
