// core/typed_id.h — small typed ids: a uint32_t that only compares with ids of its own kind.
//
// Id<Tag> wraps a number that names one thing of a kind (a ship, a team, a model, a particle
// owner, an effect). Zero is null, so a default Id names nothing and `if (id)` asks whether it
// names something. Ids of different tags are different types: passing a TeamId where a ShipId
// is wanted, comparing them, or making one from an int is a compile error. The only way in is
// an explicit uint32_t (Id<Tag>{7u}) or a table position (from_index), the only way out is
// `.value` or index(), so a conversion is always visible at the call.
//
// Example, compiled as CoreExamples.TypedId in tests/unit/core/test_core_examples.cpp:
//   struct ShipTag;
//   using ShipId = Id<ShipTag>;
//   ShipId s = ShipId::from_index(3);    // value 4
//   std::string name = ships[s.index()];  // ships[3]
//   bool none = !ShipId{};               // null: names no ship
#pragma once
#include <compare>
#include <cstddef>
#include <cstdint>

namespace arc {

template <class Tag>
struct Id {
  uint32_t value = 0;

  constexpr Id() = default;
  constexpr explicit Id(uint32_t v) : value(v) {}
  // Any other type (int, size_t, another kind of id) is refused, not converted.
  template <class T>
  explicit Id(T) = delete;

  // The id of the i-th entry of a table (value i + 1) and back; index() of a null id is meaningless.
  static constexpr Id from_index(size_t i) { return Id(static_cast<uint32_t>(i + 1)); }
  constexpr size_t index() const { return size_t(value) - 1; }

  constexpr explicit operator bool() const { return value != 0; }
  constexpr bool operator==(const Id&) const = default;
  constexpr auto operator<=>(const Id&) const = default;
};

}  // namespace arc
