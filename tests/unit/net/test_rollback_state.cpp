// tests/unit/net/test_rollback_state.cpp — what a rollback keeps and compares: the per-tick hash
// covers what decides play (lightning channels) and not what only shows (particles of sparks,
// smoke, debris, shields, glows); saves and restores into kept worlds are exact; sounds of
// predicted ticks a rollback undoes are not heard twice.
#include <gtest/gtest.h>

#include <map>

#include "game/net/rollback.h"
#include "game/render/sound_events.h"
#include "game/sim/world.h"
#include "net_match_harness.h"
#include "particles/world_state.h"

namespace arc {
namespace {

// The arena battle at a tick where beams are firing and the sky is full of particles.
Game busy_arena(std::vector<SlotInput>& in) {
  Game g = Game::load_level("levels/arena.json", {});
  std::vector<bool> piloted(g.slot_count(), false);
  piloted[0] = true;
  g.set_pilots(piloted);
  in.assign(g.slot_count(), SlotInput{});
  in[0].input.throttle = 64;
  in[0].input.buttons = kFirePrimary;
  for (int t = 0; t < 600; ++t) g.step_slots(in);
  return g;
}

ParticleWorldState& particles_of(Game& g) { return ParticleWorldAccess::state(*g.world_mut().particles); }

bool beam_firing(const Game& g) {
  for (const Ship& s : g.world().ships)
    if (s.alive && !s.beam_channels.empty()) return true;
  return false;
}

// Every particle of every cluster but the lightning channels moved, resized and recoloured,
// birth state included: the hash and the play that follows are those of the untouched world.
TEST(NetRollbackState, CosmeticParticlesAreOutsideThePlayHash) {
  std::vector<SlotInput> in;
  Game a = busy_arena(in);
  ASSERT_TRUE(beam_firing(a));
  Game b(a);
  uint32_t touched = 0;
  for (Cluster& c : particles_of(b).slots) {
    if (!c.alive || c.def->animation == AnimationType::Lightning) continue;
    ParticlePool& p = c.pool;
    for (size_t k = 0; k < p.count(); ++k, ++touched) {
      p.px[k] += 40.f, p.p0x[k] -= 25.f, p.vy[k] *= 3.f;
      p.size[k] *= 2.f, p.size0[k] *= 0.5f, p.r[k] = 1.f - p.r[k], p.a[k] *= 0.25f;
    }
  }
  ASSERT_GT(touched, 1000u);
  EXPECT_NE(a.full_hash(), b.full_hash());  // the particles did change
  EXPECT_EQ(a.hash(), b.hash());
  for (int t = 0; t < 180; ++t) {
    a.step_slots(in);
    b.step_slots(in);
    ASSERT_EQ(a.hash(), b.hash()) << "tick " << t;
  }
  ASSERT_EQ(a.world().ships.size(), b.world().ships.size());
  for (size_t s = 0; s < a.world().ships.size(); ++s) {
    EXPECT_EQ(a.world().ships[s].position, b.world().ships[s].position);
    EXPECT_EQ(a.world().ships[s].hull, b.world().ships[s].hull);
    EXPECT_EQ(a.world().ships[s].alive, b.world().ships[s].alive);
  }
  EXPECT_EQ(a.summary_json(), b.summary_json());
}

// A lightning channel decides what a beam hits: a nudge to one shows in the hash at once.
TEST(NetRollbackState, LightningChannelsAreInThePlayHash) {
  std::vector<SlotInput> in;
  Game a = busy_arena(in);
  ASSERT_TRUE(beam_firing(a));
  for (const char* field : {"direction", "origin", "epoch", "cut"}) {
    Game b(a);
    bool nudged = false;
    for (Cluster& c : particles_of(b).slots) {
      if (!c.alive || c.def->animation != AnimationType::Lightning || nudged) continue;
      LightningChannel& l = c.lightning;
      const std::string f = field;
      if (f == "direction") l.direction.x += 1e-6;
      if (f == "origin") l.origin.y += 1e-6;
      if (f == "epoch") l.epoch += 1;
      if (f == "cut") l.cut = l.cut * 0.5 + 1.0;
      nudged = true;
    }
    ASSERT_TRUE(nudged) << field;
    EXPECT_NE(a.hash(), b.hash()) << field;
  }
}

// A kept world taking a later state and giving it back (the rollback's save and restore into
// memory it already holds) is exactly that state, particles included, and steps on as it would.
TEST(NetRollbackState, SaveAndRestoreIntoKeptWorldsAreExact) {
  std::vector<SlotInput> in;
  Game live = busy_arena(in);
  Game kept(live), plain(live);
  for (int t = 0; t < 20; ++t) live.step_slots(in);
  kept.copy_state_from(live);  // kept held an older, different battle
  EXPECT_EQ(kept.full_hash(), live.full_hash());
  for (int t = 0; t < 20; ++t) plain.step_slots(in);
  for (int t = 0; t < 8; ++t) live.step_slots(in);
  live.copy_state_from(kept);  // back 8 ticks
  EXPECT_EQ(live.full_hash(), plain.full_hash());
  for (int t = 0; t < 30; ++t) {
    live.step_slots(in);
    plain.step_slots(in);
  }
  EXPECT_EQ(live.full_hash(), plain.full_hash());
  EXPECT_EQ(live.state_dump(), plain.state_dump());
}

// Inputs of the second pilot arriving 7 ticks late roll the arena battle back again and again;
// what is heard is read from the presented world after each advance, so a launch or hit of a
// tick that was stepped, undone and stepped again sounds once.
TEST(NetRollbackState, SoundsOfUndoneTicksAreNotHeardTwice) {
  const Game start = Game::load_level("levels/arena.json", {});
  const int slots = int(start.slot_count());
  std::vector<bool> piloted(size_t(slots), false);
  piloted[0] = piloted[1] = true;
  RollbackSession s(Game(start), {slots, 0, 0, 12, piloted});
  Game plain(start);
  plain.set_pilots(piloted);
  SoundEventTracker rolled_ear, plain_ear;
  std::map<uint64_t, int> launches;  // projectile owner → launch sounds heard
  std::map<SoundKind, int> rolled, heard;  // one-shot sounds by kind
  const int ticks = 600, lag = 7;
  for (int t = 1; t <= ticks + lag; ++t) {
    if (t <= ticks) {
      s.add_local_input(nettest::scripted_input(0, t));
      s.advance();
      std::vector<SlotInput> in(static_cast<size_t>(slots));
      in[0] = nettest::scripted_input(0, t), in[1] = nettest::scripted_input(1, t);
      plain.step_slots(in);
      for (const SoundEvent& e : plain_ear.collect(plain.world()))
        if (!is_loop(e.kind)) ++heard[e.kind];
    }
    if (t - lag >= 1) s.add_remote_input(1, t - lag, nettest::scripted_input(1, t - lag));
    if (t > ticks) s.settle();
    for (const SoundEvent& e : rolled_ear.collect(s.game().world())) {
      if (e.kind == SoundKind::MissileLaunch || e.kind == SoundKind::PlasmaShot) ++launches[e.owner];
      if (!is_loop(e.kind)) ++rolled[e.kind];
    }
  }
  EXPECT_GT(s.stats().rollbacks, 50u);
  EXPECT_EQ(s.hash_at(ticks), plain.hash());
  ASSERT_GT(heard[SoundKind::BeamHitShield], 0);
  ASSERT_GT(heard[SoundKind::MissileLaunch] + heard[SoundKind::PlasmaShot], 0);
  for (const auto& [owner, n] : launches) EXPECT_EQ(n, 1) << "projectile " << (owner & 0xffffffffu);
  // Heard as often as in the run that knew every input at once (a sound of a misprediction
  // may add one, a real one that took its place is not repeated).
  for (const auto& [kind, n] : heard) {
    EXPECT_LE(rolled[kind], n + 2) << sound_kind_name(kind);
    EXPECT_GE(rolled[kind], n - 2) << sound_kind_name(kind);
  }
}

}  // namespace
}  // namespace arc
