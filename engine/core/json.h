// core/json.h — JSON data files with exact error positions.
//
// Every data file (levels, ships, effects, quality presets, key bindings) is JSON with
// comments, parsed by nlohmann::json. A second SAX pass records the line and column of every
// key and value by JSON pointer, so a loader can say *where* a value is wrong, by whole key path:
//   levels/duel.json:14:18: 'ships[1].position[2]' must be in [-1073741824, 1073741824], got -2e+09
//
// Loaders read through JsonObject, which checks types, ranges and finiteness and, at
// finish(), rejects every key that was not read ("unknown key 'hul'; allowed: hull, shield").
//
// Example, compiled as CoreExamples.ReadALevel in tests/unit/core/test_core_examples.cpp:
//   std::shared_ptr<const JsonDoc> doc = JsonDoc::load_file("levels/duel.json");  // throws InputError
//   JsonObject root(doc, "", &doc->root());
//   uint64_t seed = root.integer("seed", 1, 0, UINT32_MAX);
//   root.check_list_length("ships", kMaxLevelShips);  // before reading a list (core/input_limits.h)
//   for (JsonObject s : root.objects("ships")) names.push_back(s.require_string("name"));
#pragma once
#include <cstdint>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "core/input_limits.h"

namespace arc {

struct TextPos { int line = 1; int col = 1; };
// Bytes [begin, end) of a key or value in the parsed text (a container's span runs from its
// bracket to its closing bracket). Edits splice at these spans to keep comments (workbench).
struct TextSpan { size_t begin = 0; size_t end = 0; };

class JsonDoc {
 public:
  // Reads and parses a file; a missing file or a syntax error throws InputError with the position.
  static std::shared_ptr<const JsonDoc> load_file(const std::string& path);
  static std::shared_ptr<const JsonDoc> parse(const std::string& text, const std::string& path);

  const nlohmann::json& root() const { return root_; }
  const std::string& path() const { return path_; }
  // "path:line:col" of the value at a JSON pointer (the member's key for object members).
  std::string where(const std::string& pointer) const;
  std::string where_value(const std::string& pointer) const;
  // Byte spans of the value at a pointer and of an object member's key; false when there is none.
  bool value_span(const std::string& pointer, TextSpan& out) const;
  bool key_span(const std::string& pointer, TextSpan& out) const;

 private:
  std::string path_;
  nlohmann::json root_;
  TextPos pos_at(size_t offset) const;
  std::vector<size_t> line_starts_;  // byte offset of each line's start, for positions
  std::map<std::string, TextSpan> value_span_;
  std::map<std::string, TextSpan> key_span_;
  friend struct JsonPositionRecorder;
};

class JsonObject;

// A typed, positioned view on one JSON value.
class JsonValue {
 public:
  JsonValue(std::shared_ptr<const JsonDoc> doc, std::string pointer, const nlohmann::json* j)
      : doc_(std::move(doc)), ptr_(std::move(pointer)), j_(j) {}

  const nlohmann::json& raw() const { return *j_; }
  const std::string& pointer() const { return ptr_; }
  // The whole key path from the top, for messages: ships[3].position[1], beam.mounts[0][0].
  std::string name() const;
  std::string where() const { return doc_->where_value(ptr_); }
  [[noreturn]] void fail(const std::string& message) const;

  double number(double min, double max) const;
  int64_t integer(int64_t min, int64_t max) const;
  bool boolean() const;
  std::string string() const;
  std::string choice(std::initializer_list<const char*> allowed) const;
  std::string choice(const std::vector<const char*>& allowed) const;
  glm::dvec3 vec3(double min, double max) const;
  glm::dvec4 vec4(double min, double max) const;
  std::vector<double> numbers(double min, double max) const;
  JsonObject object() const;
  std::vector<JsonValue> array() const;
  // Throws at the value's position when it is an array of more than `max` elements (checked
  // before a loader reads them: core/input_limits.h has each list's limit).
  void check_list_length(size_t max) const;
  bool is_object() const { return j_->is_object(); }
  bool is_array() const { return j_->is_array(); }
  bool is_string() const { return j_->is_string(); }
  bool is_number() const { return j_->is_number(); }

 protected:
  std::shared_ptr<const JsonDoc> doc_;
  std::string ptr_;
  const nlohmann::json* j_;
};

// An object whose keys are read one by one; finish() rejects the ones never read.
class JsonObject : public JsonValue {
 public:
  JsonObject(std::shared_ptr<const JsonDoc> doc, std::string pointer, const nlohmann::json* j);

  bool has(const std::string& key) const;
  std::optional<JsonValue> get(const std::string& key);  // marks the key as read
  JsonValue require(const std::string& key);              // missing key → error at the object

  double number(const std::string& key, double fallback, double min, double max);
  double require_number(const std::string& key, double min, double max);
  int64_t integer(const std::string& key, int64_t fallback, int64_t min, int64_t max);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key, const std::string& fallback);
  std::string require_string(const std::string& key);
  std::string choice(const std::string& key, const std::string& fallback,
                     std::initializer_list<const char*> allowed);
  std::string choice(const std::string& key, const std::string& fallback, const std::vector<const char*>& allowed);
  glm::dvec3 vec3(const std::string& key, glm::dvec3 fallback, double min, double max);
  glm::dvec4 vec4(const std::string& key, glm::dvec4 fallback, double min, double max);
  JsonObject require_object(const std::string& key);
  std::vector<JsonObject> objects(const std::string& key);  // optional array of objects; missing → empty
  // Throws at the key's position when the member is an array of more than `max` elements.
  void check_list_length(const std::string& key, size_t max) const;
  // The whole key path of a member, as name() gives it for values: "ships[3].player".
  std::string key_path(const std::string& key) const;
  // Error at a member's key position.
  [[noreturn]] void fail_key(const std::string& key, const std::string& message) const;
  // Throws for the first key that was never read, listing the allowed ones.
  void finish() const;
  // Marks keys as known without reading them (for forward-compatible optional blocks).
  void allow(std::initializer_list<const char*> keys);

 private:
  std::set<std::string> read_;
};

// Escapes a key for use in a JSON pointer (RFC 6901).
std::string json_pointer_escape(const std::string& key);
// A JSON pointer into `root` as a key path for messages: /ships/3/position/1 → ships[3].position[1].
std::string json_key_path(const nlohmann::json& root, const std::string& pointer);
// "a, b or c" for messages.
std::string join_allowed(const std::vector<std::string>& names);

// A text file through core/input_file.h: a regular file of at most `max_bytes`, else InputError.
std::string read_text_file(const std::string& path, size_t max_bytes = kMaxDataFileBytes,
                           const std::string& kind = "a data file");

}  // namespace arc
