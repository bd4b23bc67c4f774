#include "core/json.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "core/error.h"
#include "core/input_file.h"
#include "core/input_limits.h"

namespace arc {
namespace {

// The shortest text that reads back as exactly v: "got 1000000000000.0001" shows why a value
// just over a limit of 1e+12 is out, where six significant digits would print "1e+12".
std::string fmt_num(double v) {
  char buf[32];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

// Converts byte offsets to 1-based line and column.
class LineIndex {
 public:
  explicit LineIndex(const std::string& text) {
    starts.push_back(0);
    for (size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') starts.push_back(i + 1);
  }
  static TextPos at(const std::vector<size_t>& starts, size_t offset) {
    auto it = std::upper_bound(starts.begin(), starts.end(), offset);
    size_t line = size_t(it - starts.begin());
    return {int(line), int(offset - starts[line - 1] + 1)};
  }
  TextPos at(size_t offset) const { return at(starts, offset); }

  std::vector<size_t> starts;
};

// An input iterator that publishes how far the parser has read.
struct TrackingIterator {
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;
  const char* p = nullptr;
  const char** cursor = nullptr;
  reference operator*() const { return *p; }
  TrackingIterator& operator++() {
    ++p;
    if (cursor) *cursor = p;
    return *this;
  }
  TrackingIterator operator++(int) { auto t = *this; ++*this; return t; }
  bool operator==(const TrackingIterator& o) const { return p == o.p; }
  bool operator!=(const TrackingIterator& o) const { return p != o.p; }
};

}  // namespace

// Records where every key and value starts, by JSON pointer. The parser has consumed a token
// when its event fires; the token starts at the first character after the previous token that
// is not whitespace, a separator or a comment.
struct JsonPositionRecorder : nlohmann::json_sax<nlohmann::json> {
  struct Frame { bool is_array; std::string ptr; std::string key; size_t index = 0; };
  JsonDoc* doc;
  const std::string* text;
  const LineIndex* lines;
  const char* begin;
  const char* cursor;
  size_t last_end = 0;
  std::vector<Frame> stack;
  std::string duplicate;  // "line:col: key 'k' appears twice ..." for the first repeated key

  size_t token_start() {
    size_t i = last_end;
    const std::string& t = *text;
    while (i < t.size()) {
      char c = t[i];
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',' || c == ':') { ++i; continue; }
      if (c == '/' && i + 1 < t.size() && t[i + 1] == '/') {
        while (i < t.size() && t[i] != '\n') ++i;
        continue;
      }
      if (c == '/' && i + 1 < t.size() && t[i + 1] == '*') {
        size_t e = t.find("*/", i + 2);
        i = e == std::string::npos ? t.size() : e + 2;
        continue;
      }
      break;
    }
    return i;
  }
  void end_token() { last_end = size_t(cursor - begin); }
  std::string child_ptr() {
    if (stack.empty()) return "";
    Frame& f = stack.back();
    if (f.is_array) return f.ptr + "/" + std::to_string(f.index++);
    return f.ptr + "/" + json_pointer_escape(f.key);
  }
  // A scalar's last byte: the lexer has read one character past a number, so scan for it.
  size_t scalar_end(size_t s) const {
    if ((*text)[s] == '"') return size_t(cursor - begin);
    size_t e = s;
    while (e < text->size() && (std::isalnum((unsigned char)(*text)[e]) || (*text)[e] == '.' || (*text)[e] == '+' ||
                                (*text)[e] == '-'))
      ++e;
    return e;
  }
  bool value() {
    size_t s = token_start();
    // One entry per value, its position found from the span when asked: the recorder's memory
    // is one map node and one pointer string a value (bounded by core/input_limits.h).
    doc->value_span_.insert_or_assign(child_ptr(), TextSpan{s, scalar_end(s)});
    end_token();
    return true;
  }
  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool open(bool is_array) {
    size_t s = token_start();
    std::string p = child_ptr();
    doc->value_span_[p] = {s, s};
    end_token();
    stack.push_back({is_array, p, "", 0});
    return true;
  }
  bool close() {
    end_token();
    doc->value_span_[stack.back().ptr].end = last_end;
    stack.pop_back();
    return true;
  }
  bool start_object(std::size_t) override { return open(false); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& k) override {
    size_t s = token_start();
    stack.back().key = k;
    const std::string p = stack.back().ptr + "/" + json_pointer_escape(k);
    // A pasted block edited in its copy must not be dropped without a word: nlohmann keeps
    // only one of two equal keys, so the second is an error naming both places.
    if (const auto first = doc->key_span_.find(p); first != doc->key_span_.end()) {
      const TextPos at = lines->at(s), was = lines->at(first->second.begin);
      duplicate = std::to_string(at.line) + ":" + std::to_string(at.col) + ": key '" + k +
                  "' appears twice in this object (first at " + std::to_string(was.line) + ":" +
                  std::to_string(was.col) + "); allowed: each key once";
      return false;
    }
    end_token();
    doc->key_span_[p] = {s, last_end};
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;
  }
};

std::string read_text_file(const std::string& path, size_t max_bytes, const std::string& kind) {
  return read_input_file(path, max_bytes, kind);
}

std::shared_ptr<const JsonDoc> JsonDoc::load_file(const std::string& path) {
  return parse(read_input_file(path, kDataJsonLimits.max_bytes, kDataJsonLimits.kind), path);
}

std::shared_ptr<const JsonDoc> JsonDoc::parse(const std::string& text, const std::string& path) {
  // Depth, string and pointer lengths bounded first: the recorder's cost is linear after that.
  check_json_text(text, path, kDataJsonLimits);
  auto doc = std::make_shared<JsonDoc>();
  doc->path_ = path;
  LineIndex lines(text);
  try {
    doc->root_ = nlohmann::json::parse(text, nullptr, true, true);
  } catch (const nlohmann::json::parse_error& e) {
    size_t byte = e.byte > 0 ? e.byte - 1 : 0;
    TextPos p = lines.at(std::min(byte, text.size()));
    std::string msg = e.what();
    // nlohmann: "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ..."
    auto colon = msg.find(": ", msg.find("parse error"));
    if (colon != std::string::npos) msg = msg.substr(colon + 2);
    throw InputError(path + ":" + std::to_string(p.line) + ":" + std::to_string(p.col) +
                     ": invalid JSON: " + msg);
  } catch (const nlohmann::json::exception& e) {
    // Number overflow and the like carry no byte offset; find the quoted token instead.
    std::string msg = e.what();
    auto q1 = msg.find('\''), q2 = msg.rfind('\'');
    size_t at = 0;
    if (q1 != std::string::npos && q2 > q1) {
      auto found = text.find(msg.substr(q1 + 1, q2 - q1 - 1));
      if (found != std::string::npos) at = found;
    }
    TextPos p = lines.at(at);
    auto bracket = msg.find("] ");
    if (bracket != std::string::npos) msg = msg.substr(bracket + 2);
    throw InputError(path + ":" + std::to_string(p.line) + ":" + std::to_string(p.col) +
                     ": invalid JSON: " + msg + " (numbers must be finite doubles)");
  }
  JsonPositionRecorder rec;
  rec.doc = doc.get();
  rec.text = &text;
  rec.lines = &lines;
  rec.begin = text.data();
  rec.cursor = text.data();
  TrackingIterator first{text.data(), &rec.cursor};
  TrackingIterator last{text.data() + text.size(), nullptr};
  nlohmann::json::sax_parse(first, last, &rec, nlohmann::json::input_format_t::json, true, true);
  if (!rec.duplicate.empty()) throw InputError(path + ":" + rec.duplicate);
  doc->line_starts_ = std::move(lines.starts);
  return doc;
}

static std::string pos_str(const std::string& path, TextPos p) {
  return path + ":" + std::to_string(p.line) + ":" + std::to_string(p.col);
}

bool JsonDoc::value_span(const std::string& pointer, TextSpan& out) const {
  auto v = value_span_.find(pointer);
  if (v == value_span_.end()) return false;
  out = v->second;
  return true;
}

bool JsonDoc::key_span(const std::string& pointer, TextSpan& out) const {
  auto k = key_span_.find(pointer);
  if (k == key_span_.end()) return false;
  out = k->second;
  return true;
}

TextPos JsonDoc::pos_at(size_t offset) const {
  if (line_starts_.empty()) return TextPos{};
  return LineIndex::at(line_starts_, offset);
}

std::string JsonDoc::where(const std::string& pointer) const {
  auto k = key_span_.find(pointer);
  if (k != key_span_.end()) return pos_str(path_, pos_at(k->second.begin));
  return where_value(pointer);
}

std::string JsonDoc::where_value(const std::string& pointer) const {
  auto v = value_span_.find(pointer);
  if (v != value_span_.end()) return pos_str(path_, pos_at(v->second.begin));
  return pos_str(path_, TextPos{});
}

std::string json_pointer_escape(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

std::string join_allowed(const std::vector<std::string>& names) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i) out += (i + 1 == names.size()) ? " or " : ", ";
    out += names[i];
  }
  return out;
}

// ---- JsonValue -------------------------------------------------------------------------------

// A key as written after its parent: `.hull`, or `["render.scale"]` when the key holds
// characters (a dot, a space) that would make the dotted path ambiguous.
static std::string path_member(const std::string& key, bool first) {
  bool plain = !key.empty();
  for (char c : key) plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-');
  if (!plain) return "[\"" + key + "\"]";
  return first ? key : "." + key;
}

std::string json_key_path(const nlohmann::json& root, const std::string& pointer) {
  // Walk from the root so an object key made of digits is told apart from an array index.
  std::string out;
  const nlohmann::json* at = &root;
  size_t i = 0;
  while (i < pointer.size()) {
    size_t next = pointer.find('/', i + 1);
    if (next == std::string::npos) next = pointer.size();
    std::string part;
    for (size_t k = i + 1; k < next; ++k) {
      if (pointer[k] == '~' && k + 1 < next) part += pointer[++k] == '1' ? '/' : '~';
      else part += pointer[k];
    }
    if (at && at->is_array()) {
      out += "[" + part + "]";
      const size_t index = std::strtoul(part.c_str(), nullptr, 10);
      at = index < at->size() ? &(*at)[index] : nullptr;
    } else {
      out += path_member(part, out.empty());
      at = at && at->is_object() && at->contains(part) ? &(*at)[part] : nullptr;
    }
    i = next;
  }
  return out.empty() ? "document" : out;
}

std::string JsonValue::name() const { return json_key_path(doc_->root(), ptr_); }

std::string JsonObject::key_path(const std::string& key) const {
  return json_key_path(doc_->root(), ptr_ + "/" + json_pointer_escape(key));
}

void JsonValue::fail(const std::string& message) const {
  throw InputError(where() + ": " + message);
}

static const char* type_name(const nlohmann::json& j) {
  if (j.is_null()) return "null";
  if (j.is_boolean()) return "a boolean";
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_array()) return "an array";
  return "an object";
}

double JsonValue::number(double min, double max) const {
  if (!j_->is_number())
    fail("'" + name() + "' must be a number in [" + fmt_num(min) + ", " + fmt_num(max) + "], got " +
         type_name(*j_));
  double v = j_->get<double>();
  if (!std::isfinite(v)) fail("'" + name() + "' must be finite, got " + fmt_num(v));
  if (v < min || v > max)
    fail("'" + name() + "' must be in [" + fmt_num(min) + ", " + fmt_num(max) + "], got " + fmt_num(v));
  return v;
}

int64_t JsonValue::integer(int64_t min, int64_t max) const {
  bool ok = j_->is_number_integer() || j_->is_number_unsigned();
  if (j_->is_number_float()) {
    double d = j_->get<double>();
    ok = std::isfinite(d) && std::floor(d) == d && std::fabs(d) < 9.0e15;
  }
  if (!ok)
    fail("'" + name() + "' must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
         "], got " + (j_->is_number() ? j_->dump() : std::string(type_name(*j_))));
  int64_t v;
  if (j_->is_number_unsigned() && j_->get<uint64_t>() > uint64_t(INT64_MAX)) v = INT64_MAX;
  else v = j_->is_number_float() ? int64_t(j_->get<double>()) : j_->get<int64_t>();
  if (v < min || v > max)
    fail("'" + name() + "' must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " +
         j_->dump());
  return v;
}

bool JsonValue::boolean() const {
  if (!j_->is_boolean()) fail("'" + name() + "' must be true or false, got " + type_name(*j_));
  return j_->get<bool>();
}

std::string JsonValue::string() const {
  if (!j_->is_string()) fail("'" + name() + "' must be a string, got " + type_name(*j_));
  return j_->get<std::string>();
}

std::string JsonValue::choice(std::initializer_list<const char*> allowed) const {
  return choice(std::vector<const char*>(allowed));
}

std::string JsonValue::choice(const std::vector<const char*>& allowed) const {
  std::vector<std::string> names(allowed.begin(), allowed.end());
  for (auto& n : names) n = "\"" + n + "\"";
  if (!j_->is_string()) fail("'" + name() + "' must be one of " + join_allowed(names) + ", got " + type_name(*j_));
  std::string v = j_->get<std::string>();
  for (const char* a : allowed)
    if (v == a) return v;
  fail("'" + name() + "' must be one of " + join_allowed(names) + ", got \"" + v + "\"");
}

std::vector<double> JsonValue::numbers(double min, double max) const {
  if (!j_->is_array()) fail("'" + name() + "' must be an array of numbers, got " + type_name(*j_));
  std::vector<double> out;
  for (const JsonValue& e : array()) out.push_back(e.number(min, max));
  return out;
}

glm::dvec3 JsonValue::vec3(double min, double max) const {
  if (!j_->is_array() || j_->size() != 3)
    fail("'" + name() + "' must be an array of 3 numbers [x, y, z]");
  auto v = numbers(min, max);
  return {v[0], v[1], v[2]};
}

glm::dvec4 JsonValue::vec4(double min, double max) const {
  if (!j_->is_array() || j_->size() != 4)
    fail("'" + name() + "' must be an array of 4 numbers [r, g, b, a]");
  auto v = numbers(min, max);
  return {v[0], v[1], v[2], v[3]};
}

JsonObject JsonValue::object() const {
  if (!j_->is_object()) fail("'" + name() + "' must be an object, got " + type_name(*j_));
  return JsonObject(doc_, ptr_, j_);
}

std::vector<JsonValue> JsonValue::array() const {
  if (!j_->is_array()) fail("'" + name() + "' must be an array, got " + type_name(*j_));
  std::vector<JsonValue> out;
  for (size_t i = 0; i < j_->size(); ++i) out.emplace_back(doc_, ptr_ + "/" + std::to_string(i), &(*j_)[i]);
  return out;
}

void JsonValue::check_list_length(size_t max) const {
  if (j_->is_array() && j_->size() > max)
    fail("'" + name() + "' lists " + std::to_string(j_->size()) + " entries; at most " + std::to_string(max) +
         " are allowed");
}

// ---- JsonObject ------------------------------------------------------------------------------

JsonObject::JsonObject(std::shared_ptr<const JsonDoc> doc, std::string pointer, const nlohmann::json* j)
    : JsonValue(std::move(doc), std::move(pointer), j) {
  if (!j_->is_object()) fail("'" + name() + "' must be an object, got " + type_name(*j_));
}

bool JsonObject::has(const std::string& key) const { return j_->contains(key); }

std::optional<JsonValue> JsonObject::get(const std::string& key) {
  read_.insert(key);
  auto it = j_->find(key);
  if (it == j_->end()) return std::nullopt;
  return JsonValue(doc_, ptr_ + "/" + json_pointer_escape(key), &*it);
}

JsonValue JsonObject::require(const std::string& key) {
  auto v = get(key);
  if (!v)
    fail("missing required key '" + key + "' in " + (ptr_.empty() ? std::string("the top-level object") : "'" + name() + "'"));
  return *v;
}

double JsonObject::number(const std::string& key, double fallback, double min, double max) {
  auto v = get(key);
  return v ? v->number(min, max) : fallback;
}
double JsonObject::require_number(const std::string& key, double min, double max) {
  return require(key).number(min, max);
}
int64_t JsonObject::integer(const std::string& key, int64_t fallback, int64_t min, int64_t max) {
  auto v = get(key);
  return v ? v->integer(min, max) : fallback;
}
bool JsonObject::boolean(const std::string& key, bool fallback) {
  auto v = get(key);
  return v ? v->boolean() : fallback;
}
std::string JsonObject::string(const std::string& key, const std::string& fallback) {
  auto v = get(key);
  return v ? v->string() : fallback;
}
std::string JsonObject::require_string(const std::string& key) { return require(key).string(); }
std::string JsonObject::choice(const std::string& key, const std::string& fallback,
                               std::initializer_list<const char*> allowed) {
  auto v = get(key);
  return v ? v->choice(allowed) : fallback;
}
std::string JsonObject::choice(const std::string& key, const std::string& fallback,
                               const std::vector<const char*>& allowed) {
  auto v = get(key);
  return v ? v->choice(allowed) : fallback;
}
glm::dvec3 JsonObject::vec3(const std::string& key, glm::dvec3 fallback, double min, double max) {
  auto v = get(key);
  return v ? v->vec3(min, max) : fallback;
}
glm::dvec4 JsonObject::vec4(const std::string& key, glm::dvec4 fallback, double min, double max) {
  auto v = get(key);
  return v ? v->vec4(min, max) : fallback;
}
JsonObject JsonObject::require_object(const std::string& key) { return require(key).object(); }

std::vector<JsonObject> JsonObject::objects(const std::string& key) {
  std::vector<JsonObject> out;
  auto v = get(key);
  if (!v) return out;
  for (const JsonValue& e : v->array()) out.push_back(e.object());
  return out;
}

void JsonObject::check_list_length(const std::string& key, size_t max) const {
  if (!has(key)) return;
  const nlohmann::json& list = (*j_)[key];
  if (list.is_array() && list.size() > max)
    fail_key(key, "'" + key_path(key) + "' lists " + std::to_string(list.size()) + " entries; at most " + std::to_string(max) +
                      " are allowed");
}

void JsonObject::fail_key(const std::string& key, const std::string& message) const {
  throw InputError(doc_->where(ptr_ + "/" + json_pointer_escape(key)) + ": " + message);
}

void JsonObject::allow(std::initializer_list<const char*> keys) {
  for (const char* k : keys) read_.insert(k);
}

void JsonObject::finish() const {
  for (auto it = j_->begin(); it != j_->end(); ++it) {
    if (read_.count(it.key())) continue;
    std::vector<std::string> allowed(read_.begin(), read_.end());
    fail_key(it.key(), "unknown key '" + it.key() + "'" +
                           (ptr_.empty() ? std::string() : " in '" + name() + "'") +
                           "; allowed: " + join_allowed(allowed));
  }
}

}  // namespace arc
