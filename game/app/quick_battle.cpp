// The quick battle: the classes on offer, the level built from a setup, and the remembered setup.
#include "game/app/quick_battle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/file_writer.h"
#include "core/input_file.h"
#include "core/json.h"
#include "game/app/quick_battle_files.h"
#include "game/app/user_settings.h"

namespace fs = std::filesystem;

namespace arc {
namespace {



constexpr const char* kSetupFile = "quick_battle.json";
constexpr int kSetupFormat = 1;

uint64_t fnv1a(const std::string& s) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

// SplitMix64: the asteroids' places, fixed by the setup.
uint64_t mix(uint64_t& state) {
  uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}
double unit(uint64_t& state) { return double(mix(state) >> 11) * (1.0 / 9007199254740992.0); }

bool has(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

// A fighting ship's main gun does damage (a training drone's and a freighter's do none).
bool armed(const nlohmann::json& j) {
  const auto beam = j.find("beam");
  if (beam == j.end() || !beam->is_object()) return false;
  const auto dps = beam->find("damage_per_second");
  return dps != beam->end() && dps->is_number() && dps->get<double>() > 0;
}

nlohmann::ordered_json ship(const std::string& name, const std::string& cls, const std::string& team,
                            const std::array<double, 3>& at, bool facing_back) {
  nlohmann::ordered_json s = {{"name", name}, {"class", cls}, {"team", team}, {"position", at}};
  if (facing_back) s["orientation"] = {180, 0, 0};
  return s;
}

void check_class(const std::string& what, const std::string& name, const std::vector<std::string>& allowed) {
  if (!has(allowed, name))
    throw InputError("quick battle: " + what + " '" + name + "' is not a class in the data; allowed: " + join_allowed(allowed));
}

void check_count(const std::string& what, int n, int lo, int hi) {
  if (n < lo || n > hi)
    throw InputError("quick battle: " + what + " must be " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " +
                     std::to_string(n));
}

std::vector<std::string> capital_choices(const QuickClasses& c) {
  std::vector<std::string> v{"none"};
  v.insert(v.end(), c.capitals.begin(), c.capitals.end());
  return v;
}

// Rocks in the space between the two sides, clear of every ship's start.
void add_asteroids(nlohmann::ordered_json& level, QuickAsteroids a, uint64_t seed,
                   const std::vector<std::array<double, 3>>& starts) {
  const int count = a == QuickAsteroids::Many ? 24 : a == QuickAsteroids::Few ? 8 : 0;
  level["props"] = nlohmann::ordered_json::array();
  uint64_t state = seed ^ 0xa57e401dull;
  for (int i = 0, tries = 0; i < count && tries < 1000; ++tries) {
    const double scale = 1.5 + 4.0 * unit(state);
    const double radius = std::round(scale * 10.0);
    const std::array<double, 3> p{std::round(-1600 + 3200 * unit(state)), std::round(-450 + 900 * unit(state)),
                                  std::round(-2300 + 2100 * unit(state))};
    bool clear = true;
    for (const auto& s : starts)
      clear = clear && std::hypot(p[0] - s[0], p[1] - s[1], p[2] - s[2]) > radius + 150.0;
    if (!clear) continue;
    const std::array<double, 3> turn{std::round(360 * unit(state)), std::round(180 * unit(state) - 90), 0};
    level["props"].push_back({{"model", "assets/models/asteroid.glb"}, {"position", p}, {"orientation", turn},
                              {"scale", std::round(scale * 10) / 10}, {"radius", radius}});
    ++i;
  }
}

}  // namespace

const char* asteroids_name(QuickAsteroids a) {
  return a == QuickAsteroids::None ? "none" : a == QuickAsteroids::Many ? "many" : "few";
}

QuickClasses quick_classes(const std::string& root_dir) {
  QuickClasses c;
  std::error_code ec;
  const fs::path dir = fs::path(root_dir) / "assets" / "ships";
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().extension() != ".json" || !it->is_regular_file(ec)) continue;
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(read_text_file(it->path().string()), nullptr, true, true);
    } catch (const std::exception&) {
      continue;
    }
    if (!j.is_object()) continue;
    const std::string name = it->path().stem().string();
    if (j.contains("turrets") || j.contains("subsystems"))
      c.capitals.push_back(name);
    else if (j.contains("thrust") && j["thrust"].is_number() && j["thrust"].get<double>() > 0 && armed(j))
      c.fighters.push_back(name);
  }
  std::sort(c.fighters.begin(), c.fighters.end());
  std::sort(c.capitals.begin(), c.capitals.end());
  return c;
}

QuickSetup default_quick_setup(const QuickClasses& classes) {
  QuickSetup s;
  auto pick = [&](std::string& name) {
    if (!has(classes.fighters, name) && !classes.fighters.empty()) name = classes.fighters.front();
  };
  pick(s.player);
  pick(s.wing);
  pick(s.enemy);
  return s;
}

std::string quick_level_json(const QuickSetup& s, const QuickClasses& classes) {
  check_class("player ship", s.player, classes.fighters);
  check_class("wing class", s.wing, classes.fighters);
  check_class("enemy class", s.enemy, classes.fighters);
  check_class("capital ship", s.capital, capital_choices(classes));
  check_count("wingmen", s.wingmen, 0, kQuickMaxWingmen);
  check_count("enemies", s.enemies, 1, kQuickMaxEnemies);
  const uint64_t seed = fnv1a(quick_setup_json(s)) % 1000000000ull;

  nlohmann::ordered_json level;
  level["name"] = "Quick battle";
  level["seed"] = seed;
  level["difficulty"] = difficulty_name(s.difficulty);
  level["objective"] = "Destroy every enemy ship.";
  level["win"] = {{"type", "destroy_all_hostiles"}};
  level["lose"] = {{"type", "player_destroyed"}};
  level["splash"] = {{"enabled", true}, {"radius", 50}, {"damage", 30}};
  auto& ships = level["ships"] = nlohmann::ordered_json::array();
  std::vector<std::array<double, 3>> starts;
  auto add = [&](nlohmann::ordered_json sh, const std::array<double, 3>& at) {
    starts.push_back(at);
    ships.push_back(std::move(sh));
  };
  nlohmann::ordered_json me = ship("Player", s.player, "blue", {0, 0, 0}, false);
  me["player"] = true;
  add(me, {0, 0, 0});
  for (int i = 0; i < s.wingmen; ++i) {
    const double side = i % 2 ? -1 : 1, row = i / 2;
    const std::array<double, 3> at{side * (70 + 60 * row), side * -10, -300 - 40 * row};
    nlohmann::ordered_json w = ship("Alpha " + std::to_string(i + 2), s.wing, "blue", at, false);
    w["wing"] = true;
    add(w, at);
  }
  for (int i = 0; i < s.enemies; ++i) {
    const double col = (i % 4) - 1.5, row = i / 4;
    const std::array<double, 3> at{col * 160, 40 - 60 * row, -2600 - 150 * row};
    add(ship("Red " + std::to_string(i + 1), s.enemy, "red", at, true), at);
  }
  if (s.capital != "none") {
    const std::array<double, 3> at = s.capital_friendly ? std::array<double, 3>{0, -120, 700}
                                                        : std::array<double, 3>{0, 0, -3600};
    add(ship(s.capital_friendly ? "Flagship" : "Red capital", s.capital, s.capital_friendly ? "blue" : "red", at,
             !s.capital_friendly),
        at);
  }
  add_asteroids(level, s.asteroids, seed, starts);
  return "// A quick battle generated from the menu's setup.\n" + level.dump(2) + "\n";
}

std::string quick_level_path(const std::string& user_dir, const std::string& level_text) {
  char name[40];
  std::snprintf(name, sizeof name, "quick-%016llx.json", static_cast<unsigned long long>(fnv1a(level_text)));
  return (fs::path(user_dir) / "quick" / name).string();
}

bool is_quick_level(const std::string& path) {
  const std::string stem = fs::path(path).stem().string();
  return stem.rfind("quick-", 0) == 0 && fs::path(path).parent_path().filename() == "quick";
}

QuickSetup parse_quick_setup(const std::string& text, const std::string& path, const QuickClasses& classes) {
  auto doc = JsonDoc::parse(text, path);
  JsonObject r = JsonValue(doc, "", &doc->root()).object();
  JsonValue f = r.require("format");
  if (f.integer(0, 1000000) != kSetupFormat)
    f.fail("'" + f.name() + "' must be " + std::to_string(kSetupFormat) + ", got " + f.raw().dump());
  QuickSetup s = default_quick_setup(classes);
  auto one_of = [&](const char* key, std::string& out, const std::vector<std::string>& allowed) {
    auto v = r.get(key);
    if (!v) return;
    out = v->string();
    if (!has(allowed, out)) v->fail("'" + v->name() + "' must be one of " + join_allowed(allowed) + ", got \"" + out + "\"");
  };
  one_of("player", s.player, classes.fighters);
  one_of("wing", s.wing, classes.fighters);
  one_of("enemy", s.enemy, classes.fighters);
  one_of("capital", s.capital, capital_choices(classes));
  s.wingmen = int(r.integer("wingmen", s.wingmen, 0, kQuickMaxWingmen));
  s.enemies = int(r.integer("enemies", s.enemies, 1, kQuickMaxEnemies));
  s.capital_friendly = r.choice("capital_side", "enemy", {"enemy", "player"}) == "player";
  const std::string a = r.choice("asteroids", "few", {"none", "few", "many"});
  s.asteroids = a == "none" ? QuickAsteroids::None : a == "many" ? QuickAsteroids::Many : QuickAsteroids::Few;
  const std::string d = r.choice("difficulty", "normal", {"easy", "normal", "hard"});
  s.difficulty = d == "easy" ? Difficulty::Easy : d == "hard" ? Difficulty::Hard : Difficulty::Normal;
  r.finish();
  return s;
}

std::string quick_setup_json(const QuickSetup& s) {
  nlohmann::ordered_json j;
  j["format"] = kSetupFormat;
  j["player"] = s.player;
  j["wingmen"] = s.wingmen;
  j["wing"] = s.wing;
  j["enemies"] = s.enemies;
  j["enemy"] = s.enemy;
  j["capital"] = s.capital;
  j["capital_side"] = s.capital_friendly ? "player" : "enemy";
  j["asteroids"] = asteroids_name(s.asteroids);
  j["difficulty"] = difficulty_name(s.difficulty);
  return j.dump(2) + "\n";
}

QuickSetup load_quick_setup(const std::string& dir, const QuickClasses& classes, std::string& message) {
  const std::string path = (fs::path(dir) / kSetupFile).string();
  const QuickSetup fallback = default_quick_setup(classes);
  if (!input_path_exists(path)) return fallback;
  try {
    return parse_quick_setup(read_text_file(path), path, classes);
  } catch (const InputError& e) {
    const std::string m = replace_bad_file(path, quick_setup_json(fallback), e.what());
    message += (message.empty() ? "" : "\n") + m;
    return fallback;
  }
}

void save_quick_setup(const std::string& dir, const QuickSetup& s) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir + ": cannot make the folder (" + ec.message() + ")");
  write_file_atomic((fs::path(dir) / kSetupFile).string(), quick_setup_json(s));
}

}  // namespace arc

namespace arc {

void write_generated_level(const std::string& path, const std::string& text) {
  std::error_code ec;
  fs::create_directories(fs::path(path).parent_path(), ec);
  if (ec) throw InputError(fs::path(path).parent_path().string() + ": cannot make the folder (" + ec.message() + ")");
  write_file_atomic(path, text);
}

std::string copy_beside_recording(const std::string& level, const std::string& record_path) {
  const std::string copy = fs::path(record_path).replace_extension(".level.json").string();
  write_file_atomic(copy, read_text_file(level));
  return copy;
}

}  // namespace arc
