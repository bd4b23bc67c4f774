// tests/unit/game/test_hud.cpp — the HUD's combat cues, radar, scaling and settings file
// (game/render/hud_*.h), checked on the laid-out HudLayer without GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "game/render/hud_aim.h"
#include "game/render/hud_draw.h"
#include "game/render/hud_radar.h"
#include "game/render/render_view_builder.h"
#include "game/render/screen_projection.h"
#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

bool has_text(const HudLayer& h, const std::string& s) {
  for (const HudText& t : h.texts)
    if (t.text.find(s) != std::string::npos) return true;
  return false;
}

// The firing range: the player and an unpowered red drone 300 m ahead.
Game range_game() {
  Game g = Game::load_level(test::repo("tests/replays/levels/range.json"), test::options());
  g.step(InputFrame{}, {Command::TargetNearest});
  return g;
}

HudLayer hud_of(const World& w, int width = 1280, int height = 720) {
  RenderView v;
  build_render_view(w, {}, 1.0, CameraSettings{}, HudState{}, width, height, v);
  return v.hud;
}

bool has_exact_text(const HudLayer& h, const std::string& s) {
  for (const HudText& t : h.texts)
    if (t.text == s) return true;
  return false;
}

void place(World& w, size_t ship, glm::dvec3 p) { w.ships[ship].position = w.ships[ship].prev_position = p; }

// Lines drawn across a diagonal of the crosshair at screen centre: the hit marker's strokes.
int diagonal_strokes_near_centre(const HudLayer& h, double cx, double cy) {
  int n = 0;
  for (const HudLine& l : h.lines) {
    const double dx0 = l.x0 - cx, dy0 = l.y0 - cy, dx1 = l.x1 - cx, dy1 = l.y1 - cy;
    const bool diagonal = std::fabs(std::fabs(dx0) - std::fabs(dy0)) < 1.0 && std::fabs(std::fabs(dx1) - std::fabs(dy1)) < 1.0;
    if (diagonal && std::hypot(dx0, dy0) < 30.0 && std::hypot(dx1, dy1) > 5.0) ++n;
  }
  return n;
}

TEST(Hud, BeamRangeCueOnTheTargetBrackets) {
  Game g = range_game();
  EXPECT_TRUE(has_text(hud_of(g.world()), "IN RANGE"));  // 300 m, the Viper's beam reaches 650 m
  g.world_mut().ships[1].position.z = -900.0;
  g.world_mut().ships[1].prev_position.z = -900.0;
  const HudLayer far = hud_of(g.world());
  EXPECT_FALSE(has_text(far, "IN RANGE"));
  EXPECT_TRUE(has_text(far, "900 m"));
}

// Paused, the pause menu stands in the middle of the screen: no crosshair or target cues
// show through it (the bars, radar and kill feed stay).
TEST(Hud, NoCrosshairOrCuesThroughThePauseMenu) {
  Game g = range_game();
  auto green_lines_near_centre = [](const HudLayer& h) {
    int n = 0;
    for (const HudLine& l : h.lines)
      if (std::hypot(l.x0 - 640.0, l.y0 - 360.0) < 40.0 && l.color == kHudGreen) ++n;
    return n;
  };
  const HudLayer flying = hud_of(g.world());
  EXPECT_GE(green_lines_near_centre(flying), 4) << "the crosshair";
  EXPECT_TRUE(has_text(flying, "IN RANGE"));
  g.step(InputFrame{}, {Command::Pause});
  ASSERT_TRUE(g.world().paused);
  const HudLayer paused = hud_of(g.world());
  EXPECT_EQ(green_lines_near_centre(paused), 0);
  EXPECT_FALSE(has_text(paused, "IN RANGE"));
  EXPECT_TRUE(has_text(paused, "SHIELD"));
}

TEST(Hud, HitMarkerWhileTheBeamHitsAndNotBefore) {
  Game g = range_game();
  const World& w = g.world();
  const HudLayer before = hud_of(w);
  InputFrame fire;
  fire.buttons = kFirePrimary;
  for (int i = 0; i < 10; ++i) g.step(fire);
  ASSERT_EQ(w.ships[1].last_attacker, ShipId::from_index(0));
  ASSERT_GE(w.ships[1].last_hit_tick, w.tick - 3);  // the jagged channel may miss for a tick
  RenderView view;
  build_render_view(w, {}, 1.0, CameraSettings{}, HudState{}, 1280, 720, view);
  const HudLayer& during = view.hud;
  glm::dvec2 c;
  ASSERT_TRUE(Projector::of(view.camera, 1280, 720).project(crosshair_point(w, w.ships[0], 1.0), c));
  EXPECT_EQ(diagonal_strokes_near_centre(before, c.x, c.y), 0);
  EXPECT_GE(diagonal_strokes_near_centre(during, c.x, c.y), 4);
  for (int i = 0; i < 60; ++i) g.step(InputFrame{});  // the marker lasts a quarter second
  EXPECT_EQ(diagonal_strokes_near_centre(hud_of(w), c.x, c.y), 0);
}

TEST(Hud, DamageFromBehindGlowsAtTheBottomEdgeAndPointsOnTheRing) {
  Game g = range_game();
  World& w = g.world_mut();
  Ship& drone = w.ships[1];
  drone.position = drone.prev_position = glm::dvec3(0, 0, 400);  // behind the player
  const HudLayer calm = hud_of(w);
  w.ships[0].last_hit_tick = w.tick;
  w.ships[0].last_attacker = ShipId::from_index(1);
  const HudLayer hit = hud_of(w);
  int glow_at_bottom = 0;
  for (const HudQuad& q : hit.quads)
    if (q.color.r > 0.9f && q.color.g < 0.3f && q.y + q.h >= 719.0f && q.y > 600.0f) ++glow_at_bottom;
  EXPECT_GE(glow_at_bottom, 8);
  EXPECT_GT(hit.lines.size(), calm.lines.size());  // the wedge and its chevron
  for (int i = 0; i < 120; ++i) g.step(InputFrame{});  // faded after damage_seconds
  EXPECT_EQ(hud_of(g.world()).quads.size(), calm.quads.size());
}

TEST(Hud, IncomingMissileWarningWithDistance) {
  Game g = range_game();
  World& w = g.world_mut();
  EXPECT_FALSE(has_text(hud_of(w), "MISSILE "));  // "beam + MISSILES" is the weapon
  Projectile m;
  m.kind = SecondaryWeapon::Missile;
  m.owner = ShipId::from_index(1);
  m.target = ShipId::from_index(0);
  m.position = m.prev_position = glm::dvec3(120, 0, 160);  // 200 m away, behind on the right
  w.projectiles.push_back(m);
  const HudLayer h = hud_of(w);
  EXPECT_TRUE(has_text(h, "MISSILE 200 m"));
  m.target = ShipId::from_index(1);  // a missile on someone else is no warning
  w.projectiles.back() = m;
  EXPECT_FALSE(has_text(hud_of(w), "MISSILE "));
}

TEST(Hud, KillFeedNamesKillerAndVictimForAWhile) {
  Game g = range_game();
  World& w = g.world_mut();
  w.ships[1].hull = -1;
  w.ships[1].last_attacker = ShipId::from_index(0);
  g.step(InputFrame{});
  EXPECT_TRUE(has_text(hud_of(w), "Player destroyed Drone"));
  for (int i = 0; i < 9 * 60; ++i) g.step(InputFrame{});
  EXPECT_FALSE(has_text(hud_of(w), "destroyed"));
}

TEST(Hud, RadarRangeFollowsTheNearestThreat) {
  Game g = range_game();
  World& w = g.world_mut();
  const HudRules rules;
  EXPECT_EQ(radar_range(w, w.ships[0], rules), 500.0);  // 300 m × 1.3, rounded up to 500
  w.ships[1].position = glm::dvec3(0, 0, -1200);
  EXPECT_EQ(radar_range(w, w.ships[0], rules), 2000.0);
  w.ships[1].position = glm::dvec3(0, 0, -30000);
  EXPECT_EQ(radar_range(w, w.ships[0], rules), rules.radar_max_range);
  Projectile m;
  m.target = ShipId::from_index(0);
  m.position = glm::dvec3(0, 0, 500);
  w.projectiles.push_back(m);
  EXPECT_EQ(radar_range(w, w.ships[0], rules), rules.radar_max_range);  // fits the two nearest threats
  w.ships[1].position = glm::dvec3(0, 0, -700);
  EXPECT_EQ(radar_range(w, w.ships[0], rules), 1000.0);  // 700 m × 1.3
  EXPECT_TRUE(has_text(hud_of(w), "1 km"));
}

// Wherever the target is out of view, the arrow toward it stays off the radar.
TEST(Hud, OffScreenArrowNeverOverTheRadar) {
  Game g = range_game();
  World& w = g.world_mut();
  for (int width : {1280, 640, 2560}) {
    const int height = width * 9 / 16;
    const double scale = hud_canvas_scale(height);
    const HudRect r = radar_rect(std::lround(width / scale), std::lround(height / scale));
    for (int i = 0; i < 36; ++i) {
      const double a = 6.283185307179586 * i / 36;
      w.ships[1].position = w.ships[1].prev_position = glm::dvec3(300 * std::cos(a), 300 * std::sin(a), 250);
      for (const HudLine& l : hud_of(w, width, height).lines) {
        if (l.width < 2.9f * scale || l.color.r < 0.9f) continue;  // the arrow: thick red lines
        for (double t : {0.0, 0.5, 1.0}) {
          const double x = (l.x0 + (l.x1 - l.x0) * t) / scale, y = (l.y0 + (l.y1 - l.y0) * t) / scale;
          EXPECT_FALSE(x > r.x && x < r.x + r.w && y > r.y && y < r.y + r.h)
              << "arrow over the radar at " << width << "x" << height << ", target at " << i * 10 << " degrees";
        }
      }
    }
  }
}

TEST(Hud, EverySizeScalesWithTheWindowHeight) {
  Game g = range_game();
  const HudLayer small = hud_of(g.world(), 1280, 720), large = hud_of(g.world(), 2560, 1440);
  ASSERT_EQ(small.texts.size(), large.texts.size());
  ASSERT_EQ(small.lines.size(), large.lines.size());
  ASSERT_EQ(small.quads.size(), large.quads.size());
  for (size_t i = 0; i < small.texts.size(); ++i) {
    EXPECT_FLOAT_EQ(large.texts[i].scale, 2.0f * small.texts[i].scale) << small.texts[i].text;
    EXPECT_NEAR(large.texts[i].x, 2.0f * small.texts[i].x, 0.01f);
  }
  for (size_t i = 0; i < small.lines.size(); ++i) EXPECT_FLOAT_EQ(large.lines[i].width, 2.0f * small.lines[i].width);
  for (size_t i = 0; i < small.quads.size(); ++i) EXPECT_NEAR(large.quads[i].h, 2.0f * small.quads[i].h, 0.01f);
}

// The ring tells the truth: it lights exactly when holding the trigger does damage.
TEST(HudAim, BeamRingLightsWhenTheBeamWouldHit) {
  for (double side : {0.0, 60.0}) {
    Game g = range_game();
    place(g.world_mut(), 1, glm::dvec3(side, 0, -300));
    const bool lit = has_exact_text(hud_of(g.world()), "BEAM");
    EXPECT_EQ(lit, beam_would_hit(g.world(), g.world().ships[0]));
    const double before = g.world().ships[1].shield + g.world().ships[1].hull;
    InputFrame fire;
    fire.buttons = kFirePrimary;
    for (int i = 0; i < 20; ++i) g.step(fire);
    const bool hurt = g.world().ships[1].shield + g.world().ships[1].hull < before;
    EXPECT_EQ(lit, side == 0.0) << side << " m beside the nose";
    EXPECT_EQ(lit, hurt) << side << " m beside the nose";
  }
}

// Missiles home, so their cue is on the target ("MSL"); plasma flies straight and has a lead
// point ("PLS"); neither shows the other's cue.
TEST(HudAim, EachSecondaryWeaponHasItsOwnLabelledCue) {
  Game g = range_game();
  const HudLayer missiles = hud_of(g.world());
  EXPECT_TRUE(has_exact_text(missiles, "MSL"));
  EXPECT_FALSE(has_exact_text(missiles, "PLS"));
  g.step(InputFrame{}, {Command::SwitchWeapon});
  ASSERT_EQ(g.world().ships[0].secondary, SecondaryWeapon::Plasma);
  const HudLayer plasma = hud_of(g.world());
  EXPECT_TRUE(has_exact_text(plasma, "PLS"));
  EXPECT_FALSE(has_exact_text(plasma, "MSL"));
}

int red_lines(const HudLayer& h) {
  return int(std::count_if(h.lines.begin(), h.lines.end(), [](const HudLine& l) { return l.color == kHudRed; }));
}

// The lock ring fills around the target over the lock time, then "LOCK" is written beside it.
TEST(HudAim, LockRingFillsOverTheLockTimeThenSaysLock) {
  Game g = range_game();
  const World& w = g.world();
  const int64_t needed = int64_t(std::llround(w.ships[0].cls->missile.lock_time / w.dt));
  const HudLayer start = hud_of(w);
  EXPECT_FALSE(has_exact_text(start, "LOCK"));
  while (int64_t(g.tick()) < needed / 2) g.step(InputFrame{});
  const HudLayer half = hud_of(w);
  EXPECT_FALSE(has_exact_text(half, "LOCK"));
  EXPECT_TRUE(has_exact_text(half, "MSL"));
  while (int64_t(g.tick()) < needed + 2) g.step(InputFrame{});
  const HudLayer locked = hud_of(w);
  EXPECT_TRUE(has_exact_text(locked, "LOCK"));
  EXPECT_FALSE(has_exact_text(locked, "MSL"));
  // Half the ring's 32 strokes at half time; the locked cue's two rings replace the arc.
  EXPECT_NEAR(red_lines(half) - red_lines(start), 16, 2);
  EXPECT_GE(red_lines(locked) - red_lines(start), 60);
}

// The target is bracketed from the first frame, and the flares left are counted.
TEST(Hud, TargetAtLaunchAndFlareCount) {
  Game g = Game::load_level(test::repo("tests/replays/levels/range.json"), test::options());
  const HudLayer h = hud_of(g.world());
  EXPECT_TRUE(has_exact_text(h, "300 m"));
  EXPECT_TRUE(has_exact_text(h, "MSL"));
  EXPECT_TRUE(has_text(h, "flares 8"));
  g.step(InputFrame{}, {Command::Countermeasure});
  EXPECT_TRUE(has_text(hud_of(g.world()), "flares 7"));
}

TEST(HudAim, MissileReadyWithinReachAndCone) {
  Game g = range_game();
  World& w = g.world_mut();
  EXPECT_TRUE(missile_ready(w.ships[0], w.ships[1]));  // 300 m dead ahead
  place(w, 1, glm::dvec3(0, 0, -3000));                 // beyond 230 m/s × 8 s
  EXPECT_FALSE(missile_ready(w.ships[0], w.ships[1]));
  place(w, 1, glm::dvec3(0, 0, 300));                   // behind
  EXPECT_FALSE(missile_ready(w.ships[0], w.ships[1]));
}

// The distance sits under the brackets at any range, and beside the arrow when out of view.
TEST(HudAim, DistanceUnderTheBracketsAndBesideTheArrow) {
  Game g = range_game();
  World& w = g.world_mut();
  for (double z : {-300.0, -900.0, -5000.0}) {
    place(w, 1, glm::dvec3(0, 0, z));
    EXPECT_TRUE(has_exact_text(hud_of(w), fmt("%.0f m", -z))) << z;
  }
  place(w, 1, glm::dvec3(300, 0, 250));  // behind on the right: the arrow
  EXPECT_TRUE(has_exact_text(hud_of(w), "391 m"));
}

// A target far away still gets brackets of a readable size: 24 pixels at 720p, more above.
TEST(HudAim, BracketsNeverSmallerThanReadable) {
  Game g = range_game();
  place(g.world_mut(), 1, glm::dvec3(0, 0, -6000));
  for (int height : {720, 1440}) {
    double x0 = 1e9, x1 = -1e9;
    for (const HudLine& l : hud_of(g.world(), height * 16 / 9, height).lines)
      if (l.color == kHudRed)
        x0 = std::min({x0, double(l.x0), double(l.x1)}), x1 = std::max({x1, double(l.x0), double(l.x1)});
    EXPECT_GE(x1 - x0, 24.0 * height / 720.0) << height;
  }
}

// The usage example of game/render/hud_rules.h, word for word.
TEST(HudRules, BannerExample) {
  HudState hud;
  hud.rules = load_hud_rules("assets/settings/hud.json");

  EXPECT_EQ(hud.rules.radar_threats, HudRules{}.radar_threats);
}

TEST(HudRules, ShippedFileHoldsTheDefaults) {
  const HudRules file = load_hud_rules(test::repo("assets/settings/hud.json")), code;
  EXPECT_EQ(file.own_view.clear_radius, code.own_view.clear_radius);
  EXPECT_EQ(file.own_view.clear_fade, code.own_view.clear_fade);
  EXPECT_EQ(file.own_view.beam_half_width, code.own_view.beam_half_width);
  EXPECT_EQ(file.own_view.beam_near_fade, code.own_view.beam_near_fade);
  EXPECT_EQ(file.own_view.other_beam_half_width, code.own_view.other_beam_half_width);
  EXPECT_EQ(file.radar_min_range, code.radar_min_range);
  EXPECT_EQ(file.radar_max_range, code.radar_max_range);
  EXPECT_EQ(file.radar_margin, code.radar_margin);
  EXPECT_EQ(file.radar_threats, code.radar_threats);
  EXPECT_EQ(file.hit_marker_seconds, code.hit_marker_seconds);
  EXPECT_EQ(file.damage_seconds, code.damage_seconds);
  EXPECT_EQ(file.kill_feed_seconds, code.kill_feed_seconds);
  EXPECT_EQ(file.kill_feed_lines, code.kill_feed_lines);
}

TEST(HudRules, BadValuesNameFileLineAndColumn) {
  auto error_of = [](const std::string& text) {
    try {
      load_hud_rules(test::write_level("hud.json", text));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string negative = error_of("{\n  \"radar\": { \"min_range\": -5 }\n}");
  EXPECT_NE(negative.find("hud.json:2:27"), std::string::npos) << negative;
  EXPECT_NE(error_of("{ \"radar\": { \"min_range\": 900, \"max_range\": 600 } }").find("max_range"), std::string::npos);
  EXPECT_NE(error_of("{ \"hit_marker_secs\": 1 }").find("unknown key"), std::string::npos);
  EXPECT_EQ(error_of("{ \"kill_feed\": { \"lines\": 2 } }"), "no error");
}

}  // namespace
}  // namespace arc
