// workbench/json_splice.h — edits JSON text in place, keeping its comments and formatting.
//
// Each edit replaces, inserts or removes bytes at the spans core/json records for every key and
// value (JsonDoc::value_span / key_span), so everything the edit does not touch stays byte for
// byte. New values are written in the file's own indentation: a block laid out one member per
// line gets a new line indented like its siblings, an inline one (`{ "a": 1 }`, `[[0, 1], [1, 0]]`)
// gets `, ` and the value. A removed member or element goes with its line when it has one to itself.
//
// Every function returns the new text, or throws InputError("<path>: ...") when the pointer does
// not name what the edit needs; validity of the result as an effect is the caller's business.
#pragma once
#include <string>
#include <nlohmann/json.hpp>

namespace arc {

// Sets the value at `pointer`; a missing key is added to its object, and objects missing on the
// way are added with it.
std::string splice_set(const std::string& text, const std::string& path, const std::string& pointer,
                       const nlohmann::json& value);
// Removes an object member or array element.
std::string splice_remove(const std::string& text, const std::string& path, const std::string& pointer);
// Inserts `value` into the array at `array_pointer` before `index` (index == size appends).
std::string splice_insert(const std::string& text, const std::string& path, const std::string& array_pointer,
                          size_t index, const nlohmann::json& value);
// Inserts the exact text of the element at `element_pointer` again right after it.
std::string splice_duplicate(const std::string& text, const std::string& path, const std::string& element_pointer);
// Moves the element at `from` so that it ends at index `to` (both indices < size).
std::string splice_move(const std::string& text, const std::string& path, const std::string& array_pointer,
                        size_t from, size_t to);

// A value as the file would write it at a line indented by `indent` (`unit` per level): numbers
// as nlohmann writes them (whole numbers without ".0"), short arrays and objects inline, longer
// objects one member per line.
std::string format_json(const nlohmann::json& value, const std::string& indent, const std::string& unit);

}  // namespace arc
