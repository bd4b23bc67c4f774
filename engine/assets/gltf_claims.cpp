// assets/gltf_claims.cpp — a glTF file's version and required extensions, its node transforms and extent.
#include "assets/gltf_claims.h"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/json.h"

namespace arc {
namespace {

// Collects asset.version, asset.minVersion and the strings of extensionsRequired; every other
// value is passed over without being kept.
struct ClaimScanner : nlohmann::json_sax<nlohmann::json> {
  struct Frame { bool is_array; std::string key; };
  std::vector<Frame> stack;
  bool has_version = false;
  std::string version, min_version;
  bool version_not_string = false;
  std::vector<std::string> required;

  // A scalar (or the opening of a container) at depth 2: a member of "asset" or an element
  // of "extensionsRequired"; `text` is null for anything but a string.
  void scalar(const std::string* text) {
    if (stack.size() != 2 || stack[0].is_array) return;
    if (stack[0].key == "asset" && !stack[1].is_array) {
      if (stack[1].key == "version") {
        has_version = true;
        if (text) version = *text;
        else version_not_string = true;
      } else if (stack[1].key == "minVersion" && text) {
        min_version = *text;
      }
    } else if (stack[0].key == "extensionsRequired" && stack[1].is_array && text) {
      required.push_back(*text);
    }
  }
  bool null() override { scalar(nullptr); return true; }
  bool boolean(bool) override { scalar(nullptr); return true; }
  bool number_integer(number_integer_t) override { scalar(nullptr); return true; }
  bool number_unsigned(number_unsigned_t) override { scalar(nullptr); return true; }
  bool number_float(number_float_t, const string_t&) override { scalar(nullptr); return true; }
  bool string(string_t& s) override { scalar(&s); return true; }
  bool binary(binary_t&) override { scalar(nullptr); return true; }
  bool start_object(std::size_t) override { scalar(nullptr); stack.push_back({false, ""}); return true; }
  bool start_array(std::size_t) override { scalar(nullptr); stack.push_back({true, ""}); return true; }
  bool end_object() override { stack.pop_back(); return true; }
  bool end_array() override { stack.pop_back(); return true; }
  bool key(string_t& k) override { stack.back().key = k; return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }
};

// "2.0", "2.1": a major version of digits, a dot and a minor version of digits.
bool parse_version(const std::string& v, int& major, int& minor) {
  const size_t dot = v.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == v.size() || dot > 4 || v.size() - dot > 5) return false;
  for (size_t i = 0; i < v.size(); ++i)
    if (i != dot && (v[i] < '0' || v[i] > '9')) return false;
  major = std::stoi(v.substr(0, dot));
  minor = std::stoi(v.substr(dot + 1));
  return true;
}

}  // namespace

const std::vector<std::string>& gltf_supported_extensions() {
  static const std::vector<std::string> names{"KHR_materials_emissive_strength"};
  return names;
}

void check_gltf_claims(const char* json, size_t size, const std::string& path) {
  ClaimScanner scan;
  // Syntax errors are left to tinygltf, which names them; only what was read before counts.
  if (!nlohmann::json::sax_parse(json, json + size, &scan, nlohmann::json::input_format_t::json, false, true)) return;
  const std::string allowed_version = "allowed: \"2.0\" or another 2.x (glTF 2)";
  if (!scan.has_version)
    throw InputError(path + ": asset.version is missing; a glTF file states its version; " + allowed_version);
  int major = 0, minor = 0;
  if (scan.version_not_string || !parse_version(scan.version, major, minor) || major != 2)
    throw InputError(path + ": asset.version " +
                     (scan.version_not_string ? std::string("is not a string") : "'" + scan.version + "' is not glTF 2.x") +
                     "; " + allowed_version);
  if (!scan.min_version.empty() && scan.min_version != "2.0")
    throw InputError(path + ": asset.minVersion '" + scan.min_version +
                     "' asks for a newer glTF than this loader reads; allowed: \"2.0\"");
  for (const std::string& ext : scan.required) {
    bool known = false;
    for (const std::string& s : gltf_supported_extensions()) known = known || s == ext;
    if (!known)
      throw InputError(path + ": extensionsRequired lists '" + ext +
                       "', which this loader does not implement; allowed: " + join_allowed(gltf_supported_extensions()) +
                       " (export without compression or other required extensions)");
  }
}

static std::string short_num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

void check_gltf_world_transform(const glm::dmat4& world, const std::string& where) {
  double largest = 0.0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) largest = std::isfinite(world[c][r]) ? std::fmax(largest, std::fabs(world[c][r])) : HUGE_VAL;
  if (largest <= double(FLT_MAX)) return;
  throw InputError(where + " overflows the transform composed from the root (an entry reaches " + short_num(largest) +
                   "); allowed: transforms whose product stays within ±3.4e38 (single precision)");
}

void check_gltf_placed_vertices(const std::vector<glm::vec3>& positions, const std::string& where) {
  for (const glm::vec3& p : positions)
    for (int k = 0; k < 3; ++k)
      if (!(std::fabs(double(p[k])) <= kMaxModelExtent))
        throw InputError(where + ": places a vertex at " + short_num(double(p[k])) +
                         " m; allowed: vertices within ±1e9 m of the model's origin");
}

}  // namespace arc
