#include <cmath>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "game/sim/ai.h"
#include "game/sim/beams.h"
#include "game/sim/damage.h"
#include "game/sim/geometry.h"
#include "game/sim/level_start.h"
#include "game/sim/world.h"
#include "test_helpers.h"
#include "core/data_root.h"

namespace arc {
namespace {

using test::level_text;
using test::options;
using test::write_level;

// Two stationary ships: a shooter at the origin facing −Z and a target straight ahead.
Game facing_pair(const std::string& name, double target_z, const std::string& target_ai = "none",
                 const std::string& extra = "", double target_x = 0) {
  std::string ships = R"({ "name": "Shooter", "class": "viper", "team": "blue", "player": true },
    { "name": "Target", "class": "viper", "team": "red", "ai": ")" + target_ai + R"(", "position": [)" +
                      std::to_string(target_x) + ", 0, " + std::to_string(target_z) + "] }";
  return Game::load_level(write_level(name, level_text(ships, extra)), options());
}

InputFrame fire() {
  InputFrame f;
  f.buttons = kFirePrimary;
  return f;
}

TEST(BeamGeometry, StraightLineAtAShipHitsAndStallsOnTheShieldSphere) {
  Game g = facing_pair("beam_hit.json", -200);
  const World& w = g.world();
  const Ship& t = w.ships[1];
  BeamHit hit = trace_beam(w, w.ships[0].id, {glm::dvec3(0, 0, -5), glm::dvec3(0, 0, -600)});
  ASSERT_EQ(hit.ship, w.ships[1].id);
  EXPECT_TRUE(hit.on_shield);
  EXPECT_NEAR(glm::length(hit.point - t.position), t.cls->shield_radius, 1e-9);
  EXPECT_NEAR(hit.distance, 200.0 - 5.0 - t.cls->shield_radius, 1e-9);
}

TEST(BeamGeometry, BeamAimedAwayMisses) {
  Game g = facing_pair("beam_miss.json", -200);
  BeamHit hit = trace_beam(g.world(), g.world().ships[0].id, {glm::dvec3(0, 0, -5), glm::dvec3(600, 0, -5)});
  EXPECT_FALSE(hit.ship);
  EXPECT_LT(hit.distance, 0.0);
}

TEST(BeamGeometry, PolylineHitsOnTheRightSegmentAndDepletedShieldStopsAtTheHull) {
  Game g = facing_pair("beam_poly.json", -200);
  World& w = g.world_mut();
  w.ships[1].shield = 0;
  // A jagged channel: the first segment misses, the second crosses the target.
  std::vector<glm::dvec3> line{{0, 0, 0}, {50, 0, -100}, {-50, 0, -300}};
  BeamHit hit = trace_beam(w, w.ships[0].id, line);
  ASSERT_EQ(hit.ship, w.ships[1].id);
  EXPECT_FALSE(hit.on_shield);
  EXPECT_NEAR(glm::length(hit.point - w.ships[1].position), w.ships[1].cls->collision_radius, 1e-9);
  EXPECT_GT(hit.distance, glm::length(line[1] - line[0]));
}

TEST(BeamGeometry, SegmentSphereEdgeCases) {
  EXPECT_DOUBLE_EQ(segment_sphere({0, 0, 0}, {0, 0, -10}, {0, 0, -5}, 1.0), 0.4);
  EXPECT_DOUBLE_EQ(segment_sphere({0, 0, -5}, {0, 0, -10}, {0, 0, -5}, 1.0), 0.0);  // starts inside
  EXPECT_LT(segment_sphere({0, 0, 0}, {0, 0, -3}, {0, 0, -5}, 1.0), 0.0);         // stops short
  EXPECT_LT(segment_sphere({0, 0, 0}, {0, 0, 0}, {0, 0, -5}, 1.0), 0.0);          // zero length
  EXPECT_LT(segment_sphere({0, 0, -10}, {0, 0, -20}, {0, 0, -5}, 1.0), 0.0);      // moving away
}

TEST(Beam, FiringAtATargetDrainsShieldThenHullAndCostsEnergy) {
  Game g = facing_pair("beam_damage.json", -150);
  const World& w = g.world();
  const double shield0 = w.ships[1].shield, hull0 = w.ships[1].hull;
  for (int i = 0; i < 30; ++i) g.step(fire());
  EXPECT_TRUE(w.ships[0].beam_firing);
  EXPECT_EQ(w.ships[0].beam_target, w.ships[1].id);
  EXPECT_LT(w.ships[1].shield, shield0);
  EXPECT_DOUBLE_EQ(w.ships[1].hull, hull0);
  EXPECT_LT(w.ships[0].energy, w.ships[0].cls->energy);
  for (ClusterHandle ch : w.ships[0].beam_channels) EXPECT_TRUE(w.particles->alive(ch));
  g.step(InputFrame{});
  EXPECT_FALSE(w.ships[0].beam_firing);
  EXPECT_TRUE(w.ships[0].beam_channels.empty());
}

TEST(Beam, LiveChannelStallsOnTheTargetsShieldSphere) {
  Game g = facing_pair("beam_stall.json", -150);
  const World& w = g.world();
  g.step(fire());
  g.step(fire());
  const Ship& s = w.ships[0];
  const Ship& t = w.ships[1];
  ASSERT_EQ(s.beam_channels.size(), s.cls->beam.mounts.size());
  int stalled = 0;
  for (size_t m = 0; m < s.beam_channels.size(); ++m) {
    const double d = s.beam_hit_distance[m];
    if (d < 0) continue;
    ++stalled;
    glm::dvec3 p = w.particles->lightning_point_at(s.beam_channels[m], d);
    EXPECT_NEAR(glm::length(p - t.position), t.cls->shield_radius, 1e-6);
    EXPECT_LT(d, w.particles->lightning_length(s.beam_channels[m]));
  }
  EXPECT_GE(stalled, 1);
}

TEST(Damage, FlowsShieldThenHullThenExplosion) {
  Game g = facing_pair("damage_flow.json", -400);
  World& w = g.world_mut();
  Ship& t = w.ships[1];
  const double shield = t.shield, hull = t.hull;
  apply_damage(w, t, shield * 0.5, t.position, w.ships[0].id);
  EXPECT_DOUBLE_EQ(t.shield, shield * 0.5);
  EXPECT_DOUBLE_EQ(t.hull, hull);
  apply_damage(w, t, shield * 0.5 + 10.0, t.position, w.ships[0].id);
  EXPECT_DOUBLE_EQ(t.shield, 0.0);
  EXPECT_DOUBLE_EQ(t.hull, hull - 10.0);
  apply_damage(w, t, hull, t.position, w.ships[0].id);
  EXPECT_LE(t.hull, 0.0);
  EXPECT_TRUE(t.alive);  // deaths resolve inside the tick
  g.step(InputFrame{});
  EXPECT_FALSE(w.ships[1].alive);
  EXPECT_EQ(w.ships[0].kills, 1);
  EXPECT_EQ(w.explosions.size(), 1u);
  EXPECT_GT(w.particles->stats().live_clusters, 0u);
}

TEST(Damage, AttachedClustersGoWithTheirShipInTheSameTick) {
  Game g = facing_pair("attached.json", -400);
  World& w = g.world_mut();
  g.step(fire());
  std::vector<ClusterHandle> attached = w.ships[1].shield_fx.clusters;
  for (const EffectHandle& e : w.ships[1].exhaust_fx)
    attached.insert(attached.end(), e.clusters.begin(), e.clusters.end());
  ASSERT_FALSE(attached.empty());
  for (ClusterHandle c : attached) ASSERT_TRUE(w.particles->alive(c));
  apply_damage(w, w.ships[1], 1e6, w.ships[1].position, w.ships[0].id);
  g.step(InputFrame{});
  ASSERT_FALSE(w.ships[1].alive);
  for (ClusterHandle c : attached) EXPECT_FALSE(w.particles->alive(c));
}

// A class outlined in 100 000 vents carries kMaxExhaustPlumes plumes spread over its list, so
// its particle pools are bounded; a class with few exhausts has one plume per point.
TEST(Exhausts, ManyExhaustPointsSpawnABoundedNumberOfPlumes) {
  Game g = facing_pair("vents.json", -400);
  World& w = g.world_mut();
  Ship& s = w.ships[1];
  ASSERT_LE(s.cls->exhausts.size(), kMaxExhaustPlumes);
  EXPECT_EQ(s.exhaust_fx.size(), s.cls->exhausts.size());
  EXPECT_EQ(exhaust_plume_points(s.cls->exhausts), s.cls->exhausts);
  ShipClassDef vents = *s.cls;
  vents.shield = 0;
  vents.exhausts.clear();
  for (int i = 0; i < 100000; ++i) vents.exhausts.push_back({-8 + (i % 400) * 0.04, -2 + (i / 400) * 0.016, 6.125});
  const std::vector<glm::dvec3> plumes = exhaust_plume_points(vents.exhausts);
  ASSERT_EQ(plumes.size(), kMaxExhaustPlumes);
  EXPECT_LT(plumes.front().y, -1.5);  // from the first runs of the list to the last
  EXPECT_GT(plumes.back().y, 1.5);
  const size_t clusters_before = w.particles->stats().live_clusters;
  const ShipClassDef* viper = s.cls;
  s.exhaust_fx.clear();
  s.cls = &vents;
  attach_ship_effects(w, s);
  EXPECT_EQ(s.exhaust_fx.size(), kMaxExhaustPlumes);
  size_t clusters = 0;
  for (const EffectHandle& e : s.exhaust_fx) clusters += e.clusters.size();
  EXPECT_LE(clusters, 2 * kMaxExhaustPlumes);  // a plume and a nozzle glow each
  EXPECT_LE(w.particles->stats().live_clusters, clusters_before + 2 * kMaxExhaustPlumes);
  for (int i = 0; i < 5; ++i) g.step(InputFrame{});
  s.cls = viper;  // the game outlives `vents`
}

TEST(Damage, SplashDamageReachesNeighboursOnlyWhenTheLevelEnablesIt) {
  for (bool splash : {false, true}) {
    std::string ships = R"({ "name": "A", "class": "viper", "team": "blue", "ai": "none" },
      { "name": "B", "class": "viper", "team": "red", "ai": "none", "position": [0, 0, -400] },
      { "name": "C", "class": "viper", "team": "red", "ai": "none", "position": [30, 0, -400] })";
    std::string extra = splash ? R"( "splash": { "radius": 60, "damage": 50 },)" : "";
    Game g = Game::load_level(write_level("splash.json", test::level_text(ships, extra)), options());
    World& w = g.world_mut();
    apply_damage(w, w.ships[1], 1e6, w.ships[1].position, w.ships[0].id);
    g.step(InputFrame{});
    const Ship& c = w.ships[2];
    if (splash) EXPECT_LT(c.shield, c.cls->shield);
    else EXPECT_DOUBLE_EQ(c.shield, c.cls->shield);
  }
}

TEST(Shield, SphereDensityFollowsStrength) {
  Game g = facing_pair("density.json", -400);
  World& w = g.world_mut();
  g.step(InputFrame{});
  const std::vector<ClusterHandle> full = w.ships[1].shield_fx.clusters;
  EXPECT_EQ(w.ships[1].shield_density, 4);
  const uint32_t particles_full = w.particles->stats().live_particles;
  apply_damage(w, w.ships[1], w.ships[1].cls->shield * 0.6, w.ships[1].position, w.ships[0].id);
  g.step(InputFrame{});
  g.step(InputFrame{});
  EXPECT_EQ(w.ships[1].shield_density, 2);
  for (ClusterHandle c : full) EXPECT_FALSE(w.particles->alive(c));
  for (ClusterHandle c : w.ships[1].shield_fx.clusters) EXPECT_TRUE(w.particles->alive(c));
  EXPECT_LT(w.particles->stats().live_particles, particles_full);
}

TEST(Shield, RegeneratesOnlyAfterTheDelay) {
  Game g = facing_pair("regen.json", -400);
  World& w = g.world_mut();
  apply_damage(w, w.ships[1], 50, w.ships[1].position, w.ships[0].id);
  const double after_hit = w.ships[1].shield;
  const int delay_ticks = int(std::llround(w.ships[1].cls->shield_regen_delay / w.dt));
  for (int i = 0; i < delay_ticks - 2; ++i) g.step(InputFrame{});
  EXPECT_DOUBLE_EQ(w.ships[1].shield, after_hit);
  for (int i = 0; i < 60; ++i) g.step(InputFrame{});
  EXPECT_GT(w.ships[1].shield, after_hit);
}

// Locked on a target a little off the nose (game/sim/seekers.h), a missile turns onto it.
TEST(Missiles, HomeOnTheTargetAndHit) {
  Game g = facing_pair("missile.json", -300, "none", "", 40);
  World& w = g.world_mut();
  ASSERT_EQ(w.ships[0].target, w.ships[1].id);
  for (int i = 0; i < 120; ++i) g.step(InputFrame{});
  InputFrame f;
  f.buttons = kFireSecondary;
  g.step(f);
  ASSERT_EQ(w.projectiles.size(), 1u);
  EXPECT_EQ(w.projectiles[0].target, w.ships[1].id);
  const double shield0 = w.ships[1].shield;
  for (int i = 0; i < 600 && w.ships[1].shield == shield0; ++i) g.step(InputFrame{});
  EXPECT_LT(w.ships[1].shield, shield0);
  EXPECT_TRUE(w.projectiles.empty());
}

TEST(Plasma, SwitchWeaponFiresBoltsThatFlyStraight) {
  Game g = facing_pair("plasma.json", -300);
  World& w = g.world_mut();
  g.step(InputFrame{}, {Command::SwitchWeapon});
  EXPECT_EQ(w.ships[0].secondary, SecondaryWeapon::Plasma);
  InputFrame f;
  f.buttons = kFireSecondary;
  g.step(f);
  ASSERT_EQ(w.projectiles.size(), 1u);
  EXPECT_EQ(w.projectiles[0].kind, SecondaryWeapon::Plasma);
  const double shield0 = w.ships[1].shield;
  for (int i = 0; i < 120; ++i) g.step(InputFrame{});
  EXPECT_LT(w.ships[1].shield, shield0);
}

class AiVersusStationary : public ::testing::TestWithParam<const char*> {};

// Limit: shields recharge between the AI's attack runs, and on easy a Warden's regeneration
// nearly matches a calm Viper's fire (about 125 s measured), hence two and a half minutes.
TEST_P(AiVersusStationary, DestroysItWithinTwoAndAHalfMinutes) {
  std::string ships = R"({ "name": "Hunter", "class": "viper", "team": "red", "position": [300, 120, 500], "orientation": [70, 0, 0] },
    { "name": "Sitting duck", "class": "warden", "team": "blue", "ai": "none", "position": [0, 0, -300] })";
  std::string extra = std::string(R"( "difficulty": ")") + GetParam() + "\",";
  Game g = Game::load_level(write_level(std::string("ai_") + GetParam() + ".json", level_text(ships, extra)), options());
  const World& w = g.world();
  int64_t limit = 60 * 150;
  while (w.ships[1].alive && int64_t(g.tick()) < limit) g.step(InputFrame{});
  EXPECT_FALSE(w.ships[1].alive) << "hull " << w.ships[1].hull << " shield " << w.ships[1].shield;
  EXPECT_EQ(w.ships[0].kills, 1);
  RecordProperty("ticks", std::to_string(g.tick()));
}

INSTANTIATE_TEST_SUITE_P(Difficulties, AiVersusStationary, ::testing::Values("easy", "normal", "hard"));

// An AI fighter with the enemy straight ahead holds fire while a ship of its own side sits in
// the line of fire, and fires once it has flown past that ship; with the ally well to the side
// it fires on the way in.
TEST(Ai, HoldsFireWhileAnAllyIsInTheLineOfFire) {
  struct Count {
    int before = 0, after = 0;  // ticks firing with the ally still ahead, and once past it
  };
  auto run = [](double ally_x) {
    std::string ships = R"({ "name": "Hunter", "class": "viper", "team": "red", "position": [0, 0, 0] },
      { "name": "Ally", "class": "warden", "team": "red", "ai": "none", "position": [)" +
                        std::to_string(ally_x) + R"(, 0, -150] },
      { "name": "Enemy", "class": "warden", "team": "blue", "ai": "none", "position": [0, 0, -400] })";
    Game g = Game::load_level(write_level("ai_ally_" + std::to_string(int(ally_x)) + ".json", level_text(ships)), options());
    Count n;
    for (int t = 0; t < 360; ++t) {
      g.step(InputFrame{});
      const Ship& h = g.world().ships[0];
      const bool firing = (h.controls.buttons & (kFirePrimary | kFireSecondary)) != 0;
      (h.position.z > -150.0 ? n.before : n.after) += firing;
    }
    return n;
  };
  const Count blocked = run(0.0), clear = run(60.0);
  EXPECT_EQ(blocked.before, 0) << "the ally is straight in the line of fire";
  EXPECT_GT(blocked.after, 10) << "past the ally the line is clear";
  EXPECT_GT(clear.before, 10) << "the ally is well to the side";
}

// A player flying straight with an AI Viper 300 m behind: on easy and normal the AI lets go of
// the tail after the difficulty's tail_limit_s (assets/settings/ai.json), so the player gets a
// window to turn; on hard it stays there.
TEST(Ai, BreaksOffThePlayersTailOnEasyAndNormal) {
  const AiDifficultyTable ai = load_ai_difficulties(arc::data_root());
  const char* names[] = {"easy", "normal", "hard"};
  for (int d = 0; d < 3; ++d) {
    SCOPED_TRACE(names[d]);
    std::string ships = R"({ "name": "Player", "class": "warden", "team": "blue", "player": true, "velocity": [0, 0, -120] },
      { "name": "Chaser", "class": "viper", "team": "red", "position": [0, 0, 300], "velocity": [0, 0, -120] })";
    std::string extra = std::string(R"( "difficulty": ")") + names[d] + "\",";
    Game g = Game::load_level(write_level(std::string("tail_") + names[d] + ".json", level_text(ships, extra)), options());
    const World& w = g.world();
    InputFrame straight;
    straight.throttle = quantise_axis(1.0);
    double longest = 0, stretch = 0;
    bool broke_off = false;
    for (int i = 0; i < 60 * 20 && w.ships[0].alive; ++i) {
      g.step(straight);
      const Ship& p = w.ships[0];
      const Ship& c = w.ships[1];
      const glm::dvec3 rel = p.position - c.position;
      const double dist = glm::length(rel);
      const bool on_tail = dist < 1.25 * c.cls->beam.range && glm::dot(forward_of(p.orientation), rel) > 0.5 * dist &&
                           glm::dot(forward_of(c.orientation), rel) > 0.85 * dist;
      stretch = on_tail ? stretch + w.dt : 0.0;
      longest = std::max(longest, stretch);
      broke_off = broke_off || c.ai_state.mode == AiMode::BreakOff;
    }
    RecordProperty(std::string("longest_on_tail_s_") + names[d], std::to_string(longest));
    if (ai[d].tail_limit_s > 0) {
      EXPECT_TRUE(broke_off);
      // Noticed at a decision, left at one, then the nose takes a moment to swing off.
      EXPECT_LE(longest, ai[d].tail_limit_s + 2.0 * ai[d].reaction_s + 0.5);
      EXPECT_LE(ai[d].tail_limit_s, 6.0) << "a few seconds, not more";
    } else {
      EXPECT_GT(longest, 8.0);
    }
  }
  EXPECT_GT(ai[0].tail_limit_s, 0.0);
  EXPECT_GT(ai[1].tail_limit_s, 0.0);
}

// The difficulty sets the enemy's skill: the player's wing and friends fly ai.json's "allies"
// row at every difficulty, the enemy the difficulty's row.
TEST(Ai, AlliesFlyTheirOwnRowAtEveryDifficulty) {
  const AiDifficultyTable ai = load_ai_difficulties(arc::data_root());
  ASSERT_TRUE(ai.allies.has_value());
  for (int d = 0; d < 3; ++d) {
    GameOptions o;
    o.root_dir = arc::data_root();
    o.difficulty_override = true;
    o.difficulty = static_cast<Difficulty>(d);
    Game g = Game::load_level(arc::data_root() + "/levels/skirmish.json", o);
    const World& w = g.world();
    int allies = 0, enemies = 0;
    for (const Ship& s : w.ships) {
      if (s.player) continue;
      const bool ally = !w.hostile(w.ship(w.player), s);
      (ally ? allies : enemies)++;
      EXPECT_EQ(ai_difficulty(w, s).aim_error, ally ? ai.allies->aim_error : ai[size_t(d)].aim_error) << s.name << " " << d;
    }
    EXPECT_GT(allies, 0);
    EXPECT_GT(enemies, 0);
  }
}

TEST(Ai, HarderDifficultyAimsTighterAndReactsFaster) {
  const AiDifficultyTable ai = load_ai_difficulties(arc::data_root());
  EXPECT_GT(ai[0].aim_error, ai[1].aim_error);
  EXPECT_GT(ai[1].aim_error, ai[2].aim_error);
  EXPECT_GT(ai[0].reaction_s, ai[2].reaction_s);
  EXPECT_LT(ai[0].aggression, ai[2].aggression);
}

}  // namespace
}  // namespace arc
