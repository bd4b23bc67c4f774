#include "game/workbench/json_splice.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/error.h"
#include "core/json.h"

namespace arc {
namespace {

using nlohmann::json;
using Pointer = json::json_pointer;

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw InputError(path + ": " + message); }

size_t line_start(const std::string& t, size_t pos) {
  if (pos == 0) return 0;
  const size_t p = t.rfind('\n', pos - 1);
  return p == std::string::npos ? 0 : p + 1;
}
size_t line_end(const std::string& t, size_t pos) {
  const size_t p = t.find('\n', pos);
  return p == std::string::npos ? t.size() : p;
}
std::string indent_at(const std::string& t, size_t pos) {
  const size_t s = line_start(t, pos);
  size_t e = s;
  while (e < t.size() && (t[e] == ' ' || t[e] == '\t')) ++e;
  return t.substr(s, e - s);
}
bool blank_before(const std::string& t, size_t pos) {
  for (size_t i = line_start(t, pos); i < pos; ++i)
    if (t[i] != ' ' && t[i] != '\t') return false;
  return true;
}
// Only spaces, tabs or a // comment from pos to the end of its line.
bool blank_after(const std::string& t, size_t pos) {
  for (size_t i = pos; i < t.size() && t[i] != '\n'; ++i) {
    if (t[i] == '/' && i + 1 < t.size() && t[i + 1] == '/') return true;
    if (t[i] != ' ' && t[i] != '\t' && t[i] != '\r') return false;
  }
  return true;
}
// The first ',' after pos (separators follow values directly or after blanks and comments).
size_t comma_after(const std::string& t, size_t pos) {
  size_t i = pos;
  while (i < t.size() && t[i] != ',') {
    if (t[i] == '/' && i + 1 < t.size() && t[i + 1] == '/') i = line_end(t, i);
    else if (t[i] == '/' && i + 1 < t.size() && t[i + 1] == '*') i = std::min(t.size(), t.find("*/", i + 2) + 2);
    else ++i;
  }
  return i;
}

// The file's indentation step: the leading blanks of its first indented line that holds a value.
std::string indent_unit(const std::string& t) {
  for (size_t s = 0; s < t.size(); s = line_end(t, s) + 1) {
    const std::string ind = indent_at(t, s);
    const size_t c = s + ind.size();
    if (!ind.empty() && c < t.size() && t[c] != '\n' && t[c] != '/') return ind;
  }
  return "  ";
}

struct Container {
  TextSpan span;
  bool is_array = false;
  std::vector<TextSpan> items;  // file order; an object member runs from its key to its value's end
};

struct Parsed {
  std::shared_ptr<const JsonDoc> doc;
  Pointer pointer(const std::string& p) const {
    try {
      return Pointer(p);
    } catch (const json::exception&) {
      fail(doc->path(), "'" + p + "' is not a JSON pointer");
    }
  }
  bool contains(const Pointer& p) const {
    try {
      return doc->root().contains(p);
    } catch (const json::exception&) {
      return false;
    }
  }
  TextSpan span(const std::string& p) const {
    TextSpan s;
    if (!doc->value_span(p, s)) fail(doc->path(), "no value at '" + p + "'");
    return s;
  }
  Container container(const std::string& p) const {
    const Pointer jp = pointer(p);
    if (!contains(jp)) fail(doc->path(), "no value at '" + p + "'");
    const json& v = doc->root()[jp];
    if (!v.is_array() && !v.is_object()) fail(doc->path(), "'" + p + "' is not an array or object");
    Container c;
    c.span = span(p);
    c.is_array = v.is_array();
    if (c.is_array) {
      for (size_t i = 0; i < v.size(); ++i) c.items.push_back(span(p + "/" + std::to_string(i)));
      return c;
    }
    for (const auto& [k, child] : v.items()) {
      const std::string cp = p + "/" + json_pointer_escape(k);
      TextSpan key;
      doc->key_span(cp, key);
      c.items.push_back({key.begin, span(cp).end});
    }
    std::sort(c.items.begin(), c.items.end(), [](const TextSpan& a, const TextSpan& b) { return a.begin < b.begin; });
    return c;
  }
};

Parsed parse(const std::string& text, const std::string& path) { return Parsed{JsonDoc::parse(text, path)}; }

bool multi_line(const std::string& t, const Container& c) {
  return !c.items.empty() && line_start(t, c.items[0].begin) != line_start(t, c.span.begin);
}
// The indentation a value inside the container is written at.
std::string child_indent(const std::string& t, const Container& c) {
  return multi_line(t, c) ? indent_at(t, c.items[0].begin) : indent_at(t, c.span.begin) + indent_unit(t);
}

std::string insert_item(std::string t, const Container& c, size_t index, const std::string& item) {
  if (c.items.empty()) return t.substr(0, c.span.begin + 1) + item + t.substr(c.span.end - 1);
  const bool multi = multi_line(t, c);
  const std::string indent = indent_at(t, c.items[0].begin);
  if (index < c.items.size()) return t.insert(c.items[index].begin, item + (multi ? ",\n" + indent : ", "));
  const size_t last = c.items.back().end;
  if (!multi) return t.insert(last, ", " + item);
  t.insert(line_end(t, last), "\n" + indent + item);
  return t.insert(last, ",");
}

// Three cases (only item, item with a successor, last item), each in an own-line form (the item
// goes with its lines, comments on them included) and an inline form (with one separator).
std::string remove_item(std::string t, const Container& c, size_t index) {
  const size_t b = c.items[index].begin, e = c.items[index].end;
  const size_t n = c.items.size();
  if (n == 1) {
    if (!blank_before(t, b) || !blank_after(t, e)) return t.erase(b, e - b);
    const size_t from = line_start(t, b) > 0 ? line_start(t, b) - 1 : 0;
    return t.erase(from, line_end(t, e) - from);
  }
  if (index + 1 < n) {
    const size_t comma = comma_after(t, e);
    const size_t next = c.items[index + 1].begin;
    if (blank_before(t, b) && blank_after(t, comma + 1) && line_start(t, next) != line_start(t, comma)) {
      const size_t from = line_start(t, b);
      return t.erase(from, std::min(t.size(), line_end(t, comma) + 1) - from);
    }
    return t.erase(b, next - b);
  }
  const size_t prev_end = c.items[index - 1].end;
  const size_t comma = comma_after(t, prev_end);
  if (blank_before(t, b) && blank_after(t, e) && line_start(t, b) > comma) {
    const size_t from = line_start(t, b) - 1;
    t.erase(from, line_end(t, e) - from);
    return t.erase(comma, 1);
  }
  return t.erase(prev_end, e - prev_end);
}

std::string member_text(const std::string& key, const std::string& value) { return json(key).dump() + ": " + value; }

}  // namespace

std::string format_json(const json& v, const std::string& indent, const std::string& unit) {
  if (v.is_number_float()) {
    const double d = v.get<double>();
    if (std::isfinite(d) && d == std::floor(d) && std::abs(d) < 1e15) return std::to_string(static_cast<long long>(d));
    return v.dump();
  }
  if (!v.is_structured()) return v.dump();
  if (v.empty()) return v.is_array() ? "[]" : "{}";
  bool nested_object = false;
  for (const json& e : v) nested_object = nested_object || e.is_object() || (v.is_object() && e.is_array() && !e.empty() && e[0].is_object());
  std::vector<std::string> parts;
  const std::string inner = indent + unit;
  for (auto it = v.begin(); it != v.end(); ++it) {
    const std::string value = format_json(*it, nested_object ? inner : indent, unit);
    parts.push_back(v.is_object() ? member_text(it.key(), value) : value);
  }
  const char* open = v.is_array() ? "[" : "{ ";
  const char* close = v.is_array() ? "]" : " }";
  std::string line;
  for (const std::string& p : parts) line += (line.empty() ? "" : ", ") + p;
  if (!nested_object && indent.size() + line.size() < 100) return open + line + close;
  std::string out = v.is_array() ? "[\n" : "{\n";
  for (size_t i = 0; i < parts.size(); ++i) out += inner + parts[i] + (i + 1 < parts.size() ? ",\n" : "\n");
  return out + indent + (v.is_array() ? "]" : "}");
}

std::string splice_set(const std::string& text, const std::string& path, const std::string& pointer, const json& value) {
  const Parsed p = parse(text, path);
  Pointer at = p.pointer(pointer);
  if (p.contains(at)) {
    const TextSpan s = p.span(pointer);
    std::string t = text;
    return t.replace(s.begin, s.end - s.begin, format_json(value, indent_at(text, s.begin), indent_unit(text)));
  }
  json built = value;
  std::string key = at.back();
  at.pop_back();
  while (!p.contains(at)) {
    built = json{{key, built}};
    key = at.back();
    at.pop_back();
  }
  if (!p.doc->root()[at].is_object()) fail(path, "no value at '" + pointer + "'");
  const Container c = p.container(at.to_string());
  const std::string value_text = format_json(built, child_indent(text, c), indent_unit(text));
  return insert_item(text, c, c.items.size(), member_text(key, value_text));
}

std::string splice_remove(const std::string& text, const std::string& path, const std::string& pointer) {
  const Parsed p = parse(text, path);
  Pointer at = p.pointer(pointer);
  if (at.empty() || !p.contains(at)) fail(path, "no value at '" + pointer + "' to remove");
  const std::string last = at.back();
  at.pop_back();
  const Container c = p.container(at.to_string());
  const json& parent = p.doc->root()[at];
  size_t index = 0;
  if (parent.is_array()) {
    index = size_t(std::stoul(last));
  } else {
    TextSpan key;
    p.doc->key_span(pointer, key);
    while (c.items[index].begin != key.begin) ++index;
  }
  return remove_item(text, c, index);
}

std::string splice_insert(const std::string& text, const std::string& path, const std::string& array_pointer,
                          size_t index, const json& value) {
  const Parsed p = parse(text, path);
  const Container c = p.container(array_pointer);
  if (!c.is_array) fail(path, "'" + array_pointer + "' is not an array");
  if (index > c.items.size())
    fail(path, "cannot insert at " + std::to_string(index) + " into '" + array_pointer + "' of " +
                   std::to_string(c.items.size()) + " elements");
  return insert_item(text, c, index, format_json(value, child_indent(text, c), indent_unit(text)));
}

std::string splice_duplicate(const std::string& text, const std::string& path, const std::string& element_pointer) {
  const Parsed p = parse(text, path);
  Pointer at = p.pointer(element_pointer);
  if (at.empty() || !p.contains(at)) fail(path, "no element at '" + element_pointer + "'");
  const std::string last = at.back();
  at.pop_back();
  const Container c = p.container(at.to_string());
  if (!c.is_array) fail(path, "'" + element_pointer + "' is not an array element");
  const size_t index = size_t(std::stoul(last));
  const TextSpan s = c.items[index];
  return insert_item(text, c, index + 1, text.substr(s.begin, s.end - s.begin));
}

std::string splice_move(const std::string& text, const std::string& path, const std::string& array_pointer,
                        size_t from, size_t to) {
  const Parsed p = parse(text, path);
  const Container c = p.container(array_pointer);
  if (!c.is_array) fail(path, "'" + array_pointer + "' is not an array");
  if (from >= c.items.size() || to >= c.items.size())
    fail(path, "cannot move element " + std::to_string(from) + " to " + std::to_string(to) + " in '" + array_pointer +
                   "' of " + std::to_string(c.items.size()) + " elements");
  if (from == to) return text;
  const std::string item = text.substr(c.items[from].begin, c.items[from].end - c.items[from].begin);
  const std::string removed = remove_item(text, c, from);
  const Parsed q = parse(removed, path);
  return insert_item(removed, q.container(array_pointer), to, item);
}

}  // namespace arc
