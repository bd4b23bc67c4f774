// The field visitors of game/sim/world.h: every member of a simulated struct is named by its
// visitor, the hash words of each pass are numbered without gaps or clashes, and a World copies
// by default (the copy outlives the original).
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

using fields::aggregate_field_count;
using fields::check_hash_words;
using fields::hash_slots;
using fields::visited_field_count;
using test::options;
using test::repo;

// A member added to a struct and not to its visitor is in the struct's aggregate count (the most
// initialisers T{...} accepts) and not in the visitor's: this test fails until the visitor names
// it, and with that says how the snapshot and the hash treat it.
TEST(StateFields, EveryMemberIsNamedByItsVisitor) {
  AiState ai;
  CombatStats stats;
  Ship ship;
  Projectile projectile;
  ExplosionEvent explosion;
  Prop prop;
  CameraRig camera;
  TrainingProgress training;
  World world;
  EXPECT_EQ(visited_field_count(training), aggregate_field_count<TrainingProgress>());
  EXPECT_EQ(visited_field_count(ai), aggregate_field_count<AiState>());
  EXPECT_EQ(visited_field_count(stats), aggregate_field_count<CombatStats>());
  EXPECT_EQ(visited_field_count(ship), aggregate_field_count<Ship>());
  EXPECT_EQ(visited_field_count(projectile), aggregate_field_count<Projectile>());
  EXPECT_EQ(visited_field_count(explosion), aggregate_field_count<ExplosionEvent>());
  EXPECT_EQ(visited_field_count(prop), aggregate_field_count<Prop>());
  EXPECT_EQ(visited_field_count(camera), aggregate_field_count<CameraRig>());
  EXPECT_EQ(visited_field_count(world), aggregate_field_count<World>());
}

// The counting itself: a struct with a member its visitor leaves out is caught.
struct TwoMembers {
  int named = 0;
  double forgotten = 0;
};
template <fields::MaybeConst<TwoMembers> T, class V>
void visit_fields(T& t, V&& v) {
  v("named", t.named, fields::saved, fields::unhashed);
}

TEST(StateFields, AMemberLeftOutOfTheVisitorIsCounted) {
  TwoMembers t;
  EXPECT_EQ(aggregate_field_count<TwoMembers>(), 2u);
  EXPECT_EQ(visited_field_count(t), 1u);
}

TEST(StateFields, HashWordsOfEachPassAreNumberedWithoutGapsOrClashes) {
  AiState ai;
  CombatStats stats;
  Ship ship;
  Projectile projectile;
  ExplosionEvent explosion;
  CameraRig camera;
  TrainingProgress training;
  World world;
  PartState part;
  BreakUp breakup;
  for (int pass : {kStateHashPass, kPresentationHashPass}) {
    SCOPED_TRACE("pass " + std::to_string(pass));
    EXPECT_EQ(check_hash_words(hash_slots(ai, pass)), "");
    EXPECT_EQ(check_hash_words(hash_slots(stats, pass)), "");
    EXPECT_EQ(check_hash_words(hash_slots(ship, pass)), "");
    EXPECT_EQ(check_hash_words(hash_slots(projectile, pass)), "");
    EXPECT_EQ(check_hash_words(hash_slots(explosion, pass)), "");
    EXPECT_EQ(check_hash_words(hash_slots(camera, pass)), "");
    EXPECT_EQ(check_hash_words(hash_slots(training, pass)), "");
    EXPECT_EQ(check_hash_words(hash_slots(world, pass)), "");
    EXPECT_EQ(check_hash_words(hash_slots(part, pass)), "");
    EXPECT_EQ(check_hash_words(hash_slots(breakup, pass)), "");
  }
  // Word 22: its particle owner, 23: its combat stats, 24: its lock and flares, 25: a capital
  // ship's parts, 26: the part it aims at, 27: a plasma primary's cooldown.
  EXPECT_EQ(hash_slots(ship, kStateHashPass).size(), 28u);
  EXPECT_EQ(hash_slots(ship, kPresentationHashPass).size(), 11u);
}

TEST(StateFields, CheckHashWordsFindsGapsAndClashes) {
  using fields::HashAs;
  EXPECT_EQ(check_hash_words({{0, HashAs::value}, {1, HashAs::count}}), "");
  EXPECT_EQ(check_hash_words({{1, HashAs::high_bits}, {0, HashAs::value}, {1, HashAs::low_bit}}), "");
  EXPECT_NE(check_hash_words({{0, HashAs::value}, {2, HashAs::value}}), "");
  EXPECT_NE(check_hash_words({{0, HashAs::value}, {0, HashAs::value}}), "");
  EXPECT_NE(check_hash_words({{0, HashAs::high_bits}}), "");
}

// Ships point at their class in the level; copies share the (immutable) classes, so a copy
// runs on after the original is gone.
TEST(StateFields, AWorldCopyOutlivesItsOriginal) {
  auto original = std::make_unique<Game>(Game::load_level(repo("levels/duel.json"), options()));
  Game twin = Game::load_level(repo("levels/duel.json"), options());
  for (int t = 0; t < 120; ++t) {
    original->step(InputFrame{.throttle = 60, .buttons = kFirePrimary});
    twin.step(InputFrame{.throttle = 60, .buttons = kFirePrimary});
  }
  World copy = original->world();
  original.reset();
  World& w = twin.world_mut();
  EXPECT_EQ(copy.ships[0].cls->name, w.ships[0].cls->name);
  Game copied = twin;
  copied.world_mut() = copy;
  for (int t = 0; t < 120; ++t) {
    copied.step(InputFrame{.throttle = 60});
    twin.step(InputFrame{.throttle = 60});
    ASSERT_EQ(copied.hash(), twin.hash()) << "step " << t;
  }
  EXPECT_EQ(copied.full_hash(), twin.full_hash());
}

}  // namespace
}  // namespace arc
