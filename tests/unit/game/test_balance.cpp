// Balance: an idle player lives long enough to react, an attacking player can win the duel, and
// easy is the gentlest. The figures come from whole headless fights (no rendering), so
// they stay loose bounds; the report below prints the full table for tuning:
//
//   ./build/test_game --gtest_also_run_disabled_tests --gtest_filter='Balance.DISABLED_Report'
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

using test::options;
using test::repo;

Game load(const std::string& level, int difficulty, uint64_t seed) {
  GameOptions o = options();
  o.difficulty_override = true;
  o.difficulty = static_cast<Difficulty>(difficulty);
  o.seed_override = seed != 0;
  o.seed = seed;
  return Game::load_level(repo(level), o);
}

ShipId ship_named(const World& w, const std::string& name) {
  for (const Ship& s : w.ships)
    if (s.name == name) return s.id;
  return {};
}

// A simple scripted pilot: turn the nose toward the nearest hostile (leading it a little), close
// to beam range (afterburner when far), hold the beam while the target is in a narrow cone, loose
// missiles when lined up. step_pursuit() also locks the nearest hostile so the missiles home.
InputFrame pursue(const World& w) {
  InputFrame f;
  const Ship& me = w.ship(w.player);
  ShipId target;
  double best = 0;
  for (const Ship& s : w.ships) {
    if (!s.alive || !w.hostile(me, s)) continue;
    double d = glm::length(s.position - me.position);
    if (!target || d < best) target = s.id, best = d;
  }
  if (!target) return f;
  const Ship& t = w.ship(target);
  const glm::dvec3 rel = t.position - me.position;
  const double dist = glm::length(rel);
  const glm::dvec3 aim = t.position + (t.velocity - me.velocity) * (dist / 600.0);
  const glm::dvec3 local = glm::conjugate(me.orientation) * glm::normalize(aim - me.position);
  const double yaw = std::atan2(local.x, -local.z);
  const double pitch = std::atan2(local.y, std::sqrt(local.x * local.x + local.z * local.z));
  f.yaw = quantise_axis(3.0 * yaw);
  f.pitch = quantise_axis(3.0 * pitch);
  f.roll = quantise_axis(-0.3 * me.angular_velocity.z);
  f.throttle = quantise_axis(dist > 400 ? 1.0 : dist > 150 ? 0.6 : 0.3);
  if (dist > 450 && me.energy > 0.5 * me.cls->energy) f.buttons |= kAfterburner;
  const double off = std::acos(std::clamp(glm::dot(forward_of(me.orientation), rel / dist), -1.0, 1.0));
  const double cone = std::atan2(t.cls->shield_radius, dist) + 0.02;
  if (off < cone && dist < me.cls->beam.range) f.buttons |= kFirePrimary;
  if (off < 0.2 && dist < 1200) f.buttons |= kFireSecondary;
  return f;
}

struct FightStats {
  double player_death_s = -1;   // −1: alive at the end
  double wingman_death_s = -1;
  int wingman_kills = 0;
  int player_kills = 0;
  double decided_s = -1;
  double first_death_s = -1;
  int deaths = 0;
  double shield_beam_s = 0;  // summed over ships: seconds a beam stalled on a shield
  double end_s = 0;
};

void step_pursuit(Game& g) {
  const World& w = g.world();
  const Ship& me = w.ship(w.player);
  if (!me.alive) return g.step(InputFrame{});
  if (!me.target) return g.step(pursue(w), {Command::TargetNextHostile});
  g.step(pursue(w));
}

FightStats run(const std::string& level, int difficulty, uint64_t seed, double max_s, bool pursuit = false) {
  Game g = load(level, difficulty, seed);
  const World& w = g.world();
  FightStats st;
  const ShipId wing = ship_named(w, "Alpha 2");
  const int64_t limit = int64_t(max_s / w.dt);
  std::vector<bool> was_alive(w.ships.size(), true);
  while (int64_t(w.tick) < limit && w.outcome == Outcome::Undecided) {
    if (w.player && pursuit) step_pursuit(g);
    else g.step(InputFrame{});
    for (const Ship& s : w.ships) {
      if (s.alive && s.beam_firing && s.beam_target && w.ship(s.beam_target).shield > 0)
        st.shield_beam_s += w.dt;
      if (was_alive[s.id.index()] && !s.alive) {
        was_alive[s.id.index()] = false;
        ++st.deaths;
        if (st.first_death_s < 0) st.first_death_s = w.tick * w.dt;
      }
    }
  }
  st.end_s = w.tick * w.dt;
  if (w.player) {
    const Ship& p = w.ship(w.player);
    if (!p.alive) st.player_death_s = p.death_tick * w.dt;
    st.player_kills = p.kills;
  }
  if (wing) {
    if (!w.ship(wing).alive) st.wingman_death_s = w.ship(wing).death_tick * w.dt;
    st.wingman_kills = w.ship(wing).kills;
  }
  if (w.outcome != Outcome::Undecided) st.decided_s = w.outcome_tick * w.dt;
  return st;
}

// Alive at the end counts as the whole run.
double survived(double death_s, const FightStats& st) { return death_s < 0 ? st.end_s : death_s; }

const uint64_t kSeeds[] = {0, 11, 23, 37};

// An idle player on normal: long enough to see the enemy come, turn and fight back. Weapons pay
// off (test_weapon_payoff.cpp): the AI needs about 4 s to reach beam range and about 10 s
// of fire, so an idle Viper lasts about 16 s in the duel.
TEST(Balance, IdlePlayerHasTimeToReactOnNormal) {
  for (uint64_t seed : kSeeds) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    FightStats duel = run("levels/duel.json", 1, seed, 60);
    EXPECT_GE(survived(duel.player_death_s, duel), 14.0);
    FightStats sk = run("levels/skirmish.json", 1, seed, 40);
    EXPECT_GE(survived(sk.player_death_s, sk), 15.0);
    EXPECT_GE(survived(sk.wingman_death_s, sk), 10.0);
  }
}

// Mean survival of an idle duel player: longest on easy. Hard kills a sitting duck in about
// the arrival plus the weapons' time to kill; normal's wider aim error (assets/settings/ai.json)
// takes longer, yet well short of easy. How hard each is to beat shows against a pilot who
// fights back (test_pilot_duel.cpp, test_human_pilot.cpp).
TEST(Balance, EasyGivesAnIdleDuelPlayerTheLongest) {
  double mean[3] = {0, 0, 0};
  for (int d = 0; d < 3; ++d) {
    for (uint64_t seed : kSeeds) {
      FightStats st = run("levels/duel.json", d, seed, 150);
      mean[d] += survived(st.player_death_s, st) / std::size(kSeeds);
    }
  }
  EXPECT_GT(mean[0], 1.15 * mean[1]) << mean[0] << " " << mean[1];
  EXPECT_GT(mean[0], 1.25 * mean[2]) << mean[0] << " " << mean[2];
  EXPECT_GT(mean[1], mean[2]) << mean[1] << " " << mean[2];
  EXPECT_LT(mean[1], 40.0);
  EXPECT_LT(mean[2], 25.0);
}

class PursuitDuel : public ::testing::TestWithParam<int> {};

// A player who just chases and holds the trigger wins the duel on easy and normal.
TEST_P(PursuitDuel, AttackingPlayerWinsWithinTwoMinutes) {
  for (uint64_t seed : kSeeds) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    FightStats st = run("levels/duel.json", GetParam(), seed, 120, true);
    EXPECT_LT(st.player_death_s, 0.0);
    EXPECT_EQ(st.player_kills, 1);
    EXPECT_GT(st.decided_s, 0.0);
    RecordProperty("decided_s_" + std::to_string(seed), std::to_string(st.decided_s));
  }
}

INSTANTIATE_TEST_SUITE_P(EasyAndNormal, PursuitDuel, ::testing::Values(0, 1));

// The table behind the tuning: every fight level, difficulty and a few seeds.
TEST(Balance, DISABLED_Report) {
  const char* names[] = {"easy", "normal", "hard"};
  struct Case {
    const char* level;
    double max_s;
    bool pursuit;
  } cases[] = {{"levels/duel.json", 150, false},     {"levels/duel.json", 150, true},
               {"levels/skirmish.json", 150, false}, {"levels/skirmish.json", 150, true},
               {"levels/attract.json", 300, false},  {"levels/arena.json", 240, false}};
  for (const Case& c : cases) {
    for (int d = 0; d < 3; ++d) {
      std::printf("%-22s %-7s %-7s", c.level + 7, names[d], c.pursuit ? "pursue" : "idle");
      for (uint64_t seed : kSeeds) {
        FightStats st = run(c.level, d, seed, c.max_s, c.pursuit);
        std::printf(" | p%5.1f w%5.1f/%d k%d 1st%5.1f d%2d end%5.1f sb%4.0f", st.player_death_s, st.wingman_death_s,
                    st.wingman_kills, st.player_kills, st.first_death_s, st.deaths, st.decided_s, st.shield_beam_s);
      }
      std::printf("\n");
      std::fflush(stdout);
    }
  }
}

}  // namespace
}  // namespace arc

namespace arc {
namespace {
TEST(Balance, DISABLED_Trace) {
  const char* lv = std::getenv("TRACE_LEVEL");
  const int d = std::getenv("TRACE_DIFF") ? std::atoi(std::getenv("TRACE_DIFF")) : 1;
  const bool pursuit = std::getenv("TRACE_PURSUE") != nullptr;
  Game g = load(lv ? lv : "levels/duel.json", d, 0);
  const World& w = g.world();
  for (int t = 0; t < 60 * 90 && w.outcome == Outcome::Undecided; ++t) {
    if (pursuit) step_pursuit(g);
    else g.step(InputFrame{});
    if (t % 30) continue;
    std::printf("%5.1f", w.tick * w.dt);
    for (const Ship& s : w.ships)
      std::printf(" | %s h%3.0f s%3.0f e%3.0f m%d %c d%4.0f", s.name.substr(0, 6).c_str(), s.hull, s.shield, s.energy,
                  int(s.ai_state.mode), s.beam_firing ? (s.beam_target ? 'H' : 'B') : '-',
                  s.ai_state.target ? glm::length(w.ship(s.ai_state.target).position - s.position) : -1.0);
    std::printf("\n");
  }
}
}  // namespace
}  // namespace arc
