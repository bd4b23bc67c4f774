// The pace of a fight, measured: sustained fire from one Viper kills another at 200 m in
// 10–20 s, hits landed in separate passes add up to the kill (the shield waits out the lulls
// between passes), and missiles fired at a pilot who evades and drops flares miss often.
// Missiles home only with a lock, flares decoy them, AI pilots drop flares, and the player
// starts with the nearest hostile targeted. The
// figures are printed (and recorded as test properties); the test pilot's duel figures per
// weapon are
//
//   ./build/test_game --gtest_filter='Pacing.*'
//   ./build/test_game --gtest_also_run_disabled_tests --gtest_filter='Pacing.DISABLED_PilotReport'
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "game/sim/seekers.h"
#include "game/sim/world.h"
#include "test_helpers.h"
#include "test_pilot.h"

namespace arc {
namespace {

using test::level_text;
using test::options;
using test::write_level;

// A Viper at the origin facing −Z (the player) and a Viper that neither moves nor fires,
// `distance` metres straight ahead.
Game shooter_and_drone(const std::string& name, double distance) {
  const std::string ships = R"({ "name": "Shooter", "class": "viper", "team": "blue", "player": true },
    { "name": "Drone", "class": "viper", "team": "red", "ai": "none", "position": [0, 0, )" +
                            std::to_string(-distance) + "] }";
  return Game::load_level(write_level(name, level_text(ships)), options());
}

// Seconds until the drone at 200 m dies under `buttons` held from the first tick; −1 after 60 s.
double time_to_kill_200m(uint16_t buttons) {
  Game g = shooter_and_drone("pacing_ttk_" + std::to_string(buttons) + ".json", 200.0);
  const World& w = g.world();
  InputFrame fire;
  fire.buttons = buttons;
  g.step(InputFrame{}, {Command::TargetNearest});
  const int64_t start = w.tick;
  while (w.ships[1].alive && w.tick - start < int64_t(60.0 / w.dt)) g.step(fire);
  return w.ships[1].alive ? -1.0 : double(w.tick - start) * w.dt;
}

TEST(Pacing, SustainedFireKillsAFighterInTenToTwentySeconds) {
  const double beam = time_to_kill_200m(kFirePrimary);
  const double mixed = time_to_kill_200m(kFirePrimary | kFireSecondary);
  std::printf("time to kill a Viper at 200 m: beam %.2f s, beam and missiles %.2f s\n", beam, mixed);
  RecordProperty("ttk_200_beam_s", std::to_string(beam));
  RecordProperty("ttk_200_mixed_s", std::to_string(mixed));
  EXPECT_GE(beam, 10.0);
  EXPECT_LE(beam, 20.0);
  EXPECT_GE(mixed, 10.0);
  EXPECT_LE(mixed, 20.0);
}

// Passes of a dogfight: 3 s on the target, 8 s away. The shield never climbs back between
// passes, so the damage it takes to kill is the drone's health and nothing more.
TEST(Pacing, HitsInSeparatePassesAddUpToTheKill) {
  Game g = shooter_and_drone("pacing_passes.json", 200.0);
  const World& w = g.world();
  const Ship& drone = w.ships[1];
  const double health = drone.shield + drone.hull;
  InputFrame fire;
  fire.buttons = kFirePrimary;
  double lowest = drone.shield;
  bool recharged = false;
  for (int64_t i = 0; drone.alive && i < int64_t(120.0 / w.dt); ++i) {
    const bool on = (i * w.dt) - 11.0 * std::floor(i * w.dt / 11.0) < 3.0;
    g.step(on ? fire : InputFrame{});
    recharged = recharged || drone.shield > lowest;
    lowest = std::min(lowest, drone.shield);
  }
  std::printf("passes of 3 s every 11 s: killed %s after %.1f s, %.0f damage dealt for %.0f health\n",
              drone.alive ? "no" : "yes", double(w.tick) * w.dt, w.ships[0].stats.damage_dealt, health);
  EXPECT_FALSE(drone.alive);
  EXPECT_FALSE(recharged) << "the shield recharged between passes";
  EXPECT_LE(w.ships[0].stats.damage_dealt, health + 1e-6);
}

struct MissileTally {
  int64_t fired = 0, hit = 0, flares = 0;
};

// Two AI Vipers fighting for `seconds`: the missiles either fired (plasma bolts left out), how
// many struck a ship, and the flares dropped. A missile struck when it ended inside a ship's
// hit sphere grown by its last tick of flight.
MissileTally ai_duel_missiles(uint64_t seed, double seconds) {
  const std::string ships = R"({ "name": "Blue", "class": "viper", "team": "blue", "position": [0, 0, 0] },
    { "name": "Red", "class": "viper", "team": "red", "position": [60, 20, -1200], "orientation": [180, 0, 0] })";
  GameOptions o = options();
  o.seed_override = true;
  o.seed = seed;
  Game g = Game::load_level(write_level("pacing_ai_duel.json", level_text(ships)), o);
  const World& w = g.world();
  MissileTally t;
  std::vector<Projectile> before;
  while (w.tick < int64_t(seconds / w.dt) && w.ships[0].alive && w.ships[1].alive) {
    g.step(InputFrame{});
    for (const Projectile& p : before) {
      if (p.kind != SecondaryWeapon::Missile || p.decoy != 0) continue;  // a decoyed one bursts on its flare
      const bool live = std::any_of(w.projectiles.begin(), w.projectiles.end(),
                                    [&](const Projectile& q) { return q.serial == p.serial; });
      if (live) continue;
      for (const Ship& s : w.ships) {
        const double reach = s.cls->shield_radius + p.hit_radius + glm::length(p.velocity) * w.dt * 1.5;
        if (s.id != p.owner && glm::length(s.position - p.position) < reach) {
          ++t.hit;
          break;
        }
      }
    }
    for (const Projectile& p : w.projectiles) {
      const bool fresh = std::none_of(before.begin(), before.end(), [&](const Projectile& q) { return q.serial == p.serial; });
      if (fresh && p.kind == SecondaryWeapon::Missile) ++t.fired;
    }
    before = w.projectiles;
  }
  for (const Ship& s : w.ships) t.flares += s.cls->countermeasures.count - s.seeker.flares;
  return t;
}

TEST(Pacing, MissilesOftenMissAPilotWhoEvadesAndDropsFlares) {
  MissileTally all;
  for (uint64_t seed = 1; seed <= 16; ++seed) {
    const MissileTally t = ai_duel_missiles(seed, 120.0);
    all.fired += t.fired;
    all.hit += t.hit;
    all.flares += t.flares;
  }
  const double acc = accuracy(all.hit, all.fired);
  std::printf("AI against AI, 16 duels: %lld missiles, %lld hits, accuracy %.0f %%, %lld flares\n", (long long)all.fired,
              (long long)all.hit, 100.0 * acc, (long long)all.flares);
  RecordProperty("ai_missile_accuracy", std::to_string(acc));
  EXPECT_GE(all.fired, 20);
  EXPECT_LT(acc, 0.7);
  EXPECT_GT(all.flares, 0);
}

// A shooter at the origin and a drone at `x`, 0, `z` (the shooter targets it at launch).
Game pair_at(const std::string& name, double x, double z, const std::string& drone_ai = "none") {
  const std::string ships = R"({ "name": "Shooter", "class": "viper", "team": "blue", "player": true },
    { "name": "Drone", "class": "viper", "team": "red", "ai": ")" + drone_ai + R"(", "position": [)" +
                            std::to_string(x) + ", 0, " + std::to_string(z) + "] }";
  return Game::load_level(write_level(name, level_text(ships)), options());
}

InputFrame press(uint16_t b) {
  InputFrame f;
  f.buttons = b;
  return f;
}

TEST(Lock, ThePlayerStartsWithTheNearestHostileTargeted) {
  Game g = Game::load_level(arc::data_root() + "/levels/duel.json", options());
  const World& w = g.world();
  ASSERT_TRUE(w.player);
  EXPECT_EQ(w.ship(w.player).target, w.ships[1].id);
  const std::string ships = R"({ "name": "P", "class": "viper", "team": "blue", "player": true },
    { "name": "Far", "class": "viper", "team": "red", "ai": "none", "position": [0, 0, -900] },
    { "name": "Friend", "class": "viper", "team": "blue", "ai": "none", "position": [0, 0, -50] },
    { "name": "Near", "class": "viper", "team": "red", "ai": "none", "position": [300, 0, 0] })";
  Game g2 = Game::load_level(write_level("lock_launch_target.json", level_text(ships)), options());
  EXPECT_EQ(g2.world().ships[0].target, g2.world().ships[3].id);
}

// Held within the lock cone for the lock time, the missile leaves (the trigger held from the
// start) and homes; before the lock is complete nothing leaves.
TEST(Lock, AMissileLeavesOnlyWithACompleteLock) {
  Game g = pair_at("lock_needed.json", 30, -300);
  const World& w = g.world();
  const Ship& me = w.ships[0];
  ASSERT_EQ(me.target, w.ships[1].id);
  const int64_t needed = seconds_to_ticks(w, me.cls->missile.lock_time);
  while (w.tick < needed - 2) g.step(press(kFireSecondary));
  EXPECT_TRUE(w.projectiles.empty()) << "fired before the lock";
  EXPECT_FALSE(missile_locked(w, me));
  EXPECT_GT(lock_progress(w, me), 0.9);
  while (w.tick < needed + 2) g.step(press(kFireSecondary));
  EXPECT_TRUE(missile_locked(w, me));
  ASSERT_EQ(w.projectiles.size(), 1u);
  EXPECT_EQ(w.projectiles[0].target, w.ships[1].id);
}

TEST(Lock, NoLockOutsideTheConeOrRange) {
  Game wide = pair_at("lock_wide.json", 150, -300);  // 27 degrees off the nose
  for (int i = 0; i < 240; ++i) wide.step(InputFrame{});
  EXPECT_EQ(lock_progress(wide.world(), wide.world().ships[0]), 0.0);
  Game far = pair_at("lock_far.json", 0, -1500);
  for (int i = 0; i < 240; ++i) far.step(InputFrame{});
  EXPECT_EQ(lock_progress(far.world(), far.world().ships[0]), 0.0);
}

// Locks the shooter on the drone at once (the lock's rules are tested above).
void force_lock(World& w) {
  Ship& me = w.ships[0];
  me.seeker.lock_target = me.target;
  me.seeker.lock_ticks = seconds_to_ticks(w, me.cls->missile.lock_time);
}

// A flare dropped as the missile closes pulls it with the decoy chance; a pulled missile never
// hits. Over 24 shots both outcomes happen.
TEST(Flares, DecoyMissilesThatHaveThemInTheirSeekerCone) {
  int decoyed = 0, hit = 0;
  for (uint64_t seed = 1; seed <= 24; ++seed) {
    GameOptions o = options();
    o.seed_override = true;
    o.seed = seed;
    const std::string ships = R"({ "name": "Shooter", "class": "viper", "team": "blue", "player": true },
      { "name": "Drone", "class": "viper", "team": "red", "ai": "none", "position": [0, 0, -500] })";
    Game g = Game::load_level(write_level("flare_decoy.json", level_text(ships)), o);
    World& w = g.world_mut();
    force_lock(w);
    g.step(press(kFireSecondary));
    ASSERT_EQ(w.projectiles.size(), 1u);
    while (!w.projectiles.empty() && glm::length(w.projectiles[0].position - w.ships[1].position) > 150) g.step(InputFrame{});
    const int left = w.ships[1].seeker.flares;
    ASSERT_TRUE(drop_flare(w, w.ships[1]));
    EXPECT_FALSE(drop_flare(w, w.ships[1])) << "the cooldown";
    EXPECT_EQ(w.ships[1].seeker.flares, left - 1);
    const bool pulled = !w.projectiles.empty() && w.projectiles[0].decoy != 0;
    for (int i = 0; i < 300 && !w.projectiles.empty(); ++i) g.step(InputFrame{});
    decoyed += pulled;
    hit += int(w.ships[0].stats.missiles_hit);
    if (pulled) {
      EXPECT_EQ(w.ships[0].stats.missiles_hit, 0) << "seed " << seed;
    }
  }
  std::printf("flares against 24 locked missiles: %d decoyed, %d hit\n", decoyed, hit);
  EXPECT_GE(decoyed, 8);
  EXPECT_GE(hit, 3);
}

TEST(Flares, CountIsLimitedByTheClass) {
  Game g = pair_at("flare_count.json", 0, -500);
  World& w = g.world_mut();
  Ship& me = w.ships[0];
  const int count = me.cls->countermeasures.count;
  EXPECT_EQ(me.seeker.flares, count);
  int dropped = 0;
  for (int i = 0; i < 60 * 30; ++i) {
    const int before = me.seeker.flares;
    g.step(InputFrame{}, {Command::Countermeasure});
    dropped += before - me.seeker.flares;
  }
  EXPECT_EQ(dropped, count);
  EXPECT_EQ(me.seeker.flares, 0);
}

// An AI fighter with a locked missile coming at it drops flares.
TEST(Flares, AnAiPilotDropsThemAgainstAHomingMissile) {
  Game g = pair_at("flare_ai.json", 0, -700, "fighter");
  World& w = g.world_mut();
  force_lock(w);
  g.step(press(kFireSecondary));
  ASSERT_EQ(w.projectiles.size(), 1u);
  ASSERT_EQ(w.projectiles[0].target, w.ships[1].id);
  const int full = w.ships[1].seeker.flares;
  for (int i = 0; i < 600 && !w.projectiles.empty(); ++i) g.step(InputFrame{});
  EXPECT_LT(w.ships[1].seeker.flares, full);
}

// Per weapon: beam accuracy (ticks), missile and plasma accuracy (shots), and damage shares.
struct WeaponTally {
  double dealt = 0, missile_dmg = 0, plasma_dmg = 0;
  int64_t beam_shots = 0, beam_hits = 0, msl_shots = 0, msl_hits = 0, pls_shots = 0, pls_hits = 0;
  void add(const CombatStats& c) {
    dealt += c.damage_dealt, missile_dmg += c.missile_damage, plasma_dmg += c.plasma_damage;
    beam_shots += c.beam_ticks, beam_hits += c.beam_hit_ticks;
    msl_shots += c.missiles_fired - c.plasma_fired, msl_hits += c.missiles_hit - c.plasma_hit;
    pls_shots += c.plasma_fired, pls_hits += c.plasma_hit;
  }
  void print(const char* who) const {
    const double d = std::max(dealt, 1e-9);
    std::printf("  %-5s beam acc %3.0f %%, missile acc %3.0f %% (%lld), plasma acc %3.0f %% (%lld); damage: beam %3.0f %%, "
                "missiles %3.0f %%, plasma %3.0f %%\n",
                who, 100.0 * accuracy(beam_hits, beam_shots), 100.0 * accuracy(msl_hits, msl_shots), (long long)msl_shots,
                100.0 * accuracy(pls_hits, pls_shots), (long long)pls_shots, 100.0 * (dealt - missile_dmg - plasma_dmg) / d,
                100.0 * missile_dmg / d, 100.0 * plasma_dmg / d);
  }
};

// The test pilot against the AI in the duel, 20 seeds per difficulty: win rate, time to win,
// flares the AI dropped, and each side's weapons.
TEST(Pacing, DISABLED_PilotReport) {
  const char* const names[] = {"easy", "normal", "hard"};
  for (int d = 0; d < 3; ++d) {
    int wins = 0;
    double win_s = 0;
    int64_t flares = 0;
    WeaponTally pilot_w, ai_w;
    for (uint64_t seed = 1; seed <= 20; ++seed) {
      Game g = load_flight(arc::data_root(), "levels/duel.json", d, seed);
      fly_to_outcome(g, seed, PilotKind::Person, 240.0);
      const World& w = g.world();
      if (w.outcome == Outcome::Victory) ++wins, win_s += double(w.outcome_tick) * w.dt;
      pilot_w.add(w.ships[0].stats);
      ai_w.add(w.ships[1].stats);
      flares += w.ships[1].cls->countermeasures.count - w.ships[1].seeker.flares;
    }
    std::printf("%-6s won %d/20, mean win %.1f s, AI flares %lld\n", names[d], wins, wins ? win_s / wins : 0.0,
                (long long)flares);
    pilot_w.print("pilot");
    ai_w.print("AI");
    std::fflush(stdout);
  }
}

}  // namespace
}  // namespace arc
