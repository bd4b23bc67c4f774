#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <type_traits>

#include "core/error.h"
#include "core/rng.h"
#include "game/sim/world.h"
#include <glm/geometric.hpp>
#include "test_helpers.h"

namespace arc {
namespace {

using test::options;
using test::repo;

// The game's references are typed ids (game/sim/ids.h, particles/particle_ids.h): a team, a
// model slot, a particle owner or a bare int given where a ship is meant does not compile.
static_assert(!std::is_constructible_v<ShipId, TeamId>);
static_assert(!std::is_constructible_v<ShipId, int>);
static_assert(!std::is_constructible_v<TeamId, ShipId>);
static_assert(!std::is_constructible_v<ModelSlot, ShipId>);
static_assert(!std::is_constructible_v<OwnerId, ShipId>);
static_assert(!std::is_constructible_v<EffectId, OwnerId>);
static_assert(!std::is_assignable_v<decltype(Ship::target)&, int>);
static_assert(!std::is_assignable_v<decltype(Projectile::owner)&, OwnerId>);
static_assert(std::is_same_v<decltype(SpawnParams::owner), OwnerId>);

// A scripted pilot: input is a pure function of the tick, so two runs see the same inputs.
InputFrame scripted(uint64_t tick) {
  Rng r{99, 1, tick / 20};
  InputFrame f;
  f.pitch = quantise_axis(r.uniform(0) * 2 - 1);
  f.yaw = quantise_axis(r.uniform(1) * 2 - 1);
  f.roll = quantise_axis(r.uniform(2) - 0.5);
  f.throttle = quantise_axis(r.uniform(3));
  if (r.uniform(4) < 0.5) f.buttons |= kFirePrimary;
  if (r.uniform(5) < 0.2) f.buttons |= kFireSecondary;
  if (r.uniform(6) < 0.1) f.buttons |= kAfterburner;
  return f;
}

std::vector<Command> commands_at(uint64_t tick) {
  if (tick % 97 == 5) return {Command::TargetNextHostile};
  if (tick % 151 == 7) return {Command::SwitchWeapon};
  if (tick % 211 == 3) return {Command::CameraToggle};
  return {};
}

TEST(Determinism, TwoRunsHaveTheSameHashEveryTick) {
  Game a = Game::load_level(repo("levels/skirmish.json"), options());
  Game b = Game::load_level(repo("levels/skirmish.json"), options());
  ASSERT_EQ(a.hash(), b.hash());
  for (uint64_t t = 0; t < 600; ++t) {
    a.step(scripted(t), commands_at(t));
    b.step(scripted(t), commands_at(t));
    ASSERT_EQ(a.hash(), b.hash()) << "tick " << a.tick();
  }
  EXPECT_EQ(a.full_hash(), b.full_hash());
  EXPECT_EQ(a.state_dump(), b.state_dump());
}

TEST(Determinism, DifferentSeedOrInputChangesTheHash) {
  GameOptions o = options();
  o.seed_override = true;
  o.seed = 12345;
  Game a = Game::load_level(repo("levels/skirmish.json"), options());
  Game b = Game::load_level(repo("levels/skirmish.json"), o);
  Game c = Game::load_level(repo("levels/skirmish.json"), options());
  for (uint64_t t = 0; t < 300; ++t) {
    a.step(scripted(t));
    b.step(scripted(t));
    c.step(t == 10 ? InputFrame{.yaw = 1} : scripted(t));
  }
  EXPECT_NE(a.hash(), b.hash());
  EXPECT_NE(a.hash(), c.hash());
}

TEST(Serialization, RestoreReproducesHashAndContinuesIdentically) {
  Game a = Game::load_level(repo("levels/skirmish.json"), options());
  for (uint64_t t = 0; t < 250; ++t) a.step(scripted(t), commands_at(t));
  std::vector<uint8_t> bytes = a.save();
  Game b = Game::restore(bytes, repo("levels/skirmish.json"), options());
  ASSERT_EQ(a.tick(), b.tick());
  ASSERT_EQ(a.hash(), b.hash());
  ASSERT_EQ(a.full_hash(), b.full_hash());
  for (uint64_t t = 250; t < 550; ++t) {
    a.step(scripted(t), commands_at(t));
    b.step(scripted(t), commands_at(t));
    ASSERT_EQ(a.hash(), b.hash()) << "tick " << a.tick();
  }
  EXPECT_EQ(a.summary_json(), b.summary_json());
}

TEST(Serialization, CorruptOrForeignSavesAreInputErrors) {
  Game a = Game::load_level(repo("levels/duel.json"), options());
  for (uint64_t t = 0; t < 50; ++t) a.step(scripted(t));
  std::vector<uint8_t> bytes = a.save();
  std::vector<uint8_t> cut(bytes.begin(), bytes.begin() + bytes.size() / 2);
  EXPECT_THROW(Game::restore(cut, repo("levels/duel.json"), options()), InputError);
  std::vector<uint8_t> bad = bytes;
  bad[0] ^= 0xFF;
  EXPECT_THROW(Game::restore(bad, repo("levels/duel.json"), options()), InputError);
  EXPECT_THROW(Game::restore(bytes, repo("levels/skirmish.json"), options()), InputError);
}

TEST(Serialization, CopyRunsBesideTheOriginal) {
  Game a = Game::load_level(repo("levels/duel.json"), options());
  for (uint64_t t = 0; t < 100; ++t) a.step(scripted(t));
  Game b = a;
  for (uint64_t t = 100; t < 400; ++t) {
    a.step(scripted(t));
    b.step(scripted(t));
    ASSERT_EQ(a.hash(), b.hash()) << "tick " << a.tick();
  }
  EXPECT_EQ(a.full_hash(), b.full_hash());
}

TEST(PlayerInput, DrivesThePlayerShipOnly) {
  Game g = Game::load_level(repo("levels/duel.json"), options());
  const World& w = g.world();
  InputFrame f;
  f.throttle = 127;
  f.yaw = 64;
  for (int i = 0; i < 60; ++i) g.step(f);
  EXPECT_EQ(w.ship(w.player).controls, f);
  EXPECT_GT(glm::length(w.ship(w.player).velocity), 10.0);
  EXPECT_GT(forward_of(w.ship(w.player).orientation).x, 0.1);
  EXPECT_NE(w.ships[1].controls, f);  // the enemy flies itself
}

TEST(Pause, PausedGameDoesNotAdvanceUntilResumed) {
  Game g = Game::load_level(repo("levels/duel.json"), options());
  g.step(InputFrame{}, {Command::Pause});
  EXPECT_TRUE(g.paused());
  const uint64_t h = g.hash();
  for (int i = 0; i < 10; ++i) g.step(scripted(i));
  EXPECT_EQ(g.tick(), 0u);
  EXPECT_EQ(g.hash(), h);
  g.step(InputFrame{}, {Command::Resume});
  EXPECT_FALSE(g.paused());
  EXPECT_EQ(g.tick(), 1u);
}

TEST(Targeting, NearestHostileNextHostileAndNext) {
  Game g = Game::load_level(repo("levels/skirmish.json"), options());
  const World& w = g.world();
  g.step(InputFrame{}, {Command::TargetNearest});
  EXPECT_EQ(w.ship(w.player).target, w.ships[3].id);  // Red 1, not a wingman, who is closer
  g.step(InputFrame{}, {Command::TargetNextHostile});
  EXPECT_EQ(w.ship(w.player).target, w.ships[4].id);
  // Next goes round every live ship, the wingmen included; the waiting waves (5 to 8) are
  // skipped, so after Red 2 it comes round to Alpha 2.
  g.step(InputFrame{}, {Command::TargetNext});
  EXPECT_EQ(w.ship(w.player).target, w.ships[1].id);
  g.step(InputFrame{}, {Command::TargetNext});
  EXPECT_EQ(w.ship(w.player).target, w.ships[2].id);
  g.step(InputFrame{}, {Command::TargetNext});
  EXPECT_EQ(w.ship(w.player).target, w.ships[3].id);
}

TEST(Summary, HasShipsTickWinnerAndParticleCounts) {
  Game g = Game::load_level(repo("levels/duel.json"), options());
  for (int i = 0; i < 30; ++i) g.step(InputFrame{});
  auto j = nlohmann::json::parse(g.summary_json());
  EXPECT_EQ(j["tick"], 30);
  ASSERT_EQ(j["ships"].size(), 2u);
  EXPECT_EQ(j["ships"][0]["name"], "Player");
  EXPECT_EQ(j["ships"][0]["class"], "viper");
  EXPECT_EQ(j["ships"][1]["team"], "red");
  EXPECT_TRUE(j["ships"][1]["alive"].get<bool>());
  EXPECT_TRUE(j["winner"].is_null());
  EXPECT_GT(j["particles"].get<int>(), 0);
  EXPECT_GT(j["clusters"].get<int>(), 0);
}

TEST(Outcome, PlayerDeathIsDefeat) {
  Game g = Game::load_level(repo("levels/duel.json"), options());
  World& w = g.world_mut();
  w.ship(w.player).hull = -1;
  g.step(InputFrame{});
  EXPECT_EQ(w.outcome, Outcome::Defeat);
  EXPECT_EQ(w.team_name(w.winner), "red");
}

// Seed 0 means the level's own seed; the others check the outcome does not hinge on one seed.
class AttractOutcome : public ::testing::TestWithParam<uint64_t> {};

TEST_P(AttractOutcome, IsDecidedWithinFiveMinutesOfGameTime) {
  GameOptions o = options();
  o.seed_override = GetParam() != 0;
  o.seed = GetParam();
  Game g = Game::load_level(repo("levels/attract.json"), o);
  const World& w = g.world();
  const uint64_t limit = 5 * 60 * 60;
  while (w.outcome == Outcome::Undecided && g.tick() < limit) g.step(InputFrame{});
  EXPECT_EQ(w.outcome, Outcome::TeamWon) << g.state_dump();
  EXPECT_TRUE(w.team_name(w.winner) == "blue" || w.team_name(w.winner) == "red") << w.team_name(w.winner);
  auto j = nlohmann::json::parse(g.summary_json());
  EXPECT_EQ(j["winner"], w.team_name(w.winner));
  EXPECT_EQ(j["decided_tick"], w.outcome_tick);
  RecordProperty("decided_tick", std::to_string(g.tick()));
}

INSTANTIATE_TEST_SUITE_P(Seeds, AttractOutcome, ::testing::Values(0, 1, 2, 3, 4));

}  // namespace
}  // namespace arc

namespace arc {
namespace {

TEST(Ai, FightersUseBothWeaponsEvadeAndBreakOff) {
  Game g = Game::load_level(test::repo("levels/arena.json"), test::options());
  const World& w = g.world();
  bool beam = false, missile = false, plasma = false, evade = false, break_off = false;
  for (int t = 0; t < 60 * 60 && w.outcome == Outcome::Undecided; ++t) {
    g.step(InputFrame{});
    for (const Ship& s : w.ships) {
      beam = beam || (s.ai == AiKind::Fighter && s.beam_firing);
      evade = evade || s.ai_state.mode == AiMode::Evade;
      break_off = break_off || s.ai_state.mode == AiMode::BreakOff;
    }
    for (const Projectile& p : w.projectiles) {
      if (w.ship(p.owner).ai != AiKind::Fighter) continue;
      missile = missile || p.kind == SecondaryWeapon::Missile;
      plasma = plasma || p.kind == SecondaryWeapon::Plasma;
    }
  }
  EXPECT_TRUE(beam);
  EXPECT_TRUE(missile);
  EXPECT_TRUE(plasma);
  EXPECT_TRUE(evade);
  EXPECT_TRUE(break_off);
}

}  // namespace
}  // namespace arc
