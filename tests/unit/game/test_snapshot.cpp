// Game snapshots (game/sim/serialize.h): a restored game is the same game, a damaged snapshot
// is an InputError and never a crash, and the cheap per-tick hash is cheap.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "core/error.h"
#include "core/hash.h"
#include "core/rng.h"
#include "game/sim/world.h"
#include "core/snapshot_io.h"
#include "test_helpers.h"

namespace arc {
namespace {

using test::options;
using test::repo;

// Input is a pure function of the tick, so the original and the restored game see the same.
InputFrame pilot(uint64_t tick) {
  Rng r{7, 3, tick / 30};
  InputFrame f;
  f.pitch = quantise_axis(r.uniform(0) * 2 - 1);
  f.yaw = quantise_axis(r.uniform(1) * 2 - 1);
  f.throttle = quantise_axis(r.uniform(2));
  if (r.uniform(3) < 0.6) f.buttons |= kFirePrimary;
  if (r.uniform(4) < 0.3) f.buttons |= kFireSecondary;
  return f;
}

std::vector<Command> commands(uint64_t tick) {
  if (tick % 101 == 4) return {Command::TargetNextHostile};
  if (tick % 173 == 9) return {Command::SwitchWeapon};
  return {};
}

// Saves at each of `save_ticks`, restores, and runs original and copy `after` more ticks:
// hash() and full_hash() must agree on every tick.
void check_round_trips(const std::string& level, std::vector<uint64_t> save_ticks, uint64_t after) {
  Game a = Game::load_level(repo(level), options());
  uint64_t t = 0;
  for (uint64_t save_at : save_ticks) {
    for (; t < save_at; ++t) a.step(pilot(t), commands(t));
    const std::vector<uint8_t> bytes = a.save();
    Game b = Game::restore(bytes, repo(level), options());
    ASSERT_EQ(b.save(), bytes) << level << ": a restored game saves the same bytes (tick " << save_at << ")";
    ASSERT_EQ(a.hash(), b.hash()) << level << " restored at tick " << save_at;
    ASSERT_EQ(a.full_hash(), b.full_hash()) << level << " restored at tick " << save_at;
    Game ref = a;  // the original continues from its own copy, so the next save point is unchanged
    for (uint64_t k = 0; k < after; ++k) {
      ref.step(pilot(t + k), commands(t + k));
      b.step(pilot(t + k), commands(t + k));
      ASSERT_EQ(ref.hash(), b.hash()) << level << " restored at tick " << save_at << ", step " << k + 1;
      ASSERT_EQ(ref.full_hash(), b.full_hash()) << level << " restored at tick " << save_at << ", step " << k + 1;
    }
    EXPECT_EQ(ref.state_dump(), b.state_dump());
    EXPECT_EQ(ref.summary_json(), b.summary_json());
  }
}

TEST(Snapshot, ArenaRestoredAtSeveralTicksRunsIdentically) {
  check_round_trips("levels/arena.json", {0, 1, 240, 900}, 600);
}

TEST(Snapshot, AttractRestoredAtSeveralTicksRunsIdentically) {
  check_round_trips("levels/attract.json", {0, 7, 600, 1500}, 600);
}

TEST(Snapshot, PausedGameRestoresPausedWithItsStepCount) {
  Game a = Game::load_level(repo("levels/duel.json"), options());
  for (uint64_t t = 0; t < 30; ++t) a.step(pilot(t));
  a.step(InputFrame{}, {Command::Pause});
  Game b = Game::restore(a.save(), repo("levels/duel.json"), options());
  EXPECT_TRUE(b.paused());
  EXPECT_EQ(b.world().steps, a.world().steps);
  EXPECT_EQ(b.full_hash(), a.full_hash());
}

TEST(Snapshot, SeedDifficultyAndSettingsComeFromTheSnapshot) {
  GameOptions o = options();
  o.seed_override = true;
  o.seed = 4242;
  o.difficulty_override = true;
  o.difficulty = Difficulty::Hard;
  o.particle_budget = 50000;
  o.lightning_interval = 2;
  o.substeps = 2;
  Game a = Game::load_level(repo("levels/duel.json"), o);
  for (uint64_t t = 0; t < 120; ++t) a.step(pilot(t));
  Game b = Game::restore(a.save(), repo("levels/duel.json"), options());  // default options here
  EXPECT_EQ(b.world().seed, 4242u);
  EXPECT_EQ(b.world().difficulty, int(Difficulty::Hard));
  EXPECT_EQ(b.world().options.particle_budget, 50000u);
  EXPECT_EQ(b.world().options.substeps, 2);
  for (uint64_t t = 120; t < 240; ++t) {
    a.step(pilot(t));
    b.step(pilot(t));
  }
  EXPECT_EQ(a.full_hash(), b.full_hash());
}

TEST(Snapshot, RestoreDoesNotResimulate) {
  // The old save replayed the input log from tick 0; a snapshot's cost does not grow with the
  // game's length: its size stays bounded by the state, not by the ticks played.
  Game a = Game::load_level(repo("levels/duel.json"), options());
  for (uint64_t t = 0; t < 600; ++t) a.step(pilot(t));
  const size_t at600 = a.save().size();
  for (uint64_t t = 600; t < 660; ++t) a.step(InputFrame{});
  Game b = Game::restore(a.save(), repo("levels/duel.json"), options());
  EXPECT_EQ(b.tick(), a.tick());
  EXPECT_LT(a.save().size(), at600 * 4);
}

// ---- damaged snapshots ----------------------------------------------------------------------

std::vector<uint8_t> snapshot_of(const std::string& level, uint64_t ticks, const GameOptions& o = options()) {
  Game a = Game::load_level(repo(level), o);
  for (uint64_t t = 0; t < ticks; ++t) a.step(pilot(t), commands(t));
  return a.save();
}

// The frame's checksum recomputed, so a change reaches the structural checks behind it.
void reseal(std::vector<uint8_t>& b) {
  const size_t payload = b.size() - snapshot::kFrameHeader - snapshot::kFrameTrailer;
  const uint64_t c = snapshot::checksum(b.data() + snapshot::kFrameHeader, payload);
  for (int i = 0; i < 8; ++i) b[b.size() - 8 + size_t(i)] = uint8_t(c >> (8 * i));
}

// Every byte of the first `dense` bytes, then `spread` positions evenly over the rest.
std::vector<size_t> positions(size_t begin, size_t end, size_t dense, size_t spread) {
  std::vector<size_t> out;
  for (size_t i = begin; i < end && i < begin + dense; ++i) out.push_back(i);
  const size_t from = begin + dense;
  if (from < end)
    for (size_t k = 0; k < spread; ++k) out.push_back(from + (end - from) * k / spread);
  return out;
}

void expect_snapshot_error(const std::vector<uint8_t>& bytes, const std::string& why) {
  try {
    Game::restore(bytes, repo("levels/arena.json"), options());
    ADD_FAILURE() << why << ": restored without an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("snapshot: ", 0), 0u) << e.what();
  }
}

TEST(Snapshot, TruncatedSnapshotsAreInputErrors) {
  const std::vector<uint8_t> bytes = snapshot_of("levels/arena.json", 300);
  for (size_t n : {size_t(0), size_t(1), size_t(7), size_t(19), size_t(20), size_t(27), size_t(28), bytes.size() / 2,
                   bytes.size() - 9, bytes.size() - 1})
    expect_snapshot_error(std::vector<uint8_t>(bytes.begin(), bytes.begin() + n), "truncated to " + std::to_string(n));
  // Cut inside the payload with a consistent header and checksum: the field reads run out.
  for (size_t n : positions(snapshot::kFrameHeader, bytes.size() - snapshot::kFrameTrailer, 256, 300)) {
    std::vector<uint8_t> cut(bytes.begin(), bytes.begin() + n);
    const uint64_t payload = n - snapshot::kFrameHeader;
    for (int i = 0; i < 8; ++i) cut[12 + size_t(i)] = uint8_t(payload >> (8 * i));
    cut.resize(n + snapshot::kFrameTrailer);
    reseal(cut);
    expect_snapshot_error(cut, "payload cut at " + std::to_string(n));
  }
}

TEST(Snapshot, CorruptSnapshotsAreInputErrors) {
  const std::vector<uint8_t> bytes = snapshot_of("levels/arena.json", 300);
  std::vector<uint8_t> bad = bytes;
  for (size_t at : positions(0, bytes.size(), 64, 400)) {
    bad[at] ^= 0x5A;
    expect_snapshot_error(bad, "byte " + std::to_string(at) + " flipped");
    bad[at] ^= 0x5A;
  }
  std::vector<uint8_t> longer = bytes;
  longer.push_back(0);
  expect_snapshot_error(longer, "a byte appended");
  std::vector<uint8_t> version = bytes;
  version[8] = 99;
  expect_snapshot_error(version, "unknown version");
}

TEST(Snapshot, CorruptFieldsBehindAValidChecksumNeverCrash) {
  // Byte positions overwritten with extreme values and the checksum recomputed: each restore
  // either succeeds (a plausible value) and can be stepped, or throws InputError. The duel
  // after a few seconds of fighting has beams, projectiles and a few hundred clusters.
  // A budget well above the duel's few thousand particles: each of the 6000 restores builds a
  // particle store of the budget's size, and the default's would dominate the test's time.
  GameOptions small = options();
  small.particle_budget = 20000;
  const std::vector<uint8_t> bytes = snapshot_of("levels/duel.json", 200, small);
  int errors = 0, loaded = 0;
  const size_t end = bytes.size() - snapshot::kFrameTrailer;
  for (size_t at : positions(snapshot::kFrameHeader, end, 3000, 600)) {
    for (uint8_t v : {uint8_t(0xFF), uint8_t(0x80)}) {
      std::vector<uint8_t> bad = bytes;
      if (bad[at] == v) continue;
      bad[at] = v;
      reseal(bad);
      try {
        Game g = Game::restore(bad, repo("levels/duel.json"), small);
        for (int k = 0; k < 3; ++k) g.step(pilot(200 + k));
        (void)g.full_hash();
        ++loaded;
      } catch (const InputError& e) {
        ASSERT_EQ(std::string(e.what()).rfind("snapshot: ", 0), 0u) << e.what();
        ++errors;
      }
    }
  }
  EXPECT_GT(errors, 100);
  EXPECT_GT(loaded, 100);
}

TEST(Snapshot, ForeignLevelIsAnInputError) {
  Game a = Game::load_level(repo("levels/duel.json"), options());
  for (uint64_t t = 0; t < 10; ++t) a.step(pilot(t));
  EXPECT_THROW(Game::restore(a.save(), repo("levels/skirmish.json"), options()), InputError);
  EXPECT_THROW(Game::restore(a.save(), repo("levels/arena.json"), options()), InputError);
}

// ---- the cheap hash --------------------------------------------------------------------------

TEST(Snapshot, CheapHashSeesParticleCountersButNotEveryParticle) {
  Game a = Game::load_level(repo("levels/duel.json"), options());
  for (uint64_t t = 0; t < 60; ++t) a.step(pilot(t));
  Game b = a;
  EXPECT_EQ(a.hash(), b.hash());
  // A different future (one more step) changes both hashes.
  b.step(pilot(60));
  EXPECT_NE(a.hash(), b.hash());
  EXPECT_NE(a.full_hash(), b.full_hash());
}

// Not a check (speed is never asserted in tests): prints what hash() and full_hash() cost
// against step() on the arena. Run with --gtest_also_run_disabled_tests.
TEST(Snapshot, DISABLED_HashCostAgainstStepOnArena) {
  using clock = std::chrono::steady_clock;
  Game g = Game::load_level(repo("levels/arena.json"), options());
  for (uint64_t t = 0; t < 1200; ++t) g.step(pilot(t), commands(t));  // measured over ticks 1201..1800
  double step_s = 0, hash_s = 0, full_s = 0, save_s = 0, restore_s = 0;
  uint64_t sink = 0;
  const int n = 600;
  for (int i = 0; i < n; ++i) {
    auto t0 = clock::now();
    g.step(pilot(1200 + uint64_t(i)), commands(1200 + uint64_t(i)));
    auto t1 = clock::now();
    sink ^= g.hash();
    auto t2 = clock::now();
    sink ^= g.full_hash();
    auto t3 = clock::now();
    step_s += std::chrono::duration<double>(t1 - t0).count();
    hash_s += std::chrono::duration<double>(t2 - t1).count();
    full_s += std::chrono::duration<double>(t3 - t2).count();
  }
  std::vector<uint8_t> bytes;
  for (int i = 0; i < 20; ++i) {
    auto t0 = clock::now();
    bytes = g.save();
    auto t1 = clock::now();
    Game r = Game::restore(bytes, repo("levels/arena.json"), options());
    auto t2 = clock::now();
    save_s += std::chrono::duration<double>(t1 - t0).count();
    restore_s += std::chrono::duration<double>(t2 - t1).count();
    sink ^= r.tick();
  }
  const auto st = g.world().particles->stats();
  std::printf("arena at tick %llu: %u particles in %u clusters; snapshot %zu bytes\n",
              static_cast<unsigned long long>(g.tick()), st.live_particles, st.live_clusters, bytes.size());
  std::printf("step %.1f us, hash %.2f us (%.2f%% of step), full_hash %.1f us (%.1f%% of step)\n", step_s / n * 1e6,
              hash_s / n * 1e6, 100 * hash_s / step_s, full_s / n * 1e6, 100 * full_s / step_s);
  std::printf("save %.2f ms, restore (level load included) %.2f ms  [%llx]\n", save_s / 20 * 1e3, restore_s / 20 * 1e3,
              static_cast<unsigned long long>(sink));
}

}  // namespace
}  // namespace arc
