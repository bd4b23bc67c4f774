// Mission events' validation: one test per class of mistake, each reported at its file, line
// and column with the key path and what is allowed.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "core/error.h"
#include "game/sim/defs.h"
#include "test_helpers.h"

namespace arc {
namespace {

const std::string kShips = R"(
    { "name": "Lead", "class": "viper", "team": "blue", "player": true },
    { "name": "Red 1", "class": "dart", "team": "red", "position": [0, 0, -3000], "group": "raiders" },
    { "name": "Late", "class": "dart", "team": "red", "inactive": true, "position": [0, 0, -4000] })";

const std::string kSpawnLate =
    R"({ "id": "late", "when": { "type": "time", "seconds": 9 }, "do": [ { "type": "spawn", "ship": "Late" } ] })";

// The error a level with these objectives and events (after the one that spawns Late) gives.
std::string error_of(const std::string& events, const std::string& objectives = "[ { \"id\": \"main\", \"text\": \"Win\" } ]",
                     const std::string& win = "destroy_all_hostiles") {
  std::string text = test::level_text(kShips, "\n  \"objectives\": " + objectives + ",\n  \"events\": [ " + kSpawnLate +
                                                  (events.empty() ? "" : ", " + events) + " ],");
  const std::string from = "\"type\": \"destroy_all_hostiles\"";
  text.replace(text.find(from), from.size(), "\"type\": \"" + win + "\"");
  try {
    parse_level_def(text, "bad.json", arc::data_root());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Positioned (bad.json:LINE:COL:) and saying `what`.
void expect_error(const std::string& error, const std::string& what) {
  EXPECT_TRUE(std::regex_search(error, std::regex("^bad\\.json:[0-9]+:[0-9]+: "))) << error;
  EXPECT_NE(error.find(what), std::string::npos) << error;
}

TEST(MissionEventErrors, ValidLevelLoads) { EXPECT_EQ(error_of(""), ""); }

TEST(MissionEventErrors, UnknownTriggerType) {
  expect_error(error_of(R"({ "id": "a", "when": { "type": "sometime" }, "do": [ { "type": "cue", "name": "x" } ] })"),
               "events[1].when.type");
}

TEST(MissionEventErrors, UnknownActionType) {
  expect_error(error_of(R"({ "id": "a", "when": { "type": "time", "seconds": 1 }, "do": [ { "type": "explode" } ] })"),
               "got \"explode\"");
}

TEST(MissionEventErrors, UnknownShipListsTheShips) {
  expect_error(error_of(R"({ "id": "a", "when": { "type": "destroyed", "ship": "Blue 9" }, "do": [ { "type": "cue", "name": "x" } ] })"),
               "no ship of this level is named \"Blue 9\"; ships: \"Lead\", \"Red 1\" or \"Late\"");
}

TEST(MissionEventErrors, UnknownGroupListsTheGroups) {
  expect_error(error_of(R"({ "id": "a", "when": { "type": "destroyed", "group": "pirates" }, "do": [ { "type": "cue", "name": "x" } ] })"),
               "groups: \"raiders\"");
}

TEST(MissionEventErrors, ShipAndGroupTogether) {
  expect_error(error_of(R"({ "id": "a", "when": { "type": "destroyed", "ship": "Lead", "group": "raiders" }, "do": [ { "type": "cue", "name": "x" } ] })"),
               "exactly one of 'ship'");
}

TEST(MissionEventErrors, UnknownObjective) {
  expect_error(error_of(R"({ "id": "a", "when": { "type": "time", "seconds": 1 }, "do": [ { "type": "objective", "id": "side", "state": "done" } ] })"),
               "no objective has id \"side\"; ids: \"main\"");
}

TEST(MissionEventErrors, UnknownEventAndWaitingForItself) {
  expect_error(error_of(R"({ "id": "a", "when": { "type": "event", "id": "zzz" }, "do": [ { "type": "cue", "name": "x" } ] })"),
               "no event has id \"zzz\"");
  expect_error(error_of(R"({ "id": "a", "when": { "type": "event", "id": "a" }, "do": [ { "type": "cue", "name": "x" } ] })"),
               "cannot wait for itself");
}

TEST(MissionEventErrors, DuplicateIds) {
  expect_error(error_of(R"({ "id": "late", "when": { "type": "time", "seconds": 1 }, "do": [ { "type": "cue", "name": "x" } ] })"),
               "event id \"late\" is used twice");
  expect_error(error_of("", R"([ { "id": "m", "text": "a" }, { "id": "m", "text": "b" } ])"), "objective id \"m\" is used twice");
}

TEST(MissionEventErrors, BadIdCharacters) {
  expect_error(error_of(R"({ "id": "Big Event", "when": { "type": "time", "seconds": 1 }, "do": [ { "type": "cue", "name": "x" } ] })"),
               "must be an id of a-z, 0-9 and _");
}

TEST(MissionEventErrors, OutOfRangeValues) {
  expect_error(error_of(R"({ "id": "a", "when": { "type": "hull_below", "ship": "Lead", "fraction": 1.5 }, "do": [ { "type": "cue", "name": "x" } ] })"),
               "events[1].when.fraction");
  expect_error(error_of(R"({ "id": "a", "when": { "type": "time", "seconds": -1 }, "do": [ { "type": "cue", "name": "x" } ] })"),
               "events[1].when.seconds");
}

TEST(MissionEventErrors, MissingAndUnknownKeys) {
  expect_error(error_of(R"({ "id": "a", "when": { "type": "area_entered", "ship": "Lead", "radius": 5 }, "do": [ { "type": "cue", "name": "x" } ] })"),
               "center");
  expect_error(error_of(R"({ "id": "a", "when": { "type": "time", "seconds": 1, "ship": "Lead" }, "do": [ { "type": "cue", "name": "x" } ] })"),
               "unknown key 'ship'");
  expect_error(error_of(R"({ "id": "a", "when": { "type": "time", "seconds": 1 }, "do": [] })"), "at least one action");
}

TEST(MissionEventErrors, SpawningAShipAlreadyInTheFight) {
  expect_error(error_of(R"({ "id": "a", "when": { "type": "time", "seconds": 1 }, "do": [ { "type": "spawn", "group": "raiders" } ] })"),
               "only ships with \"inactive\": true can be spawned");
}

TEST(MissionEventErrors, OrderKeysBelongToTheirOrder) {
  expect_error(error_of(R"({ "id": "a", "when": { "type": "time", "seconds": 1 }, "do": [ { "type": "order", "ship": "Red 1", "order": "hold", "waypoints": [[0, 0, 0]] } ] })"),
               "only for the \"route\" order");
  expect_error(error_of(R"({ "id": "a", "when": { "type": "time", "seconds": 1 }, "do": [ { "type": "order", "ship": "Red 1", "order": "route", "waypoints": [] } ] })"),
               "at least one waypoint");
}

TEST(MissionEventErrors, UnknownTeam) {
  expect_error(error_of(R"({ "id": "a", "when": { "type": "team_below", "team": "green", "count": 1 }, "do": [ { "type": "cue", "name": "x" } ] })"),
               "names no team of this level's ships: \"green\"");
}

TEST(MissionEventErrors, ObjectivesWinNeedsAPrimary) {
  expect_error(error_of("", R"([ { "id": "m", "text": "a", "kind": "secondary" } ])", "objectives"),
               "needs at least one primary objective");
}

TEST(MissionEventErrors, InactiveShipNothingSpawns) {
  std::string text = test::level_text(kShips, "\n  \"events\": [ { \"id\": \"a\", \"when\": { \"type\": \"time\", \"seconds\": 1 }, "
                                              "\"do\": [ { \"type\": \"cue\", \"name\": \"x\" } ] } ],");
  try {
    parse_level_def(text, "bad.json", arc::data_root());
    ADD_FAILURE() << "loaded";
  } catch (const InputError& e) {
    expect_error(e.what(), "ship \"Late\" is inactive");
  }
}

}  // namespace
}  // namespace arc
