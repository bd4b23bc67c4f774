// The human-like test pilot (tests/unit/game/human_pilot.h: it sees only the HUD as drawn, reacts
// after 200–300 ms and moves the mouse in pixels through the player's input path) flies every
// mission (levels with a "mission" block of category mission) at easy, normal and hard over
// seeds 1..N, each fight to its end or 240 s of game time (600 s for the campaign's missions).
// It prints one Markdown table (see
// tests/unit/game/mission_flight.h for what each column counts) and, per mission and
// difficulty, the figures
//   test_pilot_<mission>_<difficulty>_win_rate, _kill_s, _beam_accuracy, _missile_accuracy,
//   _on_screen_share, _hidden_share
// Simulation only (no GL); deterministic, so any machine gives the same figures.
//   ARCFIRE_PILOT_SEEDS=N or NAME=N,...   seeds per mission (1..1000; duel 10, others 6)
//   ARCFIRE_PILOT_MISSIONS=NAME,...        only these missions (level names: duel, skirmish, ...)
//   ARCFIRE_PILOT_DIFFICULTIES=NAME,...    only these difficulties (easy, normal, hard)
//   ARCFIRE_PILOT_CSV=FILE.csv             also writes the table as CSV
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench_registry.h"
#include "core/data_root.h"
#include "core/file_writer.h"
#include "game/sim/game.h"
#include "mission_flight.h"

namespace {

constexpr int kDuelSeeds = 10, kOtherSeeds = 6;

[[noreturn]] void refuse(const char* var, const std::string& value, const std::string& allowed) {
  std::fprintf(stderr, "arcfire-bench: %s='%s' is not allowed; %s\n", var, value.c_str(), allowed.c_str());
  std::exit(2);
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

int seed_count(const char* var, const std::string& text) {
  char* end = nullptr;
  const long n = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || n < 1 || n > 1000) refuse(var, text, "seeds are a whole number from 1 to 1000");
  return int(n);
}

// Seeds per mission name from ARCFIRE_PILOT_SEEDS ("" is the default for missions not named).
std::map<std::string, int> seeds_from_env() {
  std::map<std::string, int> seeds{{"", 0}};
  const char* v = std::getenv("ARCFIRE_PILOT_SEEDS");
  if (!v) return seeds;
  const std::string text = v;
  if (text.find('=') == std::string::npos) return {{"", seed_count("ARCFIRE_PILOT_SEEDS", text)}};
  for (const std::string& item : split(text)) {
    const size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0) refuse("ARCFIRE_PILOT_SEEDS", text, "use N or NAME=N,NAME=N");
    seeds[item.substr(0, eq)] = seed_count("ARCFIRE_PILOT_SEEDS", item.substr(eq + 1));
  }
  return seeds;
}

// The missions to fly: every mission level, or those ARCFIRE_PILOT_MISSIONS names.
std::vector<std::string> missions_from_env(const std::string& root) {
  const std::vector<std::string> all = arc::mission_levels(root);
  const char* v = std::getenv("ARCFIRE_PILOT_MISSIONS");
  if (!v) return all;
  std::string names;
  for (const std::string& p : all) names += (names.empty() ? "" : ", ") + std::filesystem::path(p).stem().string();
  std::vector<std::string> chosen;
  for (const std::string& name : split(v)) {
    bool found = false;
    for (const std::string& p : all)
      if (std::filesystem::path(p).stem().string() == name) chosen.push_back(p), found = true;
    if (!found) refuse("ARCFIRE_PILOT_MISSIONS", v, "name missions among: " + names);
  }
  return chosen;
}

std::vector<int> difficulties_from_env() {
  const char* v = std::getenv("ARCFIRE_PILOT_DIFFICULTIES");
  if (!v) return {0, 1, 2};
  std::vector<int> out;
  for (const std::string& name : split(v)) {
    int found = -1;
    for (int d = 0; d < 3; ++d)
      if (name == arc::difficulty_name(static_cast<arc::Difficulty>(d))) found = d;
    if (found < 0) refuse("ARCFIRE_PILOT_DIFFICULTIES", v, "name difficulties among: easy, normal, hard");
    out.push_back(found);
  }
  return out;
}

void report(const arc::MissionFigures& f) {
  const std::string p = "test_pilot_" + f.mission + "_" + arc::difficulty_name(static_cast<arc::Difficulty>(f.difficulty));
  arc::bench::report_metric(p + "_win_rate", f.win_rate);
  arc::bench::report_metric(p + "_kill_s", f.mean_kill_s);
  arc::bench::report_metric(p + "_beam_accuracy", f.beam_accuracy);
  arc::bench::report_metric(p + "_missile_accuracy", f.missile_accuracy);
  arc::bench::report_metric(p + "_on_screen_share", f.on_screen_share);
  arc::bench::report_metric(p + "_hidden_share", f.hidden_share);
}

}  // namespace

ARCFIRE_SCENE(test_pilot) {
  const std::string root = arc::data_root();
  const std::map<std::string, int> seeds = seeds_from_env();
  const std::vector<std::string> missions = missions_from_env(root);
  const std::vector<int> difficulties = difficulties_from_env();
  const char* csv = std::getenv("ARCFIRE_PILOT_CSV");
  std::vector<arc::MissionFigures> rows;
  for (const std::string& level : missions) {
    const std::string name = std::filesystem::path(level).stem().string();
    int n = seeds.count(name) ? seeds.at(name) : seeds.at("");
    if (n == 0) n = name == "duel" ? kDuelSeeds : kOtherSeeds;
    for (int d : difficulties) {
      const double start = arc::bench::now_seconds();
      // Campaign missions (training first) run on their own clocks: up to 600 s of game time.
      const bool campaign = level.find("/campaign/") != std::string::npos || name == "training";
      rows.push_back(arc::mission_figures(root, level, d, n, {}, campaign ? 600.0 : 240.0));
      const arc::MissionFigures& f = rows.back();
      std::printf("  %-10s %-6s won %d, lost %d, timed out %d of %d  [%.1f s]\n", name.c_str(),
                  arc::difficulty_name(static_cast<arc::Difficulty>(d)), f.wins, f.losses, f.timeouts, f.fights,
                  arc::bench::now_seconds() - start);
      std::fflush(stdout);
      report(f);
    }
  }
  std::printf("\n%s\n", arc::figures_table(rows).c_str());
  if (!csv) return;
  try {
    arc::write_file_atomic(csv, arc::figures_csv(rows));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "arcfire-bench: ARCFIRE_PILOT_CSV: %s\n", e.what());
    std::exit(2);
  }
}
