// The chase camera frames the fight (game/sim/camera_rig.h): a target near the nose is not
// hidden behind the own hull, over the combat replays and in a hard pitch toward it, and the
// padlock view keeps the target on screen.
//
// "Hidden": the target's centre lies inside the own ship's silhouette as the chase camera sees
// it (the convex outline of its model's bounding box) and farther away than the ship.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>
#include <glm/gtc/quaternion.hpp>

#include "assets/model.h"
#include "core/data_root.h"
#include "game/app/all_settings.h"
#include "game/app/script_feeder.h"
#include "game/render/chase_framing.h"
#include "game/render/own_cover.h"
#include "game/sim/camera_rig.h"
#include "game/sim/geometry.h"
#include "game/sim/world.h"
#include "replay/script.h"
#include "test_helpers.h"

namespace arc {
namespace {

// A low, close chase camera that follows every turn with a lag: the framing that hides a
// target ahead behind the hull while the ship pitches toward it.
constexpr ChaseFraming kLowClose{.up_per_radius = 0.45,
                                 .up_m = 2.0,
                                 .back_per_radius = 2.6,
                                 .back_m = 8.0,
                                 .tilt_down_deg = 0.0,
                                 .lag_rate = 6.0,
                                 .max_lag_deg = 180.0};

HullBox model_box(const World& w, const Ship& s) {
  const ModelData m = load_model(test::repo(w.model_paths[s.model.index()]));
  return {glm::dvec3(m.bounds_min), glm::dvec3(m.bounds_max)};
}

// Whether `target` (a world point) is behind the ship's silhouette seen from `cam`.
bool hidden_by_hull(const CameraRig& cam, const Ship& me, const HullBox& box, const glm::dvec3& target) {
  return covered_by_hull(cam.position, cam.orientation, me, box, target);
}

// The ship the player fights: its target, else the nearest live hostile (null: none).
const Ship* opponent(const World& w, const Ship& me) {
  if (me.target && w.ship(me.target).alive) return &w.ship(me.target);
  const Ship* best = nullptr;
  for (const Ship& s : w.ships)
    if (s.alive && w.hostile(me, s) &&
        (!best || glm::dot(s.position - me.position, s.position - me.position) <
                      glm::dot(best->position - me.position, best->position - me.position)))
      best = &s;
  return best;
}

struct Tally {
  long ticks = 0, near_nose = 0, hidden = 0;
  double share() const { return near_nose ? double(hidden) / double(near_nose) : 0.0; }
};

// Replays a script and follows its player with a chase camera of each framing, counting the
// ticks an opponent within 20° of the nose is hidden by the hull.
void replay_and_count(const std::string& path, const std::vector<ChaseFraming>& framings, std::vector<Tally>& tallies) {
  const replay::Script script = replay::load_script(path, all_settings());
  const std::string root = arc::data_root();
  const Settings settings = script_settings(script, all_settings(), root);
  GameOptions base;
  base.root_dir = root;
  Game game = Game::load_level(resolve_script_level(script, root), script_game_options(script, settings, base));
  const World& w = game.world();
  if (!w.player) return;
  const HullBox box = model_box(w, w.ship(w.player));
  std::vector<CameraRig> rigs(framings.size());
  for (CameraRig& r : rigs) r.orientation = w.ship(w.player).orientation;
  ScriptFeeder feed(script);
  for (uint64_t t = 0; t < script.last_tick(); ++t) {
    feed.step(game, t);
    const Ship& me = w.ship(w.player);
    if (!me.alive || w.paused) continue;
    const Ship* foe = opponent(w, me);
    for (size_t i = 0; i < framings.size(); ++i) {
      rigs[i] = chase_rig(rigs[i], me, w.dt, framings[i]);
      if (!foe) continue;
      ++tallies[i].ticks;
      const glm::dvec3 to = foe->position - me.position;
      if (glm::dot(safe_norm(to, glm::dvec3(0, 0, -1)), forward_of(me.orientation)) < std::cos(20.0 * kDeg)) continue;
      ++tallies[i].near_nose;
      // The game's framing is seen as drawn, lifted over the hull (chase_framing.h).
      CameraRig seen = rigs[i];
      if (i == 0) lift_chase_view(w, 1.0, seen.position, seen.orientation);
      tallies[i].hidden += hidden_by_hull(seen, me, box, foe->position) ? 1 : 0;
    }
  }
}

// The scripts with a player and an opponent: every replay but the effect gallery's, and the
// benchmark's recorded dogfight.
std::vector<std::string> combat_replays() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(test::repo("tests/replays")))
    if (e.path().extension() == ".replay" && e.path().filename().string().rfind("scene_gallery", 0) != 0)
      out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  out.push_back(test::repo("tests/bench/combat_view.replay"));
  return out;
}

TEST(ChaseFraming, TheTargetNearTheNoseIsNotHiddenOverTheCombatReplays) {
  const std::vector<ChaseFraming> framings{ChaseFraming{}, kLowClose};
  std::vector<Tally> total(framings.size());
  for (const std::string& path : combat_replays()) {
    std::vector<Tally> one(framings.size());
    replay_and_count(path, framings, one);
    std::printf("%-40s near the nose %5ld of %5ld ticks; hidden: chase %4ld, low close %4ld\n",
                std::filesystem::path(path).filename().string().c_str(), one[0].near_nose, one[0].ticks, one[0].hidden,
                one[1].hidden);
    for (size_t i = 0; i < total.size(); ++i) {
      total[i].ticks += one[i].ticks;
      total[i].near_nose += one[i].near_nose;
      total[i].hidden += one[i].hidden;
    }
  }
  std::printf("target within 20 deg of the nose but hidden by the own hull: chase %.2f%%, low close %.2f%% (of %ld ticks)\n",
              100.0 * total[0].share(), 100.0 * total[1].share(), total[0].near_nose);
  ASSERT_GT(total[0].near_nose, 1000);
  EXPECT_LT(total[0].share(), 0.02);
  EXPECT_GT(total[1].share(), total[0].share());
}

// An enemy 61 m ahead, a little below the nose (where a pilot closing on it keeps it): the
// low close framing puts the own hull over it.
bool hidden_below_the_nose(const ChaseFraming& f, double below_deg) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  const World& w = g.world();
  const Ship& me = w.ship(w.player);
  CameraRig rig;
  rig.orientation = me.orientation;
  for (int i = 0; i < 120; ++i) rig = chase_rig(rig, me, w.dt, f);
  const glm::dvec3 dir = me.orientation * glm::dvec3(0, -std::sin(below_deg * kDeg), -std::cos(below_deg * kDeg));
  return hidden_by_hull(rig, me, model_box(w, me), me.position + dir * 61.0);
}

TEST(ChaseFraming, AnEnemy61mAheadIsNotBehindTheHull) {
  for (double below : {0.0, 4.0, 8.0}) EXPECT_FALSE(hidden_below_the_nose(ChaseFraming{}, below)) << below;
  EXPECT_TRUE(hidden_below_the_nose(kLowClose, 8.0));
}

// The hull sits below the crosshair's line: its whole silhouette below the screen centre and
// the crosshair (half the beam's range ahead), with a margin.
TEST(ChaseFraming, TheHullSitsBelowTheCrosshairsLine) {
  Game g = Game::load_level(test::repo("levels/duel.json"), test::options());
  const World& w = g.world();
  const Ship& me = w.ship(w.player);
  const HullBox box = model_box(w, me);
  CameraRig rig;
  rig.orientation = me.orientation;
  for (int i = 0; i < 120; ++i) rig = chase_rig(rig, me, w.dt);
  const glm::dquat inv = glm::conjugate(rig.orientation);
  double top = -1e9;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 local(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y, i & 4 ? box.hi.z : box.lo.z);
    const glm::dvec3 v = inv * (me.position + me.orientation * local - rig.position);
    top = std::max(top, std::atan2(v.y, -v.z));
  }
  const glm::dvec3 aim = inv * (me.position + forward_of(me.orientation) * (0.5 * me.cls->beam.range) - rig.position);
  EXPECT_LT(top, std::atan2(aim.y, -aim.z) - 5.0 * kDeg);
  EXPECT_LT(top, -5.0 * kDeg);
}

// The angle between the camera's view axis and the direction to a point, degrees.
double off_axis_deg(const CameraRig& cam, const glm::dvec3& p) {
  const glm::dvec3 d = safe_norm(p - cam.position, glm::dvec3(0, 0, -1));
  return std::acos(std::clamp(glm::dot(d, forward_of(cam.orientation)), -1.0, 1.0)) / kDeg;
}

// V turns the padlock view on and off; it keeps the target on screen wherever it is, and is
// the chase view while there is no target. C from padlock goes to the cockpit.
TEST(Padlock, KeepsTheTargetInViewAndIsChaseWithoutOne) {
  const std::string level = test::write_level("padlock.json", test::level_text(R"(
    { "name": "Player", "class": "viper", "team": "blue", "player": true, "position": [0, 0, 0] },
    { "name": "Behind", "class": "viper", "team": "red", "position": [120, 30, 300] })"));
  Game g = Game::load_level(level, test::options());
  g.step(InputFrame{}, {Command::TargetNextHostile, Command::CameraPadlock});
  const World& w = g.world();
  ASSERT_EQ(w.camera_mode, CameraMode::Padlock);
  for (int i = 0; i < 120; ++i) g.step(InputFrame{});
  const Ship& me = w.ship(w.player);
  ASSERT_TRUE(me.target);
  EXPECT_LT(off_axis_deg(w.camera, w.ship(me.target).position), 10.0);  // behind the ship, yet in view
  EXPECT_LT(off_axis_deg(w.camera, me.position), 30.0);                 // and the own ship too

  g.world_mut().ships[w.player.index()].target = ShipId{};
  const CameraRig before = w.camera;
  g.step(InputFrame{});
  const CameraRig chase = chase_rig(before, w.ship(w.player), w.dt);
  EXPECT_LT(glm::length(w.camera.position - chase.position), 1e-9);

  g.step(InputFrame{}, {Command::CameraPadlock});
  EXPECT_EQ(w.camera_mode, CameraMode::Chase);
  g.step(InputFrame{}, {Command::CameraPadlock});
  g.step(InputFrame{}, {Command::CameraToggle});
  EXPECT_EQ(w.camera_mode, CameraMode::Cockpit);
  g.step(InputFrame{}, {Command::CameraToggle});
  EXPECT_EQ(w.camera_mode, CameraMode::Chase);
}

TEST(Padlock, TheScriptCommandRoundTrips) {
  const replay::Script s = replay::parse_script(
      "arcfire-replay 1\nlevel levels/duel.json\n10 command camera_padlock\n20 end\n", "padlock.replay", all_settings());
  ASSERT_EQ(s.commands.size(), 1u);
  EXPECT_EQ(s.commands[0].command, replay::ScriptCommand::CameraPadlock);
  EXPECT_NE(replay::write_script(s).find("10 command camera_padlock"), std::string::npos);
}

}  // namespace
}  // namespace arc
