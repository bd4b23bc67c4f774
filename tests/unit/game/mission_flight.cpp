// tests/unit/game/mission_flight.cpp — missions flown by the human-like test pilot to their end,
// and the figures over seeds.
#include "mission_flight.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <map>
#include <glm/geometric.hpp>

#include "game/sim/defs.h"
#include "game/sim/game.h"
#include "game/sim/geometry.h"
#include "game/sim/world.h"

namespace arc {
namespace {

constexpr double kNoseDeg = 20.0;  // "near the nose", where a hidden target costs a shot

// Per hostile: what was left of it last tick and when the player first hurt it.
struct HostileTrack {
  double left = 0;
  int64_t first_hit = -1;
  bool counted = false;
};

// One tick's share of the figures: the target's picture, the player's first hits and kills.
// (The first call, before the first tick, only registers the hostiles.)
void count_tick(const World& w, const HumanPilot& pilot, std::map<uint32_t, HostileTrack>& hostiles, MissionRun& r) {
  const Ship& me = w.ship(w.player);
  const Sight& s = pilot.now();
  if (me.alive && s.target) {
    ++r.target_ticks;
    r.on_screen_ticks += s.on_screen ? 1 : 0;
    const Ship& t = w.ship(me.target);
    const glm::dvec3 to = safe_norm(t.position - me.position, glm::dvec3(0, 0, -1));
    if (glm::dot(to, forward_of(me.orientation)) >= std::cos(kNoseDeg * kDeg)) {
      ++r.near_nose_ticks;
      r.hidden_ticks += s.hidden ? 1 : 0;
    }
  }
  // Hostiles are tracked from the first tick they fly (waves may join later).
  for (size_t i = 0; i < w.ships.size(); ++i) {
    const Ship& e = w.ships[i];
    auto it = hostiles.find(uint32_t(i));
    if (it == hostiles.end()) {
      if (e.alive && w.hostile(me, e)) hostiles[uint32_t(i)] = {e.hull + e.shield};
      continue;
    }
    HostileTrack& h = it->second;
    const double left = e.alive ? e.hull + e.shield : 0.0;
    if (h.first_hit < 0 && left < h.left && e.last_attacker == me.id) h.first_hit = w.tick;
    h.left = left;
    if (!e.alive && !h.counted) {
      h.counted = true;
      if (e.last_attacker == me.id && h.first_hit >= 0) {
        ++r.kills;
        r.kill_s.push_back(double(w.tick - h.first_hit) * w.dt);
      }
    }
  }
}

std::string printf_line(const char* format, ...) {
  char buf[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  return buf;
}

std::string mission_name(const std::string& path) { return std::filesystem::path(path).stem().string(); }

}  // namespace

MissionRun fly_mission(const std::string& root_dir, const std::string& level_path, int difficulty, uint64_t seed,
                       const HumanSkill& skill, double max_seconds) {
  GameOptions o;
  o.root_dir = root_dir;
  o.difficulty_override = true;
  o.difficulty = static_cast<Difficulty>(std::clamp(difficulty, 0, 2));
  o.seed_override = true;
  o.seed = seed;
  // The briefing's suggestion, as the menu offers it first.
  if (const LevelDef def = load_level_def(level_path, root_dir); def.loadout.present) {
    o.ship = def.loadout.suggested_ship;
    o.loadout = loadout_text(def.loadout.suggested);
  }
  Game g = Game::load_level(level_path, o);
  const World& w = g.world();
  HumanPilot pilot(w, root_dir, seed, skill);
  MissionRun r;
  std::map<uint32_t, HostileTrack> hostiles;
  r.reaction_s = pilot.reaction_s();
  r.tick_s = w.dt;
  count_tick(w, pilot, hostiles, r);
  InputFrame in;
  std::vector<Command> keys;
  const int64_t limit = seconds_to_ticks(w, max_seconds);
  while (w.outcome == Outcome::Undecided && w.ship(w.player).alive && w.tick < limit) {
    pilot.act(w, in, keys);
    g.step(in, keys);
    count_tick(w, pilot, hostiles, r);
  }
  r.hostiles = int(hostiles.size());
  const Ship& end = w.ship(w.player);
  r.end = w.outcome == Outcome::Victory                ? FightEnd::Won
          : w.outcome != Outcome::Undecided || !end.alive ? FightEnd::Lost
                                                        : FightEnd::Timeout;
  r.seconds = double(w.outcome != Outcome::Undecided ? w.outcome_tick : w.tick) * w.dt;
  r.beam_ticks = end.stats.beam_ticks;
  r.beam_hit_ticks = end.stats.beam_hit_ticks;
  r.missiles_fired = end.stats.missiles_fired;
  r.missiles_hit = end.stats.missiles_hit;
  r.damage_dealt = end.stats.damage_dealt;
  r.damage_taken = end.stats.damage_taken;
  return r;
}

MissionFigures mission_figures(const std::string& root_dir, const std::string& level_path, int difficulty, int seeds,
                               const HumanSkill& skill, double max_seconds) {
  MissionFigures f;
  f.mission = mission_name(level_path);
  f.difficulty = difficulty;
  MissionRun sum;
  double reaction = 0, tick_s = 0;
  for (int s = 1; s <= seeds; ++s) {
    const MissionRun r = fly_mission(root_dir, level_path, difficulty, uint64_t(s), skill, max_seconds);
    ++f.fights;
    f.wins += r.end == FightEnd::Won;
    f.losses += r.end == FightEnd::Lost;
    f.timeouts += r.end == FightEnd::Timeout;
    sum.kill_s.insert(sum.kill_s.end(), r.kill_s.begin(), r.kill_s.end());
    sum.kills += r.kills;
    sum.beam_ticks += r.beam_ticks, sum.beam_hit_ticks += r.beam_hit_ticks;
    sum.missiles_fired += r.missiles_fired, sum.missiles_hit += r.missiles_hit;
    sum.damage_dealt += r.damage_dealt, sum.damage_taken += r.damage_taken;
    sum.target_ticks += r.target_ticks, sum.on_screen_ticks += r.on_screen_ticks;
    sum.near_nose_ticks += r.near_nose_ticks, sum.hidden_ticks += r.hidden_ticks;
    sum.seconds += r.seconds;
    reaction += r.reaction_s;
    tick_s = r.tick_s;
  }
  const double n = std::max(f.fights, 1);
  f.win_rate = f.wins / n;
  for (double k : sum.kill_s) f.mean_kill_s += k / double(sum.kill_s.size());
  f.kills_per_fight = sum.kills / n;
  f.beam_s_per_fight = double(sum.beam_ticks) * tick_s / n;
  f.missiles_per_fight = double(sum.missiles_fired) / n;
  f.beam_accuracy = accuracy(sum.beam_hit_ticks, sum.beam_ticks);
  f.missile_accuracy = accuracy(sum.missiles_hit, sum.missiles_fired);
  f.on_screen_share = accuracy(sum.on_screen_ticks, sum.target_ticks);
  f.hidden_share = accuracy(sum.hidden_ticks, sum.near_nose_ticks);
  f.damage_dealt = sum.damage_dealt / n;
  f.damage_taken = sum.damage_taken / n;
  f.mean_fight_s = sum.seconds / n;
  f.reaction_s = reaction / n;
  return f;
}

std::vector<std::string> mission_levels(const std::string& root_dir) {
  struct Entry {
    int order;
    std::string path;
  };
  std::vector<Entry> found;
  std::vector<std::filesystem::path> files;
  for (const char* dir : {"/levels", "/levels/campaign"})
    for (const auto& e : std::filesystem::directory_iterator(root_dir + dir)) files.push_back(e.path());
  for (const auto& path : files) {
    if (path.extension() != ".json" || path.filename() == "campaign.json") continue;
    const LevelDef def = load_level_def(path.string(), root_dir);
    if (def.mission.present && def.mission.category == MissionCategory::Mission)
      found.push_back({def.mission.order, path.string()});
  }
  std::sort(found.begin(), found.end(),
            [](const Entry& a, const Entry& b) { return a.order != b.order ? a.order < b.order : a.path < b.path; });
  std::vector<std::string> out;
  for (const Entry& e : found) out.push_back(e.path);
  return out;
}

std::string figures_table(const std::vector<MissionFigures>& rows) {
  std::string out =
      "| mission | difficulty | fights | won / lost / timed out | win rate | kill time s | kills per fight | "
      "beam accuracy | missile accuracy | target on screen | target hidden | damage dealt / taken | fight s |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const MissionFigures& f : rows)
    out += printf_line("| %s | %s | %d | %d / %d / %d | %.2f | %.1f | %.2f | %.3f | %.2f | %.2f | %.3f | %.0f / %.0f | %.1f |\n",
               f.mission.c_str(), difficulty_name(static_cast<Difficulty>(f.difficulty)), f.fights, f.wins, f.losses,
               f.timeouts, f.win_rate, f.mean_kill_s, f.kills_per_fight, f.beam_accuracy, f.missile_accuracy,
               f.on_screen_share, f.hidden_share, f.damage_dealt, f.damage_taken, f.mean_fight_s);
  return out;
}

std::string figures_csv(const std::vector<MissionFigures>& rows) {
  std::string out =
      "mission,difficulty,fights,wins,losses,timeouts,win_rate,mean_kill_s,kills_per_fight,beam_accuracy,"
      "missile_accuracy,beam_s_per_fight,missiles_per_fight,on_screen_share,hidden_share,damage_dealt,damage_taken,"
      "mean_fight_s,reaction_s\n";
  for (const MissionFigures& f : rows)
    out += printf_line("%s,%s,%d,%d,%d,%d,%.4f,%.3f,%.3f,%.4f,%.4f,%.2f,%.2f,%.4f,%.4f,%.1f,%.1f,%.2f,%.3f\n",
                       f.mission.c_str(), difficulty_name(static_cast<Difficulty>(f.difficulty)), f.fights, f.wins,
                       f.losses, f.timeouts, f.win_rate, f.mean_kill_s, f.kills_per_fight, f.beam_accuracy,
                       f.missile_accuracy, f.beam_s_per_fight, f.missiles_per_fight, f.on_screen_share,
                       f.hidden_share, f.damage_dealt, f.damage_taken, f.mean_fight_s, f.reaction_s);
  return out;
}

}  // namespace arc
