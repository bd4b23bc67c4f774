// Sound events read from the World: what each tick sounds like, without touching the
// simulation (its hash is the same with and without a tracker watching).
#include <gtest/gtest.h>

#include <algorithm>

#include "game/render/sound_events.h"
#include "game/sim/damage.h"
#include "test_helpers.h"

namespace arc {
namespace {

using test::level_text;
using test::options;
using test::write_level;

// The player's Viper at the origin facing −Z and a Viper drone 200 units straight ahead.
Game shooter_and_drone(const std::string& name) {
  const std::string ships = R"({ "name": "Shooter", "class": "viper", "team": "blue", "player": true },
    { "name": "Drone", "class": "viper", "team": "red", "ai": "none", "position": [0, 0, -200] })";
  return Game::load_level(write_level(name, level_text(ships)), options());
}

InputFrame buttons(uint16_t b) {
  InputFrame f;
  f.buttons = b;
  return f;
}

int count(const std::vector<SoundEvent>& events, SoundKind kind) {
  return int(std::count_if(events.begin(), events.end(), [&](const SoundEvent& e) { return e.kind == kind; }));
}

TEST(SoundEvents, BeamOnAShieldSoundsAtTheHitWhileItFires) {
  Game g = shooter_and_drone("sound_beam.json");
  SoundEventTracker tracker;
  int beam_ticks = 0, shield_hits = 0, hull_hits = 0;
  for (int t = 0; t < 60; ++t) {
    g.step(InputFrame{});
    auto events = tracker.collect(g.world());
    EXPECT_EQ(count(events, SoundKind::Beam), 0);
    EXPECT_EQ(count(events, SoundKind::EngineHum), 2) << "one hum per live ship";
  }
  for (int t = 0; t < 120; ++t) {
    g.step(buttons(kFirePrimary));
    auto events = tracker.collect(g.world());
    beam_ticks += count(events, SoundKind::Beam);
    shield_hits += count(events, SoundKind::BeamHitShield);
    hull_hits += count(events, SoundKind::BeamHitHull);
    for (const SoundEvent& e : events)
      if (e.kind == SoundKind::BeamHitShield) {
        EXPECT_EQ(e.owner, 2u);
        EXPECT_LT(e.position.z, -150.0) << "at the drone's shield, not at the shooter";
      }
  }
  EXPECT_EQ(beam_ticks, 120);
  EXPECT_GE(shield_hits, 10);
  EXPECT_LE(shield_hits + hull_hits, 120 / 6 + 1) << "hit sounds are spaced";
}

TEST(SoundEvents, MissilesLaunchOnceAndFlyAsLoops) {
  Game g = shooter_and_drone("sound_missile.json");
  SoundEventTracker tracker;
  tracker.collect(g.world());
  int launches = 0, flight = 0;
  // The trigger held through the lock time: the missile leaves once the lock completes.
  const int lock = int(std::llround(g.world().ships[0].cls->missile.lock_time / g.world().dt));
  for (int t = 0; t < lock + 30; ++t) {
    g.step(buttons(t <= lock ? kFireSecondary : 0));
    auto events = tracker.collect(g.world());
    launches += count(events, SoundKind::MissileLaunch);
    for (const SoundEvent& e : events)
      if (e.kind == SoundKind::MissileFlight) {
        ++flight;
        EXPECT_GT(glm::length(e.velocity), 1.0) << "moving, for Doppler";
        EXPECT_GT(e.owner, uint64_t(1) << 32);
      }
  }
  EXPECT_GE(launches, 1);
  EXPECT_GE(flight, 20);
}

// Holding the target in the lock cone: ticks that come faster, then a steady tone once locked.
TEST(SoundEvents, LockTicksSpeedUpThenATone) {
  Game g = shooter_and_drone("sound_lock.json");
  const World& w = g.world();
  SoundEventTracker tracker;
  tracker.collect(w);
  const int64_t needed = int64_t(std::llround(w.ships[0].cls->missile.lock_time / w.dt));
  std::vector<int64_t> ticks;
  int tones_before = 0, tones_after = 0, ticks_after = 0;
  for (int64_t t = 0; t < needed + 30; ++t) {
    g.step(InputFrame{});
    auto events = tracker.collect(w);
    for (const SoundEvent& e : events) {
      if (e.kind == SoundKind::LockTick) (w.tick <= needed ? ticks.push_back(w.tick) : void(++ticks_after));
      if (e.kind == SoundKind::LockTone) ++(w.tick < needed ? tones_before : tones_after);
    }
  }
  ASSERT_GE(ticks.size(), 5u);
  EXPECT_LT(ticks.back() - ticks[ticks.size() - 2], ticks[1] - ticks[0]) << "the ticks come faster";
  EXPECT_EQ(tones_before, 0);
  EXPECT_EQ(ticks_after, 0);
  EXPECT_GE(tones_after, 29);
  EXPECT_TRUE(is_loop(SoundKind::LockTone));
  EXPECT_STREQ(sound_kind_name(SoundKind::LockTick), "lock_tick");
}

TEST(SoundEvents, AFlareSoundsOnceWhereItIsDropped) {
  Game g = shooter_and_drone("sound_flare.json");
  SoundEventTracker tracker;
  tracker.collect(g.world());
  int flares = 0;
  for (int t = 0; t < 20; ++t) {
    g.step(InputFrame{}, {t == 0 ? Command::Countermeasure : Command::None});
    for (const SoundEvent& e : tracker.collect(g.world()))
      if (e.kind == SoundKind::Flare) {
        ++flares;
        EXPECT_LT(glm::length(e.position - g.world().ships[0].position), 30.0);
      }
  }
  EXPECT_EQ(flares, 1);
}

TEST(SoundEvents, AnExplosionIsScaledByTheBlast) {
  Game g = shooter_and_drone("sound_boom.json");
  SoundEventTracker tracker;
  g.step(InputFrame{});
  tracker.collect(g.world());
  World& w = g.world_mut();
  apply_damage(w, w.ships[1], 1e6, w.ships[1].position, w.ships[0].id);
  g.step(InputFrame{});
  auto events = tracker.collect(g.world());
  ASSERT_EQ(count(events, SoundKind::Explosion), 1);
  for (const SoundEvent& e : events)
    if (e.kind == SoundKind::Explosion) {
      EXPECT_NEAR(e.size, w.ships[1].cls->collision_radius * 6.0, 1e-9);
      EXPECT_LT(e.position.z, -150.0);
    }
  EXPECT_EQ(count(events, SoundKind::EngineHum), 1) << "the dead ship's engine is silent";
}

// A tracker reads the World and never writes it: the per-tick hashes are the same.
TEST(SoundEvents, WatchingDoesNotChangeTheHash) {
  Game a = shooter_and_drone("sound_hash_a.json"), b = shooter_and_drone("sound_hash_b.json");
  SoundEventTracker tracker;
  for (int t = 0; t < 240; ++t) {
    const InputFrame f = buttons(t % 90 < 60 ? kFirePrimary : kFireSecondary);
    a.step(f);
    b.step(f);
    tracker.collect(b.world());
    ASSERT_EQ(a.hash(), b.hash()) << "tick " << t;
  }
}

// A new game (tick back to the start) lists its loops but no one-shots from the change.
TEST(SoundEvents, ARestartIsNotABattle) {
  Game g = shooter_and_drone("sound_restart.json");
  SoundEventTracker tracker;
  for (int t = 0; t < 30; ++t) g.step(buttons(kFireSecondary)), tracker.collect(g.world());
  Game fresh = shooter_and_drone("sound_restart.json");
  fresh.step(InputFrame{});
  for (const SoundEvent& e : tracker.collect(fresh.world())) EXPECT_TRUE(is_loop(e.kind)) << sound_kind_name(e.kind);
}

}  // namespace
}  // namespace arc
