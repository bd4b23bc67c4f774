// game/sim/outcome.cpp — victory, defeat or the winning team, by the level's win and lose rules;
// a wave's ships still waiting to arrive count as in the fight.
#include "game/sim/outcome.h"

#include <algorithm>

#include "game/sim/mission_events.h"
#include "game/sim/training.h"
#include "game/sim/world.h"

namespace arc {
namespace {

void decide(World& w, Outcome o, TeamId winner) {
  w.outcome = o;
  w.winner = winner;
  w.outcome_tick = w.tick;
}

TeamId first_live_team(const World& w, TeamId except) {
  for (const Ship& s : w.ships)
    if (in_fight(s) && s.team != except) return s.team;
  return {};
}

}  // namespace

void update_outcome(World& w) {
  if (w.outcome != Outcome::Undecided) return;
  const LevelDef& L = w.level;
  const Ship* player = w.player ? &w.ship(w.player) : nullptr;
  const TeamId side = player ? player->team : w.ships.front().team;
  if (L.lose == LoseKind::PlayerDestroyed && player && !player->alive)
    return decide(w, Outcome::Defeat, first_live_team(w, side));
  if (L.lose == LoseKind::Protect) {
    for (const Ship& s : w.ships)
      if (s.name == L.protect_ship && !s.alive) return decide(w, Outcome::Defeat, first_live_team(w, side));
  }
  switch (L.win) {
    case WinKind::DestroyAllHostiles: {
      bool any = false, friends = false;
      for (const Ship& s : w.ships) {
        any = any || (in_fight(s) && s.team != side);
        friends = friends || (in_fight(s) && s.team == side);
      }
      if (!any) decide(w, player ? Outcome::Victory : Outcome::TeamWon, side);
      else if (!friends) decide(w, player ? Outcome::Defeat : Outcome::TeamWon, first_live_team(w, side));
      break;
    }
    case WinKind::Objectives:
      if (primary_objective_failed(w)) decide(w, player ? Outcome::Defeat : Outcome::TeamWon, first_live_team(w, side));
      else if (primary_objectives_done(w)) decide(w, player ? Outcome::Victory : Outcome::TeamWon, side);
      break;
    case WinKind::TrainingComplete:
      if (training_complete(w)) decide(w, Outcome::Victory, side);
      break;
    case WinKind::SurviveTicks:
      if (w.tick >= L.win_ticks) decide(w, player ? Outcome::Victory : Outcome::TeamWon, side);
      break;
    case WinKind::LastTeamStanding: {
      std::vector<TeamId> teams;
      for (const Ship& s : w.ships)
        if (in_fight(s) && std::find(teams.begin(), teams.end(), s.team) == teams.end()) teams.push_back(s.team);
      if (teams.size() > 1) break;
      const TeamId winner = teams.empty() ? TeamId{} : teams.front();
      if (player) decide(w, player->team == winner ? Outcome::Victory : Outcome::Defeat, winner);
      else decide(w, Outcome::TeamWon, winner);
      break;
    }
  }
}

}  // namespace arc
