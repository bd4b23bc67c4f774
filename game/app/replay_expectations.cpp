// Expectations of replay scripts evaluated against the World, and their names checked up front.
#include "game/app/replay_expectations.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/json.h"
#include "game/sim/world.h"

namespace arc {
namespace {

using replay::Expectation;

const Ship* find_ship(const World& w, const std::string& name) {
  for (const Ship& s : w.ships)
    if (s.name == name) return &s;
  return nullptr;
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

void check_expectation_names(const replay::Script& s, const World& w) {
  std::vector<std::string> names;
  for (const Ship& sh : w.ships) names.push_back("'" + sh.name + "'");
  auto require = [&](const Expectation& e, const std::string& name, int col) {
    if (name.empty() || find_ship(w, name)) return;
    throw InputError(s.path + ":" + std::to_string(e.src.line) + ":" + std::to_string(col) + ": no ship named '" + name +
                     "' in level " + w.level.name + "; ships: " + join_allowed(names));
  };
  std::vector<std::string> sounds;
  for (int k = 0; k <= int(SoundKind::EngineHum); ++k) sounds.push_back(sound_kind_name(SoundKind(k)));
  for (const Expectation& e : s.expectations) {
    require(e, e.ship, e.ship_col);
    require(e, e.other, e.other_col);
    if (e.kind == Expectation::Kind::Sound && std::find(sounds.begin(), sounds.end(), e.sound) == sounds.end())
      throw InputError(s.path + ":" + std::to_string(e.src.line) + ":" + std::to_string(e.sound_col) +
                       ": unknown sound event '" + e.sound + "'; allowed: " + join_allowed(sounds));
  }
  if (s.header.tick_rate && std::lround(1.0 / w.dt) != *s.header.tick_rate)
    throw InputError(s.path + ": header tick_rate " + std::to_string(*s.header.tick_rate) +
                     " differs from the level's " + std::to_string(std::lround(1.0 / w.dt)));
}

// "beam ×2, engine_hum ×2" for a failure message.
static std::string sounds_text(const std::vector<SoundEvent>& sounds) {
  std::string out;
  for (int k = 0; k <= int(SoundKind::EngineHum); ++k) {
    const auto n = std::count_if(sounds.begin(), sounds.end(), [&](const SoundEvent& s) { return int(s.kind) == k; });
    if (n > 0) out += (out.empty() ? "" : ", ") + std::string(sound_kind_name(SoundKind(k))) + " x" + std::to_string(n);
  }
  return out.empty() ? "none" : out;
}

std::optional<std::string> expectation_failure(const Expectation& e, const World& w,
                                               const std::vector<SoundEvent>& sounds) {
  const Ship* a = find_ship(w, e.ship);
  switch (e.kind) {
    case Expectation::Kind::Alive:
      if (a->alive) return std::nullopt;
      return e.ship + " was destroyed at tick " + std::to_string(a->death_tick);
    case Expectation::Kind::Destroyed:
      if (!a->alive) return std::nullopt;
      return e.ship + " is alive (hull " + number(a->hull) + ")";
    case Expectation::Kind::Hull:
      if (e.range.contains(a->hull)) return std::nullopt;
      return "hull of " + e.ship + " is " + number(a->hull);
    case Expectation::Kind::Shield:
      if (e.range.contains(a->shield)) return std::nullopt;
      return "shield of " + e.ship + " is " + number(a->shield);
    case Expectation::Kind::Position: {
      const glm::dvec3& p = a->position;
      if (e.box[0].contains(p.x) && e.box[1].contains(p.y) && e.box[2].contains(p.z)) return std::nullopt;
      return e.ship + " is at " + number(p.x) + " " + number(p.y) + " " + number(p.z);
    }
    case Expectation::Kind::Distance: {
      const Ship* b = find_ship(w, e.other);
      double d = glm::length(a->position - b->position);
      if (e.range.contains(d)) return std::nullopt;
      return "distance is " + number(d);
    }
    case Expectation::Kind::Particles: {
      double n = double(w.particles->stats().live_particles);
      if (e.range.contains(n)) return std::nullopt;
      return "particle count is " + number(n);
    }
    case Expectation::Kind::Kills:
      if (e.range.contains(a->kills)) return std::nullopt;
      return "kills of " + e.ship + " are " + std::to_string(a->kills);
    case Expectation::Kind::DamageDealt:
      if (e.range.contains(a->stats.damage_dealt)) return std::nullopt;
      return "damage dealt by " + e.ship + " is " + number(a->stats.damage_dealt);
    case Expectation::Kind::DamageTaken:
      if (e.range.contains(a->stats.damage_taken)) return std::nullopt;
      return "damage taken by " + e.ship + " is " + number(a->stats.damage_taken);
    case Expectation::Kind::Accuracy: {
      const CombatStats& st = a->stats;
      const bool beam = e.weapon == "beam";
      const int64_t hits = beam ? st.beam_hit_ticks : st.missiles_hit, shots = beam ? st.beam_ticks : st.missiles_fired;
      if (e.range.contains(accuracy(hits, shots))) return std::nullopt;
      return e.weapon + " accuracy of " + e.ship + " is " + number(accuracy(hits, shots)) + " (" +
             std::to_string(hits) + " hits of " + std::to_string(shots) + " shots)";
    }
    case Expectation::Kind::Sound:
      for (const SoundEvent& s : sounds)
        if (e.sound == sound_kind_name(s.kind)) return std::nullopt;
      return "no " + e.sound + " sound at this tick; sounds: " + sounds_text(sounds);
    case Expectation::Kind::Winner: {
      const std::string winner = w.outcome == Outcome::Undecided ? "none" : w.team_name(w.winner);
      if (winner == e.team) return std::nullopt;
      return "winner is " + winner;
    }
  }
  return std::nullopt;
}

}  // namespace arc
