// Combat measured, not felt: the beam held dead on a stationary ship deals its nominal damage
// over its whole stated range, a non-firing Viper at 300 m dies in 10–20 s, and a shield under
// sustained missile fire does not recover between hits. The figures are printed as test
// properties (and on stdout) so a tuning change shows its effect:
//
//   ./build/test_game --gtest_filter='WeaponPayoff.*'
#include <cstdio>
#include <string>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

using test::level_text;
using test::options;
using test::write_level;

// A Viper at the origin facing −Z (the player) and a Viper that neither moves nor fires,
// `distance` metres straight ahead (centre to centre).
Game shooter_and_drone(double distance) {
  const std::string ships = R"({ "name": "Shooter", "class": "viper", "team": "blue", "player": true },
    { "name": "Drone", "class": "viper", "team": "red", "ai": "none", "position": [0, 0, )" +
                            std::to_string(-distance) + "] }";
  return Game::load_level(write_level("payoff_" + std::to_string(int(distance)) + ".json", level_text(ships)),
                          options());
}

double health(const Ship& s) { return s.alive ? s.shield + s.hull : 0.0; }

// Share of the beam's nominal damage (damage_per_second × time) the drone takes in 5 s of fire.
double beam_damage_fraction(double distance) {
  Game g = shooter_and_drone(distance);
  const World& w = g.world();
  const double before = health(w.ships[1]);
  InputFrame fire;
  fire.buttons = kFirePrimary;
  const int ticks = int(5.0 / w.dt);
  for (int i = 0; i < ticks; ++i) g.step(fire);
  return (before - health(w.ships[1])) / (w.ships[0].cls->beam.damage_per_second * ticks * w.dt);
}

// Seconds until the drone dies with the beam held on it (and missiles when `missiles`: they
// fly straight at it until the lock completes, then home); −1 if it survives a minute.
double time_to_kill(double distance, bool missiles) {
  Game g = shooter_and_drone(distance);
  const World& w = g.world();
  g.step(InputFrame{}, {Command::TargetNextHostile});
  InputFrame fire;
  fire.buttons = kFirePrimary | (missiles ? kFireSecondary : 0);
  const int64_t start = w.tick;
  while (w.ships[1].alive && w.tick - start < int64_t(60.0 / w.dt)) g.step(fire);
  return w.ships[1].alive ? -1.0 : double(w.tick - start) * w.dt;
}

TEST(WeaponPayoff, BeamDealsItsNominalDamageOverItsStatedRange) {
  for (double d : {100.0, 300.0, 500.0, 600.0}) {
    const double f = beam_damage_fraction(d);
    std::printf("beam damage fraction at %.0f m: %.3f\n", d, f);
    RecordProperty("beam_fraction_" + std::to_string(int(d)), std::to_string(f));
    EXPECT_GE(f, 0.95) << "at " << d << " m";
    EXPECT_LE(f, 1.0 + 1e-9) << "at " << d << " m";
  }
}

TEST(WeaponPayoff, BeamStopsAtItsStatedRange) {
  Game g = shooter_and_drone(100);
  const double range = g.world().ships[0].cls->beam.range;
  const double shield_radius = g.world().ships[1].cls->shield_radius;
  // Shield sphere's front 30 m beyond the range: nothing; 30 m inside it: full damage.
  EXPECT_LT(beam_damage_fraction(range + shield_radius + 30.0), 0.01);
  EXPECT_GE(beam_damage_fraction(range + shield_radius - 30.0), 0.95);
}

// Every class's channel (assets/effects/lightning_beam.json) reaches the class's range and
// stays within a few metres of its aim line, so the bolt is where the damage goes.
TEST(WeaponPayoff, EveryClassesChannelReachesItsRangeAlongTheAimLine) {
  for (const char* cls : {"dart", "viper", "warden"}) {
    SCOPED_TRACE(cls);
    const std::string ships = std::string(R"({ "name": "Shooter", "class": ")") + cls +
                              R"(", "team": "blue", "player": true, "orientation": [30, 10, 0] })";
    Game g = Game::load_level(write_level(std::string("reach_") + cls + ".json", level_text(ships)), options());
    const World& w = g.world();
    const Ship& s = w.ships[0];
    InputFrame fire;
    fire.buttons = kFirePrimary;
    double widest = 0, shortest = 1e300;
    for (int i = 0; i < 120; ++i) {
      g.step(fire);
      const glm::dvec3 aim = forward_of(s.orientation);
      for (ClusterHandle ch : s.beam_channels) {
        const std::vector<glm::dvec3> pts = w.particles->lightning_points(ch);
        ASSERT_GE(pts.size(), 2u);
        for (const glm::dvec3& p : pts) {
          const glm::dvec3 rel = p - pts[0];
          widest = std::max(widest, glm::length(rel - aim * glm::dot(rel, aim)));
        }
        shortest = std::min(shortest, glm::dot(pts.back() - pts[0], aim));
      }
    }
    std::printf("%s channel: reaches %.0f m ahead (range %.0f m), at most %.2f m off the aim line\n", cls, shortest,
                s.cls->beam.range, widest);
    EXPECT_GE(shortest, s.cls->beam.range);
    EXPECT_LE(widest, 6.0);
  }
}

TEST(WeaponPayoff, NonFiringViperAt300mDiesInTenToTwentySeconds) {
  for (bool missiles : {false, true}) {
    const double ttk = time_to_kill(300.0, missiles);
    const std::string what = missiles ? "beam and missiles" : "beam";
    std::printf("time to kill at 300 m, %s: %.2f s\n", what.c_str(), ttk);
    RecordProperty(missiles ? "ttk_300_beam_missiles_s" : "ttk_300_beam_s", std::to_string(ttk));
    EXPECT_GE(ttk, 10.0) << what;
    EXPECT_LE(ttk, 20.0) << what;
  }
}

// Missiles alone, one every cooldown: the shield must not recharge between hits.
TEST(WeaponPayoff, ShieldDoesNotRecoverBetweenMissileHits) {
  Game g = shooter_and_drone(300.0);
  const World& w = g.world();
  g.step(InputFrame{}, {Command::TargetNextHostile});
  InputFrame fire;
  fire.buttons = kFireSecondary;
  double lowest = w.ships[1].shield;
  int64_t recharged_at = -1;
  for (int i = 0; i < int(20.0 / w.dt) && w.ships[1].alive; ++i) {
    g.step(fire);
    if (w.ships[1].shield > lowest && recharged_at < 0) recharged_at = w.tick;
    lowest = std::min(lowest, w.ships[1].shield);
  }
  std::printf("missiles alone at 300 m: shield %.0f of %.0f after 20 s\n", w.ships[1].shield, w.ships[1].cls->shield);
  EXPECT_EQ(recharged_at, -1) << "the shield recharged between hits";
  EXPECT_LT(lowest, w.ships[1].cls->shield * 0.5);
}

}  // namespace
}  // namespace arc
