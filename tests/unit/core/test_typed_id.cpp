// core/typed_id.h: ids of different kinds do not mix, ints do not become ids, zero is null.
// Most of what is tested here is that some code does not compile, so it is said with
// static_asserts; the runtime part checks null, order and the table-index round trip.
#include <gtest/gtest.h>

#include <concepts>
#include <type_traits>

#include "core/typed_id.h"

namespace arc {
namespace {

struct ShipTag;
struct TeamTag;
using ShipId = Id<ShipTag>;
using TeamId = Id<TeamTag>;

// Not from another kind of id, not from an int or a size_t, only from an explicit uint32_t.
static_assert(!std::is_constructible_v<ShipId, TeamId>);
static_assert(!std::is_constructible_v<ShipId, int>);
static_assert(!std::is_constructible_v<ShipId, size_t>);
static_assert(std::is_constructible_v<ShipId, uint32_t>);
static_assert(!std::is_convertible_v<uint32_t, ShipId>);
static_assert(!std::is_assignable_v<ShipId&, TeamId>);
static_assert(!std::is_assignable_v<ShipId&, int>);
// Not back to a number either (only `.value` or index()), and bool only explicitly.
static_assert(!std::is_convertible_v<ShipId, int>);
static_assert(!std::is_convertible_v<ShipId, uint32_t>);
static_assert(!std::is_convertible_v<ShipId, bool>);
static_assert(std::is_constructible_v<bool, ShipId>);
// Compared only with its own kind.
static_assert(std::equality_comparable<ShipId>);
static_assert(std::totally_ordered<ShipId>);
static_assert(!std::equality_comparable_with<ShipId, TeamId>);
static_assert(!std::equality_comparable_with<ShipId, int>);
static_assert(sizeof(ShipId) == sizeof(uint32_t));

TEST(TypedId, ZeroIsNullAndDefault) {
  const ShipId none;
  EXPECT_FALSE(none);
  EXPECT_EQ(none.value, 0u);
  EXPECT_TRUE(ShipId{3u});
  EXPECT_EQ(none, ShipId{0u});
}

TEST(TypedId, TableIndexRoundTripAndOrder) {
  const ShipId third = ShipId::from_index(2);
  EXPECT_EQ(third.value, 3u);
  EXPECT_EQ(third.index(), 2u);
  EXPECT_LT(ShipId::from_index(0), third);
  EXPECT_NE(ShipId::from_index(0), third);
}

}  // namespace
}  // namespace arc
