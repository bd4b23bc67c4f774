// core/state_fields.h — field visitors: one list of a simulated struct's fields drives its
// hash, its snapshot and its readable dump.
//
// Each simulated struct has a visitor beside it, one function template for const and mutable
// values, that names every field once, in snapshot order (game/sim/world.h and
// particles/world_state.h hold them):
//
// Example, compiled in game/sim/world.h:
//   template <fields::MaybeConst<ExplosionEvent> E, class V>
//   void visit_fields(E& e, V&& v) {
//     v("position", e.position, fields::saved, presentation_hash<0>);
//     v("tick", e.tick, fields::saved, presentation_hash<1>);
//     v("radius", e.radius, fields::saved, presentation_hash<2>);
//   }
//
// After the name and the field come
//  - how a snapshot treats it: `saved` (written, read back), `checked` (written; on restore it
//    must equal what the level already gave this world, e.g. a ship's name; for a list, its
//    length, the entries then read in place) or `not_saved` (rebuilt on load: definitions,
//    caches). A module may add tags derived from Saved that its reader validates.
//  - where the hash takes it: `hashed<Pass, Word>` (one or more) or `unhashed`. A hash is made
//    of passes (the game hashes every ship's state, then every ship's presentation); a pass
//    takes its fields in the order of their word numbers, which freeze the order of the hashes
//    stored by replays, whatever the snapshot's order. A nested struct is hashed by its own
//    fields of the same pass; a vector by its elements (its length only where a `count` slot
//    says so); an integer (high_bits, shifted left by one) and a flag (low_bit) may share a word.
//
// Driven by the visitors: hash_pass (a hash pass), write_value and FieldReader (snapshots),
// dump_fields (text), and for the tests visited_field_count, aggregate_field_count and
// hash_slots. Leaf types with an encoding of their own provide, found by argument-dependent
// lookup, hash_leaf(Hasher&, const T&), write_leaf(snapshot::Writer&, const T&) and
// dump_leaf(std::ostream&, const T&); the reader's context reads them back. Typed ids
// (core/typed_id.h) have theirs below: their uint32_t value.
#pragma once
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "core/snapshot_io.h"
#include "core/typed_id.h"

namespace arc {

// Typed ids (core/typed_id.h) are leaves: hashed, saved and dumped as their uint32_t value (0 for
// null). Found by argument-dependent lookup; a snapshot reader's context reads them back (and
// checks what they refer to).
template <class Hasher, class Tag>
void hash_leaf(Hasher& h, const Id<Tag>& id) {
  h.add_u64(id.value);
}
template <class Tag>
void write_leaf(snapshot::Writer& out, const Id<Tag>& id) {
  out.u32(id.value);
}
template <class Tag>
void dump_leaf(std::ostream& o, const Id<Tag>& id) {
  o << id.value;
}

}  // namespace arc

namespace arc::fields {

// ---------------------------------------------------------------- tags

struct Saved {};
struct Checked : Saved {};
struct NotSaved {};
inline constexpr Saved saved;
inline constexpr Checked checked;
inline constexpr NotSaved not_saved;

enum class HashAs : uint8_t { value, count, high_bits, low_bit };
inline constexpr int kMaxHashWords = 32;  // per pass of one struct

template <int Pass, int Word, HashAs As = HashAs::value>
struct HashAt {
  static_assert(Word >= 0 && Word < kMaxHashWords, "a pass of one struct has at most kMaxHashWords words");
};
struct Unhashed {};
template <int Pass, int Word, HashAs As = HashAs::value>
inline constexpr HashAt<Pass, Word, As> hashed;
inline constexpr Unhashed unhashed;

template <class S, class T>
concept MaybeConst = std::same_as<std::remove_const_t<S>, T>;

template <class T>
concept HasFields = requires(T& t) { visit_fields(t, [](auto&&...) {}); };

template <class T>
inline constexpr bool is_vector = false;
template <class T, class A>
inline constexpr bool is_vector<std::vector<T, A>> = true;

// Numbers, flags, enums, strings and glm vectors: encoded here, the same everywhere.
template <class T>
inline constexpr bool is_plain = std::is_arithmetic_v<T> || std::is_enum_v<T> || std::is_same_v<T, std::string> ||
                                 std::is_same_v<T, glm::dvec3> || std::is_same_v<T, glm::dquat>;

template <class T>
size_t count_of(const T& v) {
  if constexpr (requires { v.size(); }) return v.size();
  else return v.count();
}

// ---------------------------------------------------------------- hash

template <int Pass, class Hasher, class T>
void hash_pass(Hasher& h, const T& s);

template <int Pass, class Hasher, class T>
void hash_value(Hasher& h, const T& v) {
  if constexpr (HasFields<T>) {
    hash_pass<Pass>(h, v);
  } else if constexpr (is_vector<T>) {
    for (const auto& e : v) hash_value<Pass>(h, e);
  } else if constexpr (std::is_same_v<T, bool>) {
    h.add_bool(v);
  } else if constexpr (std::is_enum_v<T>) {
    h.add_u64(static_cast<uint64_t>(v));
  } else if constexpr (std::is_integral_v<T> && std::is_signed_v<T>) {
    h.add_i64(v);
  } else if constexpr (std::is_integral_v<T>) {
    h.add_u64(v);
  } else if constexpr (std::is_same_v<T, double>) {
    h.add_f64(v);
  } else if constexpr (std::is_same_v<T, glm::dvec3>) {
    h.add_vec(v);
  } else if constexpr (std::is_same_v<T, glm::dquat>) {
    h.add_quat(v);
  } else if constexpr (std::is_same_v<T, std::string>) {
    h.add_str(v);
  } else {
    hash_leaf(h, v);
  }
}

// Word `Word` of pass `Pass`: every field with that slot (two when an integer and a flag share it).
template <class Hasher, int Pass, int Word>
struct WordHasher {
  Hasher& h;
  uint64_t packed = 0;
  bool has_packed = false;

  template <class T, class Use, class... Slots>
  void operator()(const char*, const T& field, Use, Slots...) {
    static_assert(sizeof...(Slots) > 0, "say where the hash takes the field (hashed<Pass, Word>), or unhashed");
    (take(field, Slots{}), ...);
  }
  template <class T>
  void take(const T&, Unhashed) {}
  template <class T, int P, int W, HashAs As>
  void take(const T& field, HashAt<P, W, As>) {
    if constexpr (P == Pass && W == Word) {
      if constexpr (As == HashAs::value) {
        hash_value<Pass>(h, field);
      } else if constexpr (As == HashAs::count) {
        h.add_u64(count_of(field));
      } else if constexpr (As == HashAs::high_bits) {
        packed |= uint64_t(field) << 1;
        has_packed = true;
      } else {
        packed |= uint64_t(field);
        has_packed = true;
      }
    }
  }
};

template <int Pass, int Word, class Hasher, class T>
void hash_word(Hasher& h, const T& s) {
  WordHasher<Hasher, Pass, Word> w{h};
  visit_fields(s, w);
  if (w.has_packed) h.add_u64(w.packed);
}

// The fields of `s` in pass `Pass`, word by word. Flattened: each word's visit inlines to the
// one field it takes, and the hasher's state stays in registers.
template <int Pass, class Hasher, class T>
[[gnu::flatten]] void hash_pass(Hasher& h, const T& s) {
  [&]<int... Word>(std::integer_sequence<int, Word...>) {
    (hash_word<Pass, Word>(h, s), ...);
  }(std::make_integer_sequence<int, kMaxHashWords>{});
}

// ---------------------------------------------------------------- snapshot

template <class T>
void write_plain(snapshot::Writer& out, const T& v) {
  if constexpr (std::is_same_v<T, bool>) out.boolean(v);
  else if constexpr (std::is_enum_v<T>) {
    static_assert(sizeof(T) == 1, "enums are saved as one byte");
    out.u8(static_cast<uint8_t>(v));
  } else if constexpr (std::is_same_v<T, int32_t>) out.i32(v);
  else if constexpr (std::is_same_v<T, int64_t>) out.i64(v);
  else if constexpr (std::is_same_v<T, uint8_t>) out.u8(v);
  else if constexpr (std::is_same_v<T, uint16_t>) out.u16(v);
  else if constexpr (std::is_same_v<T, uint32_t>) out.u32(v);
  else if constexpr (std::is_same_v<T, uint64_t>) out.u64(v);
  else if constexpr (std::is_same_v<T, double>) out.f64(v);
  else if constexpr (std::is_same_v<T, glm::dvec3>) out.vec3(v);
  else if constexpr (std::is_same_v<T, glm::dquat>) out.quat(v);
  else out.str(v);
}

// Enums name their last value with last_enumerator(E), found by argument-dependent lookup.
template <class T>
void read_plain(snapshot::Reader& in, T& v, const char* name) {
  if constexpr (std::is_same_v<T, bool>) v = in.boolean();
  else if constexpr (std::is_enum_v<T>) {
    const uint8_t raw = in.u8();
    const auto last = static_cast<uint8_t>(last_enumerator(T{}));
    if (raw > last) in.fail(std::string(name) + " " + std::to_string(raw) + " is out of range 0.." + std::to_string(last));
    v = static_cast<T>(raw);
  } else if constexpr (std::is_same_v<T, int32_t>) v = in.i32();
  else if constexpr (std::is_same_v<T, int64_t>) v = in.i64();
  else if constexpr (std::is_same_v<T, uint8_t>) v = in.u8();
  else if constexpr (std::is_same_v<T, uint16_t>) v = in.u16();
  else if constexpr (std::is_same_v<T, uint32_t>) v = in.u32();
  else if constexpr (std::is_same_v<T, uint64_t>) v = in.u64();
  else if constexpr (std::is_same_v<T, double>) v = in.f64();
  else if constexpr (std::is_same_v<T, glm::dvec3>) v = in.vec3();
  else if constexpr (std::is_same_v<T, glm::dquat>) v = in.quat();
  else v = in.str();
}

template <class T>
void write_value(snapshot::Writer& out, const T& v);

struct FieldWriter {
  snapshot::Writer& out;
  template <class T, class Use, class... Slots>
  void operator()(const char*, const T& field, Use, Slots...) const {
    if constexpr (std::is_base_of_v<Saved, Use>) write_value(out, field);
  }
};

// A vector is its length (u32) and its elements.
template <class T>
void write_value(snapshot::Writer& out, const T& v) {
  if constexpr (HasFields<T>) {
    visit_fields(v, FieldWriter{out});
  } else if constexpr (is_vector<T>) {
    out.u32(static_cast<uint32_t>(v.size()));
    for (const auto& e : v) write_value(out, e);
  } else if constexpr (is_plain<T>) {
    write_plain(out, v);
  } else {
    write_leaf(out, v);
  }
}

// The fewest bytes an element of a saved list takes: a length read is checked against the bytes
// left before anything is allocated.
template <class T>
size_t min_saved_bytes() {
  if constexpr (HasFields<T>) {
    return 1;
  } else {
    static const size_t bytes = [] {
      snapshot::Writer w;
      write_value(w, T{});
      return w.size();
    }();
    return bytes;
  }
}

// Reads what write_value wrote. `Context` supplies read_leaf(Reader&, const char* name, T&) for
// its leaf types and, where it has them, validate(Reader&, const char* name, const T&, Use) for
// its own saved tags and after_read(Reader&, T&) for whole structs (checks across fields).
template <class Context>
class FieldReader {
 public:
  FieldReader(snapshot::Reader& in, Context& context) : in_(in), context_(context) {}

  template <class T, class Use, class... Slots>
  void operator()(const char* name, T& field, Use use, Slots...) {
    if constexpr (std::is_same_v<Use, Checked>) {
      check(name, field);
    } else if constexpr (std::is_base_of_v<Saved, Use>) {
      read(name, field);
      if constexpr (requires { context_.validate(in_, name, field, use); }) context_.validate(in_, name, field, use);
    }
  }

  template <class T>
  void read(const char* name, T& v) {
    if constexpr (HasFields<T>) {
      visit_fields(v, *this);
      if constexpr (requires { context_.after_read(in_, v); }) context_.after_read(in_, v);
    } else if constexpr (is_vector<T>) {
      v.resize(in_.count(min_saved_bytes<typename T::value_type>(), name));
      for (auto& e : v) read(name, e);
    } else if constexpr (is_plain<T>) {
      read_plain(in_, v, name);
    } else {
      context_.read_leaf(in_, name, v);
    }
  }

 private:
  template <class T>
  void check(const char* name, T& v) {
    if constexpr (is_vector<T>) {
      const size_t n = in_.count(1, name);
      if (n != v.size())
        in_.fail(std::string(name) + ": " + std::to_string(n) + " in the snapshot, " + std::to_string(v.size()) + " in this world");
      for (auto& e : v) read(name, e);
    } else {
      snapshot::Writer expected;
      write_value(expected, v);
      const std::vector<uint8_t> framed = expected.framed(0, 0);
      snapshot::Reader own = snapshot::Reader::unframe(framed.data(), framed.size(), 0, 0, "checked field");
      for (size_t i = 0; i < expected.size(); ++i)
        if (in_.u8() != own.u8()) in_.fail(std::string(name) + " differs from this world's (a snapshot of another level or build)");
    }
  }

  snapshot::Reader& in_;
  Context& context_;
};

// ---------------------------------------------------------------- dump

template <class T>
void dump_value(std::ostream& o, const T& v);

struct FieldDumper {
  std::ostream& o;
  bool first = true;
  template <class T, class Use, class... Slots>
  void operator()(const char* name, const T& field, Use, Slots...) {
    if constexpr (std::is_base_of_v<Saved, Use>) {
      o << (first ? "" : " ") << name << ' ';
      dump_value(o, field);
      first = false;
    }
  }
};

// Readable: "name value" for every saved field, nested structs in braces, lists in brackets
// (a list of structs one entry per line).
template <class T>
void dump_fields(std::ostream& o, const T& s) {
  visit_fields(s, FieldDumper{o});
}

template <class T>
void dump_value(std::ostream& o, const T& v) {
  if constexpr (HasFields<T>) {
    o << "{ ";
    dump_fields(o, v);
    o << " }";
  } else if constexpr (is_vector<T>) {
    o << '[';
    for (const auto& e : v) {
      if constexpr (HasFields<typename T::value_type>) o << "\n  ";
      else o << ' ';
      dump_value(o, e);
    }
    o << " ]";
  } else if constexpr (std::is_enum_v<T> || std::is_same_v<T, bool> || std::is_integral_v<T>) {
    o << static_cast<int64_t>(v);
  } else if constexpr (std::is_same_v<T, double>) {
    o << v;
  } else if constexpr (std::is_same_v<T, glm::dvec3>) {
    o << '(' << v.x << ' ' << v.y << ' ' << v.z << ')';
  } else if constexpr (std::is_same_v<T, glm::dquat>) {
    o << '(' << v.w << ' ' << v.x << ' ' << v.y << ' ' << v.z << ')';
  } else if constexpr (std::is_same_v<T, std::string>) {
    o << '"' << v << '"';
  } else {
    dump_leaf(o, v);
  }
}

// ---------------------------------------------------------------- for the tests

// How many fields the visitor names for this value (a Cluster's free slot names only two).
template <class T>
size_t visited_field_count(T& probe) {
  size_t n = 0;
  visit_fields(probe, [&n](auto&&...) { ++n; });
  return n;
}

// How many members an aggregate has: the most initialisers T{...} accepts. A member added to a
// struct and not to its visitor makes this differ from visited_field_count.
struct AnyMember {
  template <class T>
  operator T() const;
};
template <class T, class... Members>
constexpr size_t aggregate_field_count() {
  if constexpr (requires { T{Members{}..., AnyMember{}}; }) return aggregate_field_count<T, Members..., AnyMember>();
  else return sizeof...(Members);
}

// The hash slots the visitor declares for pass `pass`, in visitor order: word number and how.
struct HashSlot {
  int word;
  HashAs as;
};
template <class T>
std::vector<HashSlot> hash_slots(T& probe, int pass) {
  std::vector<HashSlot> out;
  auto take = [&]<int P, int W, HashAs As>(HashAt<P, W, As>) {
    if (P == pass) out.push_back({W, As});
  };
  visit_fields(probe, [&](const char*, auto&, auto, auto... slots) {
    ([&] {
      if constexpr (!std::is_same_v<decltype(slots), Unhashed>) take(slots);
    }(), ...);
  });
  return out;
}

// Empty when the words of a pass are 0..n-1, each taken once (a packed word by one high_bits
// and one low_bit field); otherwise what is wrong.
inline std::string check_hash_words(const std::vector<HashSlot>& slots) {
  std::vector<int> uses(kMaxHashWords, 0), packed(kMaxHashWords, 0);
  for (const HashSlot& s : slots) {
    if (s.as == HashAs::high_bits || s.as == HashAs::low_bit) packed[size_t(s.word)] += s.as == HashAs::high_bits ? 1 : 10;
    else ++uses[size_t(s.word)];
  }
  bool ended = false;
  for (int w = 0; w < kMaxHashWords; ++w) {
    const bool used = uses[size_t(w)] > 0 || packed[size_t(w)] > 0;
    if (used && ended) return "word " + std::to_string(w) + " follows an unused word";
    if (!used) ended = true;
    if (used && !(uses[size_t(w)] == 1 && packed[size_t(w)] == 0) && !(uses[size_t(w)] == 0 && packed[size_t(w)] == 11))
      return "word " + std::to_string(w) + " is taken by more than one field, or packs without a high_bits and a low_bit";
  }
  return "";
}

}  // namespace arc::fields
