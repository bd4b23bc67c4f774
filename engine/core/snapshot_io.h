// core/snapshot_io.h — little-endian byte writer and bounds-checked reader for snapshots.
//
// Used by ParticleWorld::save/load and by the game's snapshot (game/sim/serialize.cpp). A
// snapshot is framed as
//   magic (8 bytes) · version (u32) · payload size (u64) · payload · checksum of the payload (u64)
// and every read checks the bytes left, so a truncated or corrupt snapshot throws
// InputError("snapshot: ...") instead of reading past the end. Counts are checked against
// the bytes left before anything is allocated.
//
// Example, compiled as CoreExamples.SnapshotRoundTrip in tests/unit/core/test_core_examples.cpp:
//   snapshot::Writer out;  out.u64(x);  out.vec3(p);  std::vector<uint8_t> b = out.framed(kMagic, 1);
//   snapshot::Reader in = snapshot::Reader::unframe(b.data(), b.size(), kMagic, 1, "particle world");
//   uint64_t x2 = in.u64();  glm::dvec3 p2 = in.vec3();  in.expect_end();
#pragma once
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>
#include <vector>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "core/error.h"
#include "core/rng.h"

namespace arc::snapshot {

// Eight ASCII characters as a little-endian u64 ("ARCSNAP1" reads as those bytes in the file).
constexpr uint64_t magic(const char (&s)[9]) {
  uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v |= uint64_t(uint8_t(s[i])) << (8 * i);
  return v;
}

// A 64-bit checksum of bytes (SplitMix-mixed words; any flipped bit changes it).
inline uint64_t checksum(const uint8_t* p, size_t n) {
  uint64_t h = mix64(0x5EED5A7Eull ^ n);
  size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    uint64_t w = 0;
    for (int k = 0; k < 8; ++k) w |= uint64_t(p[i + k]) << (8 * k);
    h = mix64(h ^ w) + 0x9E3779B97F4A7C15ull;
  }
  uint64_t tail = 0;
  for (int k = 0; i + size_t(k) < n; ++k) tail |= uint64_t(p[i + k]) << (8 * k);
  return mix64(h ^ tail ^ 0xA5);
}

constexpr size_t kFrameHeader = 8 + 4 + 8;
constexpr size_t kFrameTrailer = 8;

class Writer {
 public:
  void u8(uint8_t v) { bytes_.push_back(v); }
  void u16(uint16_t v) { put(v, 2); }
  void u32(uint32_t v) { put(v, 4); }
  void u64(uint64_t v) { put(v, 8); }
  void i32(int32_t v) { u32(static_cast<uint32_t>(v)); }
  void i64(int64_t v) { u64(static_cast<uint64_t>(v)); }
  void boolean(bool v) { u8(v ? 1 : 0); }
  void f32(float v) { u32(std::bit_cast<uint32_t>(v)); }
  void f64(double v) { u64(std::bit_cast<uint64_t>(v)); }
  void vec3(const glm::dvec3& v) { f64(v.x), f64(v.y), f64(v.z); }
  void quat(const glm::dquat& q) { f64(q.w), f64(q.x), f64(q.y), f64(q.z); }
  void str(const std::string& s) {
    u32(static_cast<uint32_t>(s.size()));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
  }
  void bytes(const std::vector<uint8_t>& b) {
    u64(b.size());
    bytes_.insert(bytes_.end(), b.begin(), b.end());
  }
  // An array of plain numbers (no count: the caller writes it once for several arrays).
  template <typename T>
  void array(std::span<const T> v) {
    static_assert(std::is_arithmetic_v<T>);
    if constexpr (std::endian::native == std::endian::little) {
      const size_t at = bytes_.size();
      bytes_.resize(at + v.size() * sizeof(T));
      if (!v.empty()) std::memcpy(bytes_.data() + at, v.data(), v.size() * sizeof(T));
    } else {
      for (T x : v) {
        if constexpr (sizeof(T) == 1) u8(std::bit_cast<uint8_t>(x));
        else if constexpr (sizeof(T) == 2) u16(std::bit_cast<uint16_t>(x));
        else if constexpr (sizeof(T) == 4) u32(std::bit_cast<uint32_t>(x));
        else u64(std::bit_cast<uint64_t>(x));
      }
    }
  }
  size_t size() const { return bytes_.size(); }

  // The payload written so far, framed: magic, version, size, payload, checksum.
  std::vector<uint8_t> framed(uint64_t magic_value, uint32_t version) const {
    Writer out;
    out.bytes_.reserve(kFrameHeader + bytes_.size() + kFrameTrailer);
    out.u64(magic_value);
    out.u32(version);
    out.u64(bytes_.size());
    out.bytes_.insert(out.bytes_.end(), bytes_.begin(), bytes_.end());
    out.u64(checksum(bytes_.data(), bytes_.size()));
    return std::move(out.bytes_);
  }

 private:
  void put(uint64_t v, int n) {
    for (int i = 0; i < n; ++i) bytes_.push_back(uint8_t(v >> (8 * i)));
  }
  std::vector<uint8_t> bytes_;
};

class Reader {
 public:
  Reader(const uint8_t* data, size_t size, std::string what) : p_(data), n_(size), what_(std::move(what)) {}

  // Checks the frame (size, magic, version, checksum) and returns a reader over the payload.
  static Reader unframe(const uint8_t* data, size_t size, uint64_t magic_value, uint32_t version, const std::string& what) {
    Reader head(data, size, what);
    if (size < kFrameHeader + kFrameTrailer)
      head.fail("too short (" + std::to_string(size) + " bytes; a snapshot has at least " +
                std::to_string(kFrameHeader + kFrameTrailer) + ")");
    if (head.u64() != magic_value) head.fail("not a " + what + " snapshot (bad magic)");
    const uint32_t v = head.u32();
    if (v != version)
      head.fail("version " + std::to_string(v) + " is not supported (this build reads version " + std::to_string(version) + ")");
    const uint64_t payload = head.u64();
    if (payload != size - kFrameHeader - kFrameTrailer)
      head.fail("truncated or padded: the header says " + std::to_string(payload) + " payload bytes, the data holds " +
                std::to_string(size - kFrameHeader - kFrameTrailer));
    Reader tail(data + kFrameHeader + payload, kFrameTrailer, what);
    if (tail.u64() != checksum(data + kFrameHeader, size_t(payload))) head.fail("checksum mismatch (corrupt data)");
    return Reader(data + kFrameHeader, size_t(payload), what);
  }

  [[noreturn]] void fail(const std::string& why) const {
    throw InputError("snapshot: " + what_ + ": " + why + " (at byte " + std::to_string(at_) + ")");
  }

  uint8_t u8() { return uint8_t(get(1)); }
  uint16_t u16() { return uint16_t(get(2)); }
  uint32_t u32() { return uint32_t(get(4)); }
  uint64_t u64() { return get(8); }
  int32_t i32() { return static_cast<int32_t>(u32()); }
  int64_t i64() { return static_cast<int64_t>(u64()); }
  bool boolean() {
    const uint8_t v = u8();
    if (v > 1) fail("a flag is " + std::to_string(v) + ", allowed 0 or 1");
    return v == 1;
  }
  float f32() { return std::bit_cast<float>(u32()); }
  double f64() { return std::bit_cast<double>(u64()); }
  glm::dvec3 vec3() {
    glm::dvec3 v;
    v.x = f64(), v.y = f64(), v.z = f64();
    return v;
  }
  glm::dquat quat() {
    glm::dquat q;
    q.w = f64(), q.x = f64(), q.y = f64(), q.z = f64();
    return q;
  }
  std::string str() {
    const size_t n = count(1, "string length");
    std::string s(reinterpret_cast<const char*>(p_ + at_), n);
    at_ += n;
    return s;
  }
  std::vector<uint8_t> bytes() {
    const size_t n = size_t(count64(1, "byte block length"));
    std::vector<uint8_t> b(p_ + at_, p_ + at_ + n);
    at_ += n;
    return b;
  }
  // A u32 count of items of at least `min_item_bytes` each, checked against the bytes left.
  size_t count(size_t min_item_bytes, const char* what) {
    const uint64_t n = u32();
    check_room(n, min_item_bytes, what);
    return size_t(n);
  }
  uint64_t count64(size_t min_item_bytes, const char* what) {
    const uint64_t n = u64();
    check_room(n, min_item_bytes, what);
    return n;
  }
  // Exactly v.size() numbers into v.
  template <typename T>
  void array(std::span<T> v) {
    static_assert(std::is_arithmetic_v<T>);
    const size_t n = v.size();
    check_room(n, sizeof(T), "array");
    if constexpr (std::endian::native == std::endian::little) {
      if (n) std::memcpy(v.data(), p_ + at_, n * sizeof(T));
      at_ += n * sizeof(T);
    } else {
      for (size_t i = 0; i < n; ++i) {
        if constexpr (sizeof(T) == 1) v[i] = std::bit_cast<T>(u8());
        else if constexpr (sizeof(T) == 2) v[i] = std::bit_cast<T>(u16());
        else if constexpr (sizeof(T) == 4) v[i] = std::bit_cast<T>(u32());
        else v[i] = std::bit_cast<T>(u64());
      }
    }
  }

  size_t remaining() const { return n_ - at_; }
  size_t position() const { return at_; }
  void expect_end() const {
    if (at_ != n_) fail(std::to_string(n_ - at_) + " unexpected bytes after the end");
  }

 private:
  uint64_t get(int n) {
    if (n_ - at_ < size_t(n)) fail("truncated: needs " + std::to_string(n) + " more bytes, " + std::to_string(n_ - at_) + " left");
    uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= uint64_t(p_[at_ + i]) << (8 * i);
    at_ += size_t(n);
    return v;
  }
  void check_room(uint64_t n, size_t item, const char* what) {
    if (item > 0 && n > remaining() / item)
      fail(std::string(what) + " " + std::to_string(n) + " exceeds the " + std::to_string(remaining()) + " bytes left");
  }

  const uint8_t* p_;
  size_t n_;
  size_t at_ = 0;
  std::string what_;
};

}  // namespace arc::snapshot
