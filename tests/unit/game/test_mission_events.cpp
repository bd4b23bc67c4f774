// Mission events: each trigger and each action in a small level, the objectives' win rule,
// the autopilot, waves through the same spawn, and events in the hash and the snapshot.
#include <gtest/gtest.h>

#include <string>

#include "game/render/hud_objectives.h"
#include "game/sim/mission_events.h"
#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

const std::string kShips = R"(
    { "name": "Lead", "class": "viper", "team": "blue", "player": true, "position": [0, 0, 0] },
    { "name": "Hauler", "class": "warden", "team": "blue", "ai": "none", "position": [200, 0, 0] },
    { "name": "Red 1", "class": "dart", "team": "red", "ai": "none", "position": [0, 0, -3000] },
    { "name": "Red 2", "class": "dart", "team": "red", "ai": "none", "position": [100, 0, -3000], "group": "raiders" },
    { "name": "Red 3", "class": "dart", "team": "red", "ai": "none", "position": [150, 0, -3000], "group": "raiders" },
    { "name": "Late", "class": "dart", "team": "red", "ai": "none", "inactive": true, "group": "late", "position": [0, 0, -5000] })";

const std::string kObjectives = R"(
  "objectives": [
    { "id": "escort", "text": "Keep the Hauler alive", "kind": "primary" },
    { "id": "bonus", "text": "Down Red 1", "kind": "secondary" },
    { "id": "secret", "text": "Find the cache", "kind": "hidden" } ],)";

// The events given, then one that would bring Late in at the end of the hour (every inactive
// ship needs something that spawns it).
std::string level(std::string events, const std::string& win = "destroy_all_hostiles") {
  const std::string late = R"({ "id": "zz_late", "when": { "type": "time", "seconds": 3600 }, "do": [ { "type": "spawn", "ship": "Late" } ] })";
  events.insert(events.rfind(']'), events.find('{') == std::string::npos ? late : ", " + late);
  std::string text = test::level_text(kShips, kObjectives + "\n  \"events\": " + events + ",");
  const std::string from = "\"win\": { \"type\": \"destroy_all_hostiles\" }";
  text.replace(text.find(from), from.size(), "\"win\": { \"type\": \"" + win + "\" }");
  return text;
}

Game load(const std::string& text, const std::string& name, GameOptions o = test::options()) {
  return Game::load_level(test::write_level(name, text), o);
}

void run_to(Game& g, int64_t tick) {
  while (g.world().tick < tick) g.step({});
}

int64_t fired(const Game& g, size_t i) { return g.world().mission->events[i].fired_tick; }

bool has_message(const World& w, const std::string& text) {
  for (const SimMessage& m : w.messages)
    if (m.text == text) return true;
  return false;
}

void destroy(World& w, size_t i) {
  w.ships[i].alive = false;
  w.ships[i].hull = 0;
  w.ships[i].death_tick = w.tick;
}

// ---------------------------------------------------------------- triggers

TEST(MissionTriggers, TimeFiresAtItsSecondAndDelayWaitsAfterIt) {
  Game g = load(level(R"([
    { "id": "a", "when": { "type": "time", "seconds": 1 }, "do": [ { "type": "message", "text": "one" } ] },
    { "id": "b", "when": { "type": "time", "seconds": 1 }, "delay": 0.5, "do": [ { "type": "message", "text": "two" } ] } ])"),
             "ev_time.json");
  run_to(g, 59);
  EXPECT_EQ(fired(g, 0), -1);
  run_to(g, 60);
  EXPECT_EQ(fired(g, 0), 60);
  EXPECT_EQ(g.world().mission->events[1].armed_tick, 60);
  EXPECT_TRUE(has_message(g.world(), "one"));
  run_to(g, 90);
  EXPECT_EQ(fired(g, 1), 90);
}

TEST(MissionTriggers, DestroyedShipAndWholeGroup) {
  Game g = load(level(R"([
    { "id": "ship", "when": { "type": "destroyed", "ship": "Red 1" }, "do": [ { "type": "message", "text": "s" } ] },
    { "id": "group", "when": { "type": "destroyed", "group": "raiders" }, "do": [ { "type": "message", "text": "g" } ] } ])"),
             "ev_destroyed.json");
  run_to(g, 5);
  destroy(g.world_mut(), 2);
  destroy(g.world_mut(), 3);
  run_to(g, 6);
  EXPECT_EQ(fired(g, 0), 6);
  EXPECT_EQ(fired(g, 1), -1);  // Red 3 of the group still flies
  destroy(g.world_mut(), 4);
  run_to(g, 7);
  EXPECT_EQ(fired(g, 1), 7);
}

TEST(MissionTriggers, HullBelowAFraction) {
  Game g = load(level(R"([
    { "id": "hurt", "when": { "type": "hull_below", "ship": "Hauler", "fraction": 0.5 }, "do": [ { "type": "message", "text": "h" } ] } ])"),
             "ev_hull.json");
  World& w = g.world_mut();
  w.ships[1].hull = 0.6 * w.ships[1].cls->hull;
  run_to(g, 3);
  EXPECT_EQ(fired(g, 0), -1);
  g.world_mut().ships[1].hull = 0.4 * w.ships[1].cls->hull;
  run_to(g, 4);
  EXPECT_EQ(fired(g, 0), 4);
}

TEST(MissionTriggers, AreaEntered) {
  Game g = load(level(R"([
    { "id": "nav", "when": { "type": "area_entered", "ship": "Lead", "center": [0, 0, -1000], "radius": 100 }, "do": [ { "type": "message", "text": "n" } ] } ])"),
             "ev_area.json");
  run_to(g, 3);
  EXPECT_EQ(fired(g, 0), -1);
  g.world_mut().ships[0].position = {0, 0, -950};
  run_to(g, 4);
  EXPECT_EQ(fired(g, 0), 4);
}

TEST(MissionTriggers, ObjectiveStateAndAnotherEventChainInOneTick) {
  Game g = load(level(R"([
    { "id": "set", "when": { "type": "time", "seconds": 0.5 }, "do": [ { "type": "objective", "id": "bonus", "state": "failed" } ] },
    { "id": "on_fail", "when": { "type": "objective", "id": "bonus", "state": "failed" }, "do": [ { "type": "message", "text": "f" } ] },
    { "id": "after", "when": { "type": "event", "id": "on_fail" }, "do": [ { "type": "message", "text": "e" } ] } ])"),
             "ev_chain.json");
  run_to(g, 30);
  EXPECT_EQ(fired(g, 0), 30);
  EXPECT_EQ(fired(g, 1), 30);  // later in file order: the same tick
  EXPECT_EQ(fired(g, 2), 30);
}

TEST(MissionTriggers, TeamBelowACount) {
  Game g = load(level(R"([
    { "id": "low", "when": { "type": "team_below", "team": "red", "count": 2 }, "do": [ { "type": "message", "text": "l" } ] } ])"),
             "ev_team.json");
  run_to(g, 2);
  destroy(g.world_mut(), 2);
  run_to(g, 3);
  EXPECT_EQ(fired(g, 0), -1);  // two of red left
  destroy(g.world_mut(), 3);
  run_to(g, 4);
  EXPECT_EQ(fired(g, 0), 4);
}

// ---------------------------------------------------------------- actions

TEST(MissionActions, SpawnAGroupAtAPointWithItsShieldAndAnnouncement) {
  Game g = load(level(R"([
    { "id": "in", "when": { "type": "time", "seconds": 0.1 }, "do": [ { "type": "spawn", "group": "late", "at": [500, 0, -800], "announce": true } ] } ])"),
             "ev_spawn.json");
  EXPECT_TRUE(dormant(g.world().ships[5]));
  run_to(g, 6);
  const Ship& s = g.world().ships[5];
  EXPECT_TRUE(s.alive);
  EXPECT_FALSE(s.shield_fx.clusters.empty());
  EXPECT_NEAR(s.position.x, 500 + s.velocity.x * g.world().dt, 1.0);
  EXPECT_TRUE(has_message(g.world(), "Reinforcements: 1 hostile ship"));
}

TEST(MissionActions, MessageAndRadioWithItsSpeaker) {
  Game g = load(level(R"([
    { "id": "talk", "when": { "type": "time", "seconds": 0 }, "do": [
      { "type": "message", "text": "Nav point reached" },
      { "type": "radio", "speaker": "Cmdr Hale", "text": "Stay sharp" } ] } ])"),
             "ev_radio.json");
  run_to(g, 1);
  const World& w = g.world();
  ASSERT_EQ(w.messages.size(), 2u);
  EXPECT_EQ(w.messages[1].kind, MessageKind::Radio);
  EXPECT_EQ(w.messages[1].text, "Cmdr Hale: Stay sharp");
}

TEST(MissionActions, ObjectiveStateRevealsAHiddenOneAndShowsOnTheHud) {
  Game g = load(level(R"([
    { "id": "found", "when": { "type": "time", "seconds": 0.1 }, "do": [
      { "type": "objective", "id": "secret", "state": "done" }, { "type": "objective", "id": "bonus", "state": "failed" } ] } ])"),
             "ev_objective.json");
  EXPECT_FALSE(g.world().mission->objectives[2].revealed);
  HudLayer h;
  EXPECT_GT(hud_objectives(g.world(), 10, 50, h), 50.0);
  EXPECT_EQ(h.texts.size(), 2u);  // the hidden one is not drawn yet
  run_to(g, 6);
  const MissionProgress& m = *g.world().mission;
  EXPECT_EQ(m.objectives[2].status, ObjectiveStatus::Done);
  EXPECT_TRUE(m.objectives[2].revealed);
  EXPECT_EQ(objective_row(g.world(), 2), "[+] Find the cache");
  EXPECT_EQ(objective_row(g.world(), 1), "[x] (bonus) Down Red 1");
  EXPECT_EQ(objective_row(g.world(), 0), "[ ] Keep the Hauler alive");
}

TEST(MissionActions, ADecidedObjectiveStaysDecided) {
  Game g = load(level(R"([
    { "id": "fail", "when": { "type": "time", "seconds": 0.1 }, "do": [ { "type": "objective", "id": "bonus", "state": "failed" } ] },
    { "id": "win", "when": { "type": "time", "seconds": 0.2 }, "do": [ { "type": "objective", "id": "bonus", "state": "done" } ] } ])"),
             "ev_final.json");
  run_to(g, 20);
  EXPECT_EQ(g.world().mission->objectives[1].status, ObjectiveStatus::Failed);
  EXPECT_EQ(g.world().mission->objectives[1].changed_tick, 6);
}

TEST(MissionActions, RouteOrderFliesTheWaypointsThenHolds) {
  Game g = load(level(R"([
    { "id": "go", "when": { "type": "time", "seconds": 0 }, "do": [
      { "type": "order", "ship": "Hauler", "order": "route", "waypoints": [[200, 0, -300]], "speed": 1 } ] } ])"),
             "ev_route.json");
  run_to(g, 1);
  EXPECT_EQ(order_of(g.world(), ShipId::from_index(1))->kind, OrderKind::Route);
  run_to(g, 900);
  const Ship& s = g.world().ships[1];
  EXPECT_EQ(order_of(g.world(), s.id)->kind, OrderKind::Hold);
  EXPECT_LT(s.position.z, -150.0);
}

TEST(MissionActions, AttackOrderNamesTheTarget) {
  Game g = load(level(R"([
    { "id": "go", "when": { "type": "time", "seconds": 0 }, "do": [
      { "type": "order", "group": "raiders", "order": "attack", "target": "Hauler" } ] } ])"),
             "ev_attack.json");
  for (size_t i : {3, 4}) g.world_mut().ships[i].ai = AiKind::Fighter;
  run_to(g, 30);
  EXPECT_EQ(ordered_target(g.world(), ShipId::from_index(3)), ShipId::from_index(1));
  EXPECT_EQ(g.world().ships[3].ai_state.target, ShipId::from_index(1));
}

TEST(MissionActions, TeamChangeIsRecordedAndCountsForTheOutcome) {
  Game g = load(level(R"([
    { "id": "defect", "when": { "type": "time", "seconds": 0 }, "do": [ { "type": "team", "group": "raiders", "team": "blue" } ] } ])"),
             "ev_team_change.json");
  run_to(g, 1);
  const World& w = g.world();
  EXPECT_EQ(w.team_name(w.ships[3].team), "blue");
  ASSERT_EQ(w.mission->team_changes.size(), 2u);
}

TEST(MissionActions, EndWithAVerdict) {
  Game g = load(level(R"([
    { "id": "lose", "when": { "type": "time", "seconds": 0.2 }, "do": [ { "type": "end", "verdict": "defeat" } ] } ])"),
             "ev_end.json");
  run_to(g, 12);
  EXPECT_EQ(g.world().outcome, Outcome::Defeat);
  EXPECT_EQ(g.world().outcome_tick, 12);
  EXPECT_EQ(g.world().team_name(g.world().winner), "red");
}

TEST(MissionActions, CuePlaysByName) {
  Game g = load(level(R"([
    { "id": "c", "when": { "type": "time", "seconds": 0 }, "do": [ { "type": "cue", "name": "alarm" } ] } ])"),
             "ev_cue.json");
  run_to(g, 1);
  EXPECT_EQ(g.world().mission->cue, "alarm");
  EXPECT_EQ(g.world().mission->cue_tick, 1);
}

TEST(MissionObjectives, WonWhenEveryPrimaryIsDoneLostWhenOneFails) {
  const std::string done = R"([
    { "id": "ok", "when": { "type": "time", "seconds": 0.5 }, "do": [ { "type": "objective", "id": "escort", "state": "done" } ] } ])";
  Game g = load(level(done, "objectives"), "ev_win.json");
  run_to(g, 30);
  EXPECT_EQ(g.world().outcome, Outcome::Victory);
  const std::string failed = R"([
    { "id": "bad", "when": { "type": "destroyed", "ship": "Hauler" }, "do": [ { "type": "objective", "id": "escort", "state": "failed" } ] } ])";
  Game f = load(level(failed, "objectives"), "ev_fail.json");
  destroy(f.world_mut(), 1);
  run_to(f, 2);
  EXPECT_EQ(f.world().outcome, Outcome::Defeat);
}

// ---------------------------------------------------------------- determinism and the rest

TEST(MissionEvents, HashedReplayedAndSnapshotted) {
  const std::string events = R"([
    { "id": "in", "when": { "type": "time", "seconds": 0.5 }, "do": [ { "type": "spawn", "ship": "Late" },
      { "type": "order", "ship": "Late", "order": "route", "waypoints": [[0, 0, 0], [0, 0, -5000]], "loop": true } ] } ])";
  Game a = load(level(events), "ev_hash.json");
  Game b = load(level(events), "ev_hash.json");
  run_to(a, 120);
  run_to(b, 60);
  Game restored = Game::restore(b.save(), test::write_level("ev_hash.json", level(events)), test::options());
  run_to(restored, 120);
  EXPECT_EQ(a.hash(), restored.hash());
  // The mission's own state is in the hash: an objective's state alone changes it.
  const uint64_t before = a.hash();
  a.world_mut().mission->objectives[0].status = ObjectiveStatus::Done;
  EXPECT_NE(a.hash(), before);
}

TEST(MissionEvents, LevelsWithoutThemHaveNoMissionState) {
  const std::string ships = R"(
    { "name": "Lead", "class": "viper", "team": "blue", "player": true },
    { "name": "Red 1", "class": "dart", "team": "red", "position": [0, 0, -3000] })";
  Game g = Game::load_level(test::write_level("ev_none.json", test::level_text(ships)), test::options());
  EXPECT_FALSE(g.world().mission.has_value());
}

TEST(MissionEvents, AutopilotHandsThePlayersShipToTheFighterAi) {
  GameOptions o = test::options();
  o.autopilot = true;
  Game g = load(level("[]"), "ev_auto.json", o);
  EXPECT_EQ(g.world().ship(g.world().player).ai, AiKind::Fighter);
}

TEST(MissionEvents, FieldVisitorsListEveryField) {
  EventProgress e;
  ObjectiveProgress o;
  ShipOrder s;
  TeamChange t;
  MissionProgress m;
  EXPECT_EQ(fields::visited_field_count(e), fields::aggregate_field_count<EventProgress>());
  EXPECT_EQ(fields::visited_field_count(o), fields::aggregate_field_count<ObjectiveProgress>());
  EXPECT_EQ(fields::visited_field_count(s), fields::aggregate_field_count<ShipOrder>());
  EXPECT_EQ(fields::visited_field_count(t), fields::aggregate_field_count<TeamChange>());
  EXPECT_EQ(fields::visited_field_count(m), fields::aggregate_field_count<MissionProgress>());
}

}  // namespace
}  // namespace arc
